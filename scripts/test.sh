#!/usr/bin/env bash
# The whole test suite: what CI runs (.ci/run). Installs what it needs first (Debian packages).
# Stages: gcc -Werror build + ctest; clang ASan+UBSan build + ctest; fuzz smoke; compiler matrix;
# static analysis; MCU builds with sizes; big-endian tests under qemu; package consumers;
# benchmark figures (printed, never asserted).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh --dev
jobs=$(nproc)
t0=$(date +%s)
stage() { printf '\n=== %s  (%ss)\n' "$*" "$(($(date +%s) - t0))"; }

stage "gcc: build with -Werror, run the tests"
cmake -S . -B build/gcc -DCMAKE_BUILD_TYPE=Debug -DCMAKE_C_COMPILER=gcc >/dev/null
cmake --build build/gcc --parallel "$jobs"
ctest --test-dir build/gcc --output-on-failure --parallel "$jobs"

stage "clang: build with ASan+UBSan, run the tests"
cmake --preset debug >/dev/null
cmake --build --preset debug --parallel "$jobs"
ctest --preset debug --parallel "$jobs"

stage "fuzz smoke: libFuzzer harnesses over the saved corpus and a short run"
scripts/fuzz.sh smoke

stage "compiler matrix: gcc/clang x C99/C11, headers as C++"
scripts/matrix.sh

stage "static analysis: cppcheck, clang-tidy"
scripts/lint.sh

stage "MCU: Cortex-M4 firmware and RISC-V builds, sizes"
scripts/mcu_size.sh

stage "big-endian: codec and client tests on s390x under qemu-user"
scripts/bigendian.sh

stage "package: find_package, add_subdirectory, pkg-config consumers"
scripts/check_package.sh

stage "benchmarks: parser instructions per byte (callgrind), client latency and CPU"
scripts/bench.sh
build/gcc/bench/xfgcu_client_bench latency 500
build/gcc/bench/xfgcu_client_bench cpu 3

stage "done"
echo "all stages passed"
