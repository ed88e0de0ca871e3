#!/usr/bin/env python3
"""Where the instructions go: self Ir of a callgrind profile, per function of
the xfgcu headers, inlined code included (callgrind attributes inlined code
to source lines; this maps each line back to the function around it).

    cg_breakdown.py CALLGRIND_OUT [BYTES]

The profile must come from a build with -g and --dump-line=yes (the default).
BYTES: divide by it to print Ir per byte too. Used by `scripts/bench.sh profile`.
"""
import re
import sys
from collections import defaultdict

FUNC_RE = re.compile(r'^(?:XF_API|XF__NOINLINE|static)\b[^=(]*?\b(\w+)\s*\(')


def functions_of(path, cache={}):
    """line -> name of the function whose body holds it (None outside)."""
    if path in cache:
        return cache[path]
    spans = []
    try:
        lines = open(path, encoding='utf-8', errors='replace').read().split('\n')
    except OSError:
        cache[path] = None
        return None
    name, start, depth, opened = None, 0, 0, False
    for i, text in enumerate(lines, 1):
        if name is None and depth == 0:
            m = FUNC_RE.match(text)
            if m:
                name, start, opened = m.group(1), i, False
        if '{' in text:
            opened = True
        depth += text.count('{') - text.count('}')
        if name is not None and depth == 0:
            if opened:
                spans.append((start, i, name))
                name = None
            elif text.rstrip().endswith(';'):
                name = None  # a prototype
    cache[path] = spans
    return spans


def owner(path, line):
    spans = functions_of(path)
    if not spans:
        return None
    for a, b, n in spans:
        if a <= line <= b:
            return n
    return None


def main():
    if len(sys.argv) < 2:
        print(__doc__, file=sys.stderr)
        return 2
    nbytes = float(sys.argv[2]) if len(sys.argv) > 2 else 0.0
    names = {}
    cost = defaultdict(int)
    fl = fi = None
    line = 0
    skip_next = False
    total = 0

    def name_of(spec):
        m = re.match(r'\((\d+)\)(?:\s+(.*))?', spec)
        if not m:
            return spec
        if m.group(2):
            names[m.group(1)] = m.group(2)
        return names.get(m.group(1), '?')

    for raw in open(sys.argv[1], encoding='utf-8', errors='replace'):
        raw = raw.rstrip('\n')
        if not raw:
            continue
        key, _, val = raw.partition('=')
        if key in ('fl', 'fi', 'fe') and _:
            path = name_of(val)
            if key == 'fl':
                fl = fi = path
            else:
                fi = path
            continue
        if key in ('cfi', 'cfl', 'cfn', 'cob', 'ob', 'fn') and _:
            if key in ('cfi', 'cfl'):
                name_of(val)
            if key == 'fn':
                fi = fl
            continue
        if key == 'calls' and _:
            skip_next = True
            continue
        if not (raw[0].isdigit() or raw[0] in '+-*'):
            continue
        parts = raw.split()
        pos = parts[0]
        if pos == '*':
            pass
        elif pos[0] in '+-':
            line += int(pos)
        else:
            line = int(pos)
        if skip_next:
            skip_next = False
            continue
        if len(parts) < 2:
            continue
        ir = int(parts[1])
        total += ir
        path = fi or fl or '?'
        func = owner(path, line) if path.startswith('/') else None
        short = path.rsplit('/', 1)[-1]
        cost[(short, func or ('line %d' % line if short.startswith('xf_') else '(other)'))] += ir

    print('%14s %7s %9s  %s' % ('self Ir', '%', 'Ir/byte' if nbytes else '', 'where'))
    for (short, func), ir in sorted(cost.items(), key=lambda kv: -kv[1]):
        if ir * 200 < total:
            continue
        per = '%9.2f' % (ir / nbytes) if nbytes else ''
        print('%14d %6.1f%% %9s  %s: %s' % (ir, 100.0 * ir / total, per, short, func))
    print('%14d %6.1f%% %9s  total' % (total, 100.0, '%9.2f' % (total / nbytes) if nbytes else ''))
    return 0


if __name__ == '__main__':
    sys.exit(main())
