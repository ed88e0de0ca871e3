#!/usr/bin/env bash
# The whole test suite: what CI runs (.ci/run). Installs what it needs first (Debian packages).
# Stages: gcc -Werror Debug build + ctest (the Wireshark dissector's tests with tshark among them);
# the Python package's pytest suite; the README's recipes as printed (Release gcc -O3 + ctest,
# install to a fresh prefix, find_package / pkg-config / add_subdirectory consumers run, the Python
# package installed into a venv and tested, a capture dissected by tshark, the clang
# ASan+UBSan preset + ctest, the bare-metal presets); gcc -O2, clang -O2 and -O3 builds + ctest;
# fuzz smoke; compiler matrix; docs (Doxygen with warnings as errors, man page, no references
# outside the project); static analysis with the parser's size gates; MCU sizes with their gates;
# big-endian tests under qemu; benchmark figures (the speed ones printed, the parser's promises
# asserted).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh --dev
jobs=$(nproc)
t0=$(date +%s)
stage() { printf '\n=== %s  (%ss)\n' "$*" "$(($(date +%s) - t0))"; }

stage "gcc: Debug build with -Werror (the Python package's native library too), run the tests"
cmake -S . -B build/gcc -DCMAKE_BUILD_TYPE=Debug -DCMAKE_C_COMPILER=gcc -DXFGCU_BUILD_PYTHON=ON >/dev/null
cmake --build build/gcc --parallel "$jobs"
ctest --test-dir build/gcc --output-on-failure --parallel "$jobs"

stage "Python: the package's tests (pytest, hypothesis) over build/gcc's library and program"
python/run_tests.sh build/gcc

stage "README: every recipe it prints, run as printed (Release, install, consumers, presets)"
scripts/check_readme.sh

stage "optimised builds with -Werror: gcc -O2, clang -O2, clang -O3; run the tests"
for cfg in "gcc -O2" "clang -O2" "clang -O3"; do
  set -- $cfg
  dir=build/opt-$1$2
  echo "--- $1 $2"
  cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Release -DCMAKE_C_COMPILER="$1" \
        -DCMAKE_C_FLAGS_RELEASE="$2 -DNDEBUG" >/dev/null
  cmake --build "$dir" --parallel "$jobs"
  ctest --test-dir "$dir" --output-on-failure --parallel "$jobs" --label-exclude live # the Debug, Release
done                                                                                 # and ASan runs have them

stage "fuzz smoke: libFuzzer harnesses over the saved corpus and a short run"
scripts/fuzz.sh smoke

stage "compiler matrix: gcc/clang x C99/C11, headers as C++, a user TU of the codec at -O0..-O3/-Os"
scripts/matrix.sh

stage "docs: API reference (Doxygen, warnings are errors), man page up to date, nothing outside"
scripts/check_docs.sh

stage "static analysis: cppcheck, clang-tidy, the parser's size in lines (a failing gate)"
scripts/lint.sh

stage "MCU: Cortex-M4 firmware and RISC-V builds, sizes (flash and RAM targets: failing gates)"
scripts/mcu_size.sh

stage "big-endian: codec and client tests on s390x under qemu-user"
scripts/bigendian.sh

stage "benchmarks: parser instructions per byte (callgrind), client latency and CPU"
scripts/bench.sh
build/gcc/bench/xfgcu_client_bench latency 500
build/gcc/bench/xfgcu_client_bench cpu 3
scripts/bench_send.sh build/gcc/tools/xfgcu 30

stage "mutation: named mutants of the parser, each killed by its tests (scripts/mutate.sh)"; scripts/mutate.sh

stage "done"
# the suite's time, for docs/performance.md (scripts/perf_page.sh)
printf 'commit %s\ndate %s\nseconds %s\ncores %s\n' "$(git rev-parse --short HEAD)" "$(date -u +%Y-%m-%d)" \
  "$(($(date +%s) - t0))" "$jobs" >build/test-time.txt
echo "all stages passed"
