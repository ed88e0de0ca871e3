#!/usr/bin/env python3
"""The parser's size in lines, and its gate (scripts/lint.sh fails on it).

Counts the lines of code of include/xfgcu/xf_parser.h and include/xfgcu/xf_crc.h: lines that
are neither blank nor comment (the generated tables, xf_crc_tables.h, apart), and the longest
function of each, in lines from its name to its closing brace.

Usage: scripts/parser_loc.py            print the figures, one `name value` per line
       scripts/parser_loc.py --check    the same, and exit 1 when a target is exceeded
"""
import os
import re
import sys

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
FILES = ["include/xfgcu/xf_parser.h", "include/xfgcu/xf_crc.h"]
MAX_LINES = 300  # parser + CRC
MAX_FUNCTION = 40  # any one function


def strip_comments(text):
    return re.sub(r"/\*.*?\*/", lambda m: "\n" * m.group(0).count("\n"), text, flags=re.S)


def code_lines(text):
    return sum(1 for line in strip_comments(text).splitlines() if line.strip() and not line.strip().startswith("//"))


def functions(text):
    """(name, lines) of each function defined at file level: a line starting in column 0 that
    names a function, then its body up to the brace in column 0 that closes it."""
    lines = strip_comments(text).splitlines()
    out, i = [], 0
    while i < len(lines):
        m = re.match(r"^[A-Za-z_].*?\b(\w+)\s*\([^;]*$", lines[i])
        if m and not lines[i].startswith("#") and not lines[i].startswith("typedef"):
            j = i
            while j < len(lines) and "{" not in lines[j] and not lines[j].rstrip().endswith(";"):
                j += 1
            if j < len(lines) and "{" in lines[j]:
                if lines[j].rstrip().endswith("}"):  # one line
                    out.append((m.group(1), j - i + 1))
                    i = j + 1
                    continue
                k = j + 1
                while k < len(lines) and not lines[k].startswith("}"):
                    k += 1
                out.append((m.group(1), k - i + 1))
                i = k + 1
                continue
        i += 1
    return out


def main():
    total, longest, bad = 0, ("", 0), []
    for path in FILES:
        text = open(os.path.join(ROOT, path)).read()
        n = code_lines(text)
        total += n
        print("lines %s %d" % (path, n))
        for name, length in functions(text):
            if length > longest[1]:
                longest = (name, length)
            if length > MAX_FUNCTION:
                bad.append("%s: %s is %d lines (at most %d)" % (path, name, length, MAX_FUNCTION))
    print("lines total %d" % total)
    print("longest %s %d" % longest)
    if total > MAX_LINES:
        bad.append("parser + CRC: %d lines of code (at most %d)" % (total, MAX_LINES))
    if sys.argv[1:] == ["--check"]:
        for b in bad:
            print("OVER: " + b, file=sys.stderr)
        sys.exit(1 if bad else 0)
    if sys.argv[1:]:
        sys.exit(__doc__)


if __name__ == "__main__":
    main()
