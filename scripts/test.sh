#!/usr/bin/env bash
# The whole test suite: what CI runs (.ci/run). Installs what it needs first.
#   gcc -Werror build + ctest; clang ASan+UBSan build + ctest; MCU compile + size.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh --dev
jobs=$(nproc)
stage() { printf '\n=== %s\n' "$*"; }

stage "gcc: build with -Werror, run the tests"
cmake -S . -B build/gcc -DCMAKE_BUILD_TYPE=Debug -DCMAKE_C_COMPILER=gcc >/dev/null
cmake --build build/gcc --parallel "$jobs"
ctest --test-dir build/gcc --output-on-failure --parallel "$jobs"

stage "clang: build with ASan+UBSan, run the tests"
cmake -S . -B build/asan -DCMAKE_BUILD_TYPE=Debug -DCMAKE_C_COMPILER=clang -DXFGCU_SANITIZE=ON >/dev/null
cmake --build build/asan --parallel "$jobs"
ctest --test-dir build/asan --output-on-failure --parallel "$jobs"

stage "MCU: Cortex-M4 compile with strict flags, size"
scripts/mcu_size.sh

echo
echo "all stages passed"
