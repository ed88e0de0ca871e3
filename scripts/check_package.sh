#!/usr/bin/env bash
# Consume xfgcu the three ways the README shows, from outside the tree:
#   1. installed, with find_package(xfgcu)   2. the source tree, with add_subdirectory
#   3. installed, with pkg-config
# Each consumer builds tests/consumer/consumer.c and runs it (a client and a simulator on loopback).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
out=$root/build/package
rm -rf "$out"
mkdir -p "$out"

echo "--- install"
cmake -S . -B "$out/xfgcu" -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX="$out/prefix" \
      -DXFGCU_BUILD_TESTS=OFF -DXFGCU_BUILD_BENCH=OFF -DXFGCU_BUILD_EXAMPLES=OFF >/dev/null
cmake --build "$out/xfgcu" --parallel "$(nproc)" >/dev/null
cmake --install "$out/xfgcu" >/dev/null

echo "--- find_package(xfgcu)"
cmake -S tests/consumer/find_package -B "$out/fp" -DCMAKE_PREFIX_PATH="$out/prefix" >/dev/null
cmake --build "$out/fp" >/dev/null
"$out/fp/consumer"

echo "--- add_subdirectory(xfgcu)"
cmake -S tests/consumer/add_subdirectory -B "$out/as" -DXFGCU_SOURCE_DIR="$root" >/dev/null
cmake --build "$out/as" --parallel "$(nproc)" >/dev/null
# A consumer's build gets none of our tests, tools or install rules.
if [ -d "$out/as/xfgcu/tests" ] || [ -d "$out/as/xfgcu/tools" ]; then
  echo "add_subdirectory built xfgcu's tests or tools for a consumer" >&2; exit 1
fi
"$out/as/consumer"

echo "--- pkg-config xfgcu"
PKG_CONFIG_PATH="$out/prefix/lib/pkgconfig" cc -std=c99 tests/consumer/consumer.c -o "$out/pc-consumer" \
  $(PKG_CONFIG_PATH="$out/prefix/lib/pkgconfig" pkg-config --cflags --libs xfgcu)
"$out/pc-consumer"
echo "package consumers: 3 passed"
