#!/usr/bin/env bash
# The compiler matrix: gcc and clang, C99 and C11, -Werror -pedantic-errors -Wconversion, over
# every library source and all public headers; the public headers as C++ (g++, clang++) too.
set -euo pipefail
cd "$(dirname "$0")/.."
out=build/matrix
mkdir -p "$out"
warn=(-Wall -Wextra -Werror -pedantic-errors -Wconversion -Wshadow -Wundef -Wstrict-prototypes
      -Wmissing-prototypes -Wcast-align -Wdouble-promotion -Wformat=2)
n=0
for cc in gcc clang; do
  for std in c99 c11; do
    for src in src/*.c tests/matrix/all_headers.c; do
      "$cc" -std="$std" "${warn[@]}" -Iinclude -c "$src" -o "$out/$(basename "$src").$cc.$std.o"
      n=$((n + 1))
    done
    # the codec compiled once (XF_SEPARATE_IMPLEMENTATION) and with its options
    for defs in "-DXF_SEPARATE_IMPLEMENTATION" "-DXF_CRC_TABLE_256=1" "-DXF_PACKET_MAX_LEN=84" "-DXF_NO_LIBC=1"; do
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

# The README's example must compile as printed (compiled only: it would talk to a real GCU).
awk '/^## Example/ {inex = 1} inex && /^```c/ {code = 1; next} code && /^```/ {exit} code {print}' README.md \
  > "$out/readme_example.body"
{
  grep '^#include' "$out/readme_example.body"
  printf '#include <stdio.h>\nextern xf_carrier my_ins;\nxf_carrier my_ins;\nint readme_example(void);\nint readme_example(void)\n{\n'
  grep -v '^#include' "$out/readme_example.body"
  printf '}\n'
} > "$out/readme_example.c"
gcc -std=c99 -Wall -Wextra -Werror -Iinclude -c "$out/readme_example.c" -o "$out/readme_example.o"
echo "README example: compiles"
