#!/usr/bin/env bash
# The compiler matrix: gcc and clang, C99 and C11, -Werror -pedantic-errors -Wconversion, over
# every library source and all public headers; the public headers as C++ (g++, clang++) too.
# Then a user's program (tests/matrix/user_tu.c, the translation unit that defines
# XF_IMPLEMENTATION, and user_tu_values.c, one that does not: every public codec function, small
# and large buffers) built by gcc, clang, g++ and clang++ at -O0/-O2/-O3/-Os (and the codec options
# at -O2/-O3), where gcc's -Warray-bounds / -Wstringop-overflow look into the inlined headers,
# and each binary run. Any warning or failed run fails the script. MATRIX_JOBS=N: parallel
# builds (default: the number of CPUs).
set -euo pipefail
cd "$(dirname "$0")/.."
out=build/matrix
mkdir -p "$out"
warn=(-Wall -Wextra -Werror -pedantic-errors -Wconversion -Wshadow -Wundef -Wstrict-prototypes
      -Wmissing-prototypes -Wcast-align -Wcast-qual -Wdouble-promotion -Wformat=2)
n=0
for cc in gcc clang; do
  for std in c99 c11; do
    for src in src/*.c tests/matrix/all_headers.c; do
      "$cc" -std="$std" "${warn[@]}" -Iinclude -c "$src" -o "$out/$(basename "$src").$cc.$std.o"
      n=$((n + 1))
    done
    # the codec's implementation translation unit with each option
    for defs in "-DXF_CRC_TABLE_256=1" "-DXF_PACKET_MAX_LEN=84" "-DXF_NO_LIBC=1" "-DXF_PARSER_SLOTS=1"; do
      "$cc" -std="$std" "${warn[@]}" $defs -Iinclude -c src/xf_codec.c -o "$out/codec.$cc.$std.o"
      n=$((n + 1))
    done
  done
done
for cxx in g++ clang++; do
  for std in c++11 c++17; do
    "$cxx" -std="$std" -Wall -Wextra -Werror -pedantic-errors -Iinclude -c tests/matrix/all_headers.cpp \
      -o "$out/headers.$cxx.$std.o"
    n=$((n + 1))
  done
done
echo "compiler matrix: $n compilations, all clean"

# Every header alone, as C and as C++; every portable header (all but posix/) alone for a bare-metal
# target: where a header lives says where it builds.
nh=0
for h in include/xfgcu/*.h include/xfgcu/posix/*.h; do
  inc=${h#include/}
  printf '#include "%s"\ntypedef int xf_matrix_nonempty;\n' "$inc" | gcc -std=c99 "${warn[@]}" -Iinclude -fsyntax-only -x c -
  printf '#include "%s"\ntypedef int xf_matrix_nonempty;\n' "$inc" | g++ -std=c++11 -Wall -Wextra -Werror -pedantic-errors -Iinclude -fsyntax-only -x c++ -
  nh=$((nh + 1))
done
nf=0
for h in include/xfgcu/*.h; do
  printf '#include "%s"\ntypedef int xf_matrix_nonempty;\n' "${h#include/}" |
    arm-none-eabi-gcc -mcpu=cortex-m4 -mthumb -ffreestanding -std=c99 -Wall -Wextra -Werror -Iinclude \
      -fsyntax-only -x c -
  nf=$((nf + 1))
done
echo "headers: $nh alone as C and C++; the $nf portable ones alone freestanding (arm-none-eabi-gcc)"

# The README's example must compile as printed (compiled only: it would talk to a real GCU).
# It is either a whole program (it has a main) or a fragment, wrapped here in a function.
awk '/^## Example/ {inex = 1} inex && /^```c/ {code = 1; next} code && /^```/ {exit} code {print}' README.md \
  > "$out/readme_example.body"
if grep -q '^int main(' "$out/readme_example.body"; then
  cp "$out/readme_example.body" "$out/readme_example.c"
else
  {
    grep '^#include' "$out/readme_example.body"
    printf '#include <stdio.h>\nextern xf_carrier my_ins;\nxf_carrier my_ins;\nint readme_example(void);\nint readme_example(void)\n{\n'
    grep -v '^#include' "$out/readme_example.body"
    printf '}\n'
  } > "$out/readme_example.c"
fi
gcc -std=c99 -Wall -Wextra -Werror -Iinclude -c "$out/readme_example.c" -o "$out/readme_example.o"
echo "README example: compiles"

# ---- a user's program: its implementation translation unit and one other -------------------
# tests/matrix/user_tu.c defines XF_IMPLEMENTATION and includes xfgcu/xfgcu.h, calls every public
# codec function that takes the caller's buffers with buffers of 1, 4 and 16 bytes (which must
# fail cleanly) and of XF_PACKET_MAX_LEN and 4096 bytes, and checks its results; its second file,
# user_tu_values.c, includes xfgcu/xfgcu.h without XF_IMPLEMENTATION (declarations only, as a
# user's other files do) and calls the rest, on values and tables. Both are compiled and linked
# into one program (a second XF_IMPLEMENTATION, or none, fails the link). First: do they still
# call every public function and function-like macro of the headers xfgcu.h includes (non-xf__
# names)?
utu=(tests/matrix/user_tu.c tests/matrix/user_tu_values.c)
codec_headers() { # the headers xfgcu.h includes, and the ones they include, once each
  local todo=(xfgcu.h) seen=" " h inc
  while [ "${#todo[@]}" -gt 0 ]; do
    h=${todo[0]}
    todo=("${todo[@]:1}")
    case "$seen" in *" $h "*) continue ;; esac
    seen="$seen$h "
    [ "$h" = xfgcu.h ] || echo "include/xfgcu/$h"
    while read -r inc; do
      todo+=("$inc")
    done < <(sed -n 's/^#include "\(xf[a-z0-9_]*\.h\)".*/\1/p' "include/xfgcu/$h")
  done
}
mapfile -t hdrs < <(codec_headers)
mapfile -t api < <(
  {
    grep -hoE '^(XF_API|static inline)[^(]*[^A-Za-z0-9_]xf_[a-z0-9_]+\(' "${hdrs[@]}" |
      grep -oE 'xf_[a-z0-9_]+\($'
    grep -hoE '^#[[:space:]]*define[[:space:]]+XF_[A-Za-z0-9_]+\(' "${hdrs[@]}" | grep -oE 'XF_[A-Za-z0-9_]+\($'
  } | tr -d '(' | grep -v -e '^xf__' -e '^XF__' | sort -u
)
missing=()
for f in "${api[@]}"; do
  grep -qE "(^|[^A-Za-z0-9_])${f}[[:space:]]*\(" "${utu[@]}" || missing+=("$f")
done
if [ "${#api[@]}" -lt 50 ] || [ "${#missing[@]}" -gt 0 ]; then
  echo "matrix: FAIL: ${utu[*]} do not call every public codec function (${#api[@]} found in" \
    "${#hdrs[@]} headers); missing: ${missing[*]:-(the list itself looks wrong)}" >&2
  exit 1
fi
echo "user TU: calls all ${#api[@]} public codec functions and macros of ${#hdrs[@]} headers"

# Every combination, built and run in parallel; one line each, in this order.
cwarn="-std=c99 -Wall -Wextra -Wconversion -Wshadow -Wcast-qual -Wstrict-prototypes -Wmissing-prototypes"
cwarn="$cwarn -Wpedantic -Werror"
cxxwarn="-x c++ -Wall -Wextra -Wpedantic -Werror"
combos=() # "file name|label|compiler|flags"
for cc in gcc clang; do
  for o in -O0 -O2 -O3 -Os; do combos+=("$cc$o|$cc C99 $o|$cc|$cwarn $o"); done
done
for cxx in g++ clang++; do
  for o in -O0 -O2 -O3 -Os; do combos+=("$cxx$o|$cxx C++ $o|$cxx|$cxxwarn $o"); done
done
# the options that change the codec's code paths, where the optimiser looks hardest
for opt in XF_PARSER_SLOTS=1 XF_CRC_TABLE_256=1 XF_PACKET_MAX_LEN=84 XF_NO_LIBC=1; do
  for cc in gcc clang; do
    for o in -O2 -O3; do combos+=("$cc$o-${opt%%=*}-${opt#*=}|$cc C99 $o -D$opt|$cc|$cwarn $o -D$opt"); done
  done
done

# utu_one NAME LABEL COMPILER FLAGS: build both files into one program (any compiler output fails
# it), then run. Writes the line to print in $out/user_tu.NAME.result and "ok" or "FAIL" in $out/user_tu.NAME.status.
utu_one() {
  local label="$2" cc="$3" flags="$4" bin="$out/user_tu.$1" t0 t1 rc=0 ndiag res status=FAIL
  t0=$(date +%s%N)
  # shellcheck disable=SC2086
  "$cc" $flags -Iinclude "${utu[@]}" -o "$bin" >"$bin.build.log" 2>&1 || rc=$?
  t1=$(date +%s%N)
  if [ "$rc" -ne 0 ] || [ -s "$bin.build.log" ]; then
    ndiag=$(grep -cE '(warning|error):' "$bin.build.log" || true)
    res="FAIL  build (exit $rc, $ndiag warnings/errors): $bin.build.log"
  elif timeout 60 "$bin" >"$bin.run.log" 2>&1; then
    res="ok    $(tail -n 1 "$bin.run.log")"
    status=ok
  else
    rc=$?
    res="FAIL  run (exit $rc): $bin.run.log"
  fi
  printf 'user TU  %-38s %5s s  %s\n' "$label" "$(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.1f", (b - a) / 1e9 }')" \
    "$res" >"$bin.result"
  echo "$status" >"$bin.status"
}

jobs_max="${MATRIX_JOBS:-$(nproc 2>/dev/null || echo 2)}"
rm -f "$out"/user_tu.*
for c in "${combos[@]}"; do
  IFS='|' read -r name label cc flags <<<"$c"
  while [ "$(jobs -rp | wc -l)" -ge "$jobs_max" ]; do wait -n || true; done
  utu_one "$name" "$label" "$cc" "$flags" &
done
wait
fails=0
for c in "${combos[@]}"; do
  name=${c%%|*}
  if [ -f "$out/user_tu.$name.result" ]; then
    cat "$out/user_tu.$name.result"
  else
    printf 'user TU  %-38s %5s    FAIL  no result\n' "$(echo "$c" | cut -d'|' -f2)" "-"
  fi
  [ "$(cat "$out/user_tu.$name.status" 2>/dev/null)" = ok ] || fails=$((fails + 1))
done
if [ "$fails" -gt 0 ]; then
  for c in "${combos[@]}"; do
    name=${c%%|*}
    [ "$(cat "$out/user_tu.$name.status" 2>/dev/null)" = ok ] && continue
    echo "---- $(echo "$c" | cut -d'|' -f3- | tr '|' ' ')" >&2
    cat "$out/user_tu.$name.build.log" "$out/user_tu.$name.run.log" 2>/dev/null | head -n 40 >&2
  done
  echo "matrix: FAIL: $fails of ${#combos[@]} user TU combinations warned or failed (logs above, in $out/)" >&2
  exit 1
fi
echo "user TU: ${#combos[@]} combinations, no warning, every run passed"
