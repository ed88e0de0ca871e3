#!/usr/bin/env bash
# The documentation's own checks:
#  - the API reference builds with Doxygen and no warning (every public entity documented);
#  - the man page is what scripts/gen_manpage.py makes of docs/cli.md, and renders without warning;
#  - every relative link of the Markdown docs points at a file of the repository;
#  - nothing in the project refers to a file outside it.
set -euo pipefail
cd "$(dirname "$0")/.."

echo "--- API reference (Doxygen, warnings are errors)"
cmake -S . -B build/docs -DXFGCU_BUILD_DOCS=ON -DXFGCU_BUILD_TESTS=OFF -DXFGCU_BUILD_TOOLS=OFF \
      -DXFGCU_BUILD_BENCH=OFF -DXFGCU_BUILD_EXAMPLES=OFF >/dev/null
cmake --build build/docs --target xfgcu_docs
test -s build/docs/docs/api/html/index.html
echo "API reference: build/docs/docs/api/html/index.html"

echo "--- man page"
scripts/gen_manpage.py docs/cli.md --check docs/xfgcu.1
warnings=$(groff -man -ww -z docs/xfgcu.1 2>&1)
if [ -n "$warnings" ]; then
  echo "docs/xfgcu.1: groff warns: $warnings" >&2; exit 1
fi
echo "man page: up to date, renders cleanly"

echo "--- links"
python3 - README.md docs/*.md examples/mcu/README.md fuzz/README.md <<'PY'
import os, re, sys
bad = 0
for md in sys.argv[1:]:
    text = open(md, encoding="utf-8").read()
    text = re.sub(r"```.*?```", "", text, flags=re.S)  # code blocks hold no links
    for target in re.findall(r"\]\(([^)\s]+)\)", text):
        if re.match(r"^[a-z]+:", target) or target.startswith("#"):
            continue
        path = os.path.normpath(os.path.join(os.path.dirname(md), target.split("#")[0]))
        if not os.path.exists(path):
            print(f"{md}: link to {target}: no such file", file=sys.stderr)
            bad += 1
sys.exit(1 if bad else 0)
PY
echo "links: every relative link resolves"

echo "--- the project stands alone"
if git grep -nE '(\.\./shared|shared/(spec|style|research))' -- . ':!scripts/check_docs.sh'; then
  echo "the lines above refer to files outside the project" >&2; exit 1
fi
echo "no reference outside the project"
