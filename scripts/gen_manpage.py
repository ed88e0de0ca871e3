#!/usr/bin/env python3
"""Convert docs/cli.md into the roff man page xfgcu(1).

    scripts/gen_manpage.py docs/cli.md -o docs/xfgcu.1        write the page
    scripts/gen_manpage.py docs/cli.md --check docs/xfgcu.1   exit 1 if it is out of date
    scripts/gen_manpage.py docs/cli.md                        print the page

Standard library only. The output depends on nothing but the markdown and the
version in include/xfgcu/xf_version.h (a fixed date, no clock), so --check is exact.

The markdown subset understood (anything else is taken as paragraph text):
  # NAME — SUMMARY       the title: the NAME section
  ## Heading             a section (.SH, upper-cased); text before the first one
                         opens DESCRIPTION
  ### Heading            a subsection (.SS)
  paragraphs             lines up to a blank line
  - item                 bullet lists; continuation lines are indented
  | a | b | c |          tables: the first column is the tag of a .TP paragraph,
                         the second its text, further columns "Header: value"
                         (empty and '\u2014' cells are left out)
  ``` ... ```            code blocks (no-fill, indented)
  `code` **bold** *italic* [text](target)   inline; a link shows its text only
"""

import argparse
import re
import sys
import textwrap
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
VERSION_HEADER = ROOT / "include" / "xfgcu" / "xf_version.h"
WRAP = 78  # mandoc -T lint wants source lines of at most 80 bytes
# The page's date: fixed, so that the output never depends on the clock.
# Change it with the version in include/xfgcu/xf_version.h.
DATE = "2026-11-24"

# Characters outside ASCII that the page may use, as roff escapes; any other
# becomes \[uXXXX], which groff and mandoc both know.
UNICODE = {
    "\u2014": r"\(em",  # em dash
    "\u2013": r"\(en",  # en dash
    "\u2212": r"\-",  # minus
    "\u00d7": r"\(mu",  # multiplication sign
    "\u2264": r"\(<=",
    "\u2265": r"\(>=",
    "\u00b0": r"\(de",  # degree
    "\u2192": r"\(->",
    "\u2026": "...",
    "\u2018": r"\(oq",
    "\u2019": r"\(cq",
    "\u201c": r"\(lq",
    "\u201d": r"\(rq",
}


class MarkdownError(Exception):
    pass


# ---- inline text ---------------------------------------------------------------


def escape(text, code=False):
    """Roff-escape plain text. In code every '-' is a minus (copyable options);
    in prose only a '-' that starts a word (an option, a negative number)."""
    out = []
    for i, ch in enumerate(text):
        if ch == "\\":
            out.append(r"\e")
        elif ch == "-":
            prev = text[i - 1] if i > 0 else " "
            nxt = text[i + 1] if i + 1 < len(text) else " "
            if code or (prev in " (/[-" and (nxt.isalnum() or nxt in "-.")):
                out.append(r"\-")
            else:
                out.append("-")
        elif ord(ch) > 126:
            out.append(UNICODE.get(ch, r"\[u%04X]" % ord(ch)))
        else:
            out.append(ch)
    return "".join(out)


INLINE = re.compile(
    r"(?P<code>`+)(?P<code_text>.+?)(?P=code)"
    r"|\*\*(?P<bold>.+?)\*\*"
    r"|\[(?P<link>[^\]]+)\]\((?P<target>[^)\s]+)\)"
    r"|(?<![\w*])\*(?P<italic>[^*\s][^*]*?)\*(?![\w*])"
)


def inline(text, fonts=True):
    """Markdown inline markup to roff; fonts=False drops font changes (headings)."""
    out = []
    pos = 0
    for m in INLINE.finditer(text):
        out.append(escape(text[pos : m.start()]))
        pos = m.end()
        if m.group("code") is not None:
            body = escape(m.group("code_text").strip(), code=True)
            out.append(r"\fB%s\fR" % body if fonts else body)
        elif m.group("bold") is not None:
            body = inline(m.group("bold"), fonts)
            out.append(r"\fB%s\fR" % body if fonts else body)
        elif m.group("link") is not None:
            out.append(inline(m.group("link"), fonts))
        else:
            body = inline(m.group("italic"), fonts)
            out.append(r"\fI%s\fR" % body if fonts else body)
    out.append(escape(text[pos:]))
    return "".join(out)


def text_lines(roff):
    """Filled text as source lines of at most WRAP columns, none starting a request."""
    lines = textwrap.wrap(roff, WRAP, break_long_words=False, break_on_hyphens=False)
    return [one_line(ln) for ln in lines]


def one_line(roff):
    return ("\\&" + roff) if roff[:1] in (".", "'") else roff


def macro_arg(roff):
    return '"%s"' % roff.replace('"', '""')


# ---- blocks ------------------------------------------------------------------------


def split_row(line):
    """The cells of a table row; '\\|' is a literal bar."""
    row = line.strip()
    if row.startswith("|"):
        row = row[1:]
    if row.endswith("|") and not row.endswith("\\|"):
        row = row[:-1]
    cells = re.split(r"(?<!\\)\|", row)
    return [c.strip().replace("\\|", "|") for c in cells]


def parse_blocks(lines):
    """Markdown lines to a list of (kind, data) blocks."""
    blocks = []
    i = 0
    n = len(lines)
    while i < n:
        line = lines[i]
        stripped = line.strip()
        if not stripped:
            i += 1
            continue
        if stripped.startswith("```"):
            body = []
            i += 1
            while i < n and not lines[i].strip().startswith("```"):
                body.append(lines[i].rstrip())
                i += 1
            if i == n:
                raise MarkdownError("code block opened and never closed")
            blocks.append(("code", body))
            i += 1
            continue
        m = re.match(r"(#{1,3})\s+(.*?)\s*#*\s*$", line)
        if m:
            blocks.append(("h%d" % len(m.group(1)), m.group(2)))
            i += 1
            continue
        if stripped.startswith("|"):
            rows = []
            while i < n and lines[i].strip().startswith("|"):
                rows.append(split_row(lines[i]))
                i += 1
            if len(rows) < 2 or not all(re.fullmatch(r":?-+:?", c) for c in rows[1]):
                raise MarkdownError("table without a header separator: %s" % stripped)
            blocks.append(("table", (rows[0], rows[2:])))
            continue
        if re.match(r"[-*]\s+", stripped):
            items = []
            while i < n and lines[i].strip():
                item = re.match(r"[-*]\s+(.*)", lines[i])  # an item starts in column 0
                if item:
                    items.append([item.group(1).strip()])
                elif items and lines[i][:1] == " ":
                    items[-1].append(lines[i].strip())
                else:
                    break
                i += 1
            blocks.append(("list", [" ".join(it) for it in items]))
            continue
        para = []
        while i < n and lines[i].strip():
            s = lines[i].strip()
            if para and (s.startswith(("```", "#", "|")) or re.match(r"[-*]\s+", s)):
                break
            para.append(s)
            i += 1
        blocks.append(("para", " ".join(para)))
    return blocks


# ---- the page -----------------------------------------------------------------------


def version():
    try:
        text = VERSION_HEADER.read_text(encoding="utf-8")
    except OSError as e:
        raise MarkdownError("cannot read %s: %s" % (VERSION_HEADER, e.strerror))
    m = re.search(r'#define\s+XF_VERSION_STRING\s+"([^"]+)"', text)
    if not m:
        raise MarkdownError("no XF_VERSION_STRING in %s" % VERSION_HEADER)
    return m.group(1)


def source_name(path):
    """The input as the comment names it: relative to the repository when inside it."""
    p = Path(path).resolve()
    try:
        return p.relative_to(ROOT).as_posix()
    except ValueError:
        return p.name


class Page:
    def __init__(self):
        self.out = []
        self.fresh = True  # just after .SH/.SS/.TH: no paragraph macro needed

    def emit(self, *lines):
        self.out.extend(lines)

    def paragraph(self):
        if not self.fresh:
            self.emit(".PP")
        self.fresh = False

    def section(self, title):
        """A section from its markdown title (upper-cased before escaping)."""
        self.emit(".SH " + macro_arg(inline(title.upper(), fonts=False)))
        self.fresh = True

    def subsection(self, title):
        self.emit(".SS " + macro_arg(inline(title, fonts=False)))
        self.fresh = True

    def block(self, kind, data):
        if kind == "para":
            self.paragraph()
            self.emit(*text_lines(inline(data)))
        elif kind == "list":
            for item in data:
                self.emit(r".IP \(bu 2")
                self.emit(*text_lines(inline(item)))
            self.fresh = False
        elif kind == "table":
            header, rows = data
            for row in rows:
                row = row + [""] * (len(header) - len(row))
                self.emit(".TP")
                self.emit(one_line(inline(row[0])))  # the tag: one line, whatever its length
                self.emit(*text_lines(inline(row[1]) if len(row) > 1 else ""))
                for label, cell in zip(header[2:], row[2:]):
                    if cell in ("", "-", "\u2014"):
                        continue  # an empty cell says nothing
                    self.emit(".br")
                    self.emit(*text_lines(inline(label.capitalize() + ": " + cell)))
            self.fresh = False
        elif kind == "code":
            self.paragraph()
            self.emit(".RS 4", ".nf")
            for ln in data:
                ln = escape(ln, code=True)
                self.emit(one_line(ln) if ln else "\\&")
            self.emit(".fi", ".RE")
            self.fresh = False


def convert(markdown, source):
    blocks = parse_blocks(markdown.splitlines())
    if not blocks or blocks[0][0] != "h1":
        raise MarkdownError("the file must start with a '# NAME \u2014 SUMMARY' title")
    title = blocks[0][1].replace("`", "")
    name, sep, summary = title.partition(" \u2014 ")
    if not sep:
        name, sep, summary = title.partition(" - ")
    if not sep:
        raise MarkdownError("the title must read 'NAME \u2014 SUMMARY'")
    name = name.strip()

    page = Page()
    page.emit(
        '.\\" Generated by scripts/gen_manpage.py from %s; do not edit.' % source,
        '.\\" Edit %s and run: scripts/gen_manpage.py %s -o FILE' % (source, source),
        ".TH %s 1 %s %s \"User Commands\""
        % (escape(name.upper()), DATE, macro_arg("%s %s" % (escape(name), version()))),
    )
    page.emit(".nh", ".ad l")  # no hyphenation (options, names), ragged right
    page.section("Name")
    page.emit("%s \\- %s" % (escape(name), inline(summary.strip(), fonts=False)))

    # Text between the title and the first section goes to the top of DESCRIPTION.
    rest = blocks[1:]
    k = next((j for j, b in enumerate(rest) if b[0] == "h2"), len(rest))
    intro, rest = rest[:k], rest[k:]
    if not any(b == ("h2", "Description") for b in rest) and intro:
        raise MarkdownError("text before the first section needs a 'Description' section")
    for kind, data in rest:
        if kind == "h1":
            raise MarkdownError("a second '#' title: %s" % data)
        if kind == "h2":
            page.section(data)
            if data == "Description":
                for b in intro:
                    page.block(*b)
        elif kind == "h3":
            page.subsection(data)
        else:
            page.block(kind, data)
    return "\n".join(page.out) + "\n"


def main(argv=None):
    ap = argparse.ArgumentParser(description="Convert docs/cli.md into the man page xfgcu(1).")
    ap.add_argument("markdown", help="the markdown source, docs/cli.md")
    group = ap.add_mutually_exclusive_group()
    group.add_argument("-o", "--output", metavar="FILE", help="write the page to FILE")
    group.add_argument("--check", metavar="FILE", help="exit 1 if FILE differs from the page generated")
    args = ap.parse_args(argv)

    try:
        markdown = Path(args.markdown).read_text(encoding="utf-8")
        page = convert(markdown, source_name(args.markdown))
    except OSError as e:
        print("gen_manpage.py: cannot read %s: %s" % (args.markdown, e.strerror), file=sys.stderr)
        return 2
    except MarkdownError as e:
        print("gen_manpage.py: %s: %s" % (args.markdown, e), file=sys.stderr)
        return 2

    if args.check:
        try:
            current = Path(args.check).read_text(encoding="utf-8")
        except OSError as e:
            print("gen_manpage.py: %s: cannot read: %s" % (args.check, e.strerror), file=sys.stderr)
            return 1
        if current != page:
            print(
                "gen_manpage.py: %s is out of date with %s; run scripts/gen_manpage.py %s -o %s"
                % (args.check, args.markdown, args.markdown, args.check),
                file=sys.stderr,
            )
            return 1
        return 0
    if args.output:
        with open(args.output, "w", encoding="utf-8", newline="\n") as f:
            f.write(page)
        return 0
    sys.stdout.write(page)
    return 0


if __name__ == "__main__":
    sys.exit(main())
