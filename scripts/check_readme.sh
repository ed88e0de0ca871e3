#!/usr/bin/env bash
# Runs the README's recipes exactly as printed, as a newcomer would: in a scratch directory that
# holds a copy of this clone named `xfgcu`, with HOME pointed into the scratch directory (so that
# "$HOME/opt/xfgcu" is a fresh prefix).
#
# A fenced block right after `<!-- readme-check: file PATH -->` is written to PATH (relative to the
# scratch directory); one after `<!-- readme-check: run -->` is run there with bash -euo pipefail,
# in the order of the README. Background jobs a block starts are waited for before the next one.
#   scripts/check_readme.sh [README]
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
readme=${1:-README.md}
work=$root/build/readme
rm -rf "$work"
mkdir -p "$work/home" "$work/xfgcu"

# The clone as committed or staged, plus what is modified in the work tree (not build trees).
git ls-files -z --cached --others --exclude-standard | tar --null -T - -cf - | tar -C "$work/xfgcu" -xf -

python3 - "$readme" "$work" <<'PY'
import os, re, sys
readme, work = sys.argv[1], sys.argv[2]
lines = open(readme, encoding="utf-8").read().split("\n")
steps, i, mark = [], 0, None
while i < len(lines):
    m = re.match(r"^<!-- readme-check: (file (\S+)|run) -->$", lines[i])
    if m:
        mark = ("file", m.group(2)) if m.group(2) else ("run", None)
        i += 1
        continue
    if lines[i].startswith("```") and mark:
        j = i + 1
        while not lines[j].startswith("```"):
            j += 1
        body = "\n".join(lines[i + 1:j]) + "\n"
        steps.append((mark[0], mark[1], body, i + 1))
        mark, i = None, j + 1
        continue
    i += 1
n = 0
for kind, path, body, line in steps:
    if kind == "file":
        full = os.path.join(work, path)
        os.makedirs(os.path.dirname(full), exist_ok=True)
        open(full, "w").write(body)
    else:
        n += 1
        open(os.path.join(work, f"step{n:02d}.sh"), "w").write(f"# README line {line}\n" + body)
print(f"readme: {len(steps)} blocks, {n} to run")
PY

export HOME=$work/home
unset PKG_CONFIG_PATH CMAKE_PREFIX_PATH
status=0
for step in "$work"/step*.sh; do
  echo "--- $(basename "$step") ($(head -1 "$step" | sed 's/^# //'))"
  sed 1d "$step" | sed 's/^/    /'
  if ! (cd "$work" && bash -euo pipefail -c "$(cat "$step"); wait" > "$step.log" 2>&1); then
    echo "README recipe failed: $(head -1 "$step" | sed 's/^# //'); its output:" >&2
    tail -40 "$step.log" >&2
    status=1
    break
  fi
  tail -3 "$step.log" | sed 's/^/    > /'
done
# add_subdirectory gives a consumer none of our tests, tools or install rules.
if [ "$status" = 0 ] && { [ -d "$work/myapp2/build/xfgcu/tests" ] || [ -d "$work/myapp2/build/xfgcu/tools" ]; }; then
  echo "README recipe: add_subdirectory built xfgcu's tests or tools for a consumer" >&2
  status=1
fi
# The installed shared libraries export the public API only: no xf__ internal (cmake/xfgcu.map).
if [ "$status" = 0 ]; then
  sos=("$HOME"/opt/xfgcu/lib/libxfgcu_*.so)
  leaked=$(for so in "${sos[@]}"; do nm -D --defined-only "$so" | awk -v f="$so" '$3 ~ /^xf__/ {print f ": " $3}'; done)
  if [ "${#sos[@]}" -lt 5 ] || [ -n "$leaked" ]; then
    echo "README: shared libraries missing (${#sos[@]}) or exporting internals: $leaked" >&2
    status=1
  else
    echo "--- ${#sos[@]} shared libraries export no xf__ symbol"
  fi
fi

# The README's promise for a machine without cmocka: configure says so in one line, and the
# library, the program and the examples still build. (pkg-config is shown every .pc file but
# cmocka's.)
if [ "$status" = 0 ]; then
  echo "--- without cmocka"
  pc=$work/pc-no-cmocka
  mkdir -p "$pc"
  for d in $(pkg-config --variable pc_path pkg-config | tr : ' '); do
    [ -d "$d" ] && find "$d" -maxdepth 1 -name '*.pc' ! -name 'cmocka.pc' -exec ln -sf {} "$pc/" \;
  done
  if ! PKG_CONFIG_LIBDIR=$pc cmake -S "$work/xfgcu" -B "$work/no-cmocka" -DCMAKE_BUILD_TYPE=Release \
         > "$work/no-cmocka.log" 2>&1 ||
     ! grep -q 'xfgcu: tests off: cmocka not found' "$work/no-cmocka.log" ||
     ! cmake --build "$work/no-cmocka" --parallel "$(nproc)" >> "$work/no-cmocka.log" 2>&1 ||
     [ ! -x "$work/no-cmocka/tools/xfgcu" ] || [ -d "$work/no-cmocka/tests" ]; then
    echo "README: a build without cmocka did not go as promised; its output:" >&2
    tail -20 "$work/no-cmocka.log" >&2
    status=1
  else
    grep 'xfgcu: tests off' "$work/no-cmocka.log" | sed 's/^/    > /'
  fi
fi
[ "$status" = 0 ] && echo "README recipes: all ran as printed"
exit "$status"
