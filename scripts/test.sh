#!/usr/bin/env bash
# The whole test suite, in named stages: what CI runs (.ci/run). Installs what it needs first
# (Debian packages, scripts/setup.sh --dev).
#
#   scripts/test.sh                 every stage, in order; then a table of stage, seconds, verdict
#   scripts/test.sh STAGE [STAGE…]  only these (each builds what it needs), e.g. scripts/test.sh lint
#   scripts/test.sh --list          the stages and what each checks
#
# A failing stage does not stop the others: every stage gets its own verdict, and the run fails
# at the end if any stage failed. Each stage runs in its own process, so it can be run alone.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc)
# ctest: four tests per core; most wait on sockets, ptys, timers and child processes, and each
# passes --repeat until-fail:3 so run
tjobs=$((4 * jobs))

stages=(tree build python readme optimised fuzz matrix docs lint mcu firmware bigendian bench mutation)

describe() {
  case $1 in
    tree)      echo "no binaries, build products, big files or long test sources tracked (scripts/check_tree.py)" ;;
    build)     echo "gcc Debug build with -Werror (the Python package's native library too), every ctest" ;;
    python)    echo "the Python package's tests (pytest, hypothesis) over build/gcc's library and program" ;;
    readme)    echo "every recipe README.md prints, run as printed (Release, install, consumers, presets)" ;;
    optimised) echo "gcc -O2 and clang -O3 builds with -Werror, their tests" ;;
    fuzz)      echo "libFuzzer harnesses over the saved corpus, and a short run" ;;
    matrix)    echo "gcc/clang x C99/C11, headers alone as C and C++, a user TU at -O0..-O3/-Os" ;;
    docs)      echo "API reference (Doxygen, warnings are errors), man page current, nothing outside" ;;
    lint)      echo "generated files current, cppcheck, clang-tidy, clang-format, the parser's lines (a gate)" ;;
    mcu)       echo "Cortex-M4 firmware and RISC-V builds, their flash and RAM (gates)" ;;
    firmware)  echo "the MCU example under qemu-system-arm against xfgcu sim (ctest -L firmware)" ;;
    bigendian) echo "codec and client tests on s390x under qemu-user" ;;
    bench)     echo "parser instructions per byte (callgrind; its promises gated), client latency and CPU, send's time" ;;
    mutation)  echo "named mutants of the parser, each killed by its tests (scripts/mutate.sh)" ;;
    *) return 1 ;;
  esac
}

# The Debug build that several stages use; incremental when it exists.
gcc_build() {
  cmake -S . -B build/gcc -DCMAKE_BUILD_TYPE=Debug -DCMAKE_C_COMPILER=gcc -DXFGCU_BUILD_PYTHON=ON >/dev/null
  cmake --build build/gcc --parallel "$jobs"
}

stage_tree() { scripts/check_tree.py --self-test && scripts/check_tree.py; }
# The firmware loop runs once, in its own stage.
stage_build() { gcc_build && ctest --test-dir build/gcc --output-on-failure --parallel "$tjobs" --label-exclude firmware; }
stage_python() { gcc_build >/dev/null && python/run_tests.sh build/gcc; }
stage_readme() { scripts/check_readme.sh; }
stage_optimised() {
  local cfg dir
  # gcc -O2: its flow-sensitive warnings; clang -O3: the other compiler's most aggressive optimiser
  # (gcc -O3 is the README's Release build, run by the readme stage)
  for cfg in "gcc -O2" "clang -O3"; do
    set -- $cfg
    dir=build/opt-$1$2
    echo "--- $1 $2"
    cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Release -DCMAKE_C_COMPILER="$1" \
          -DCMAKE_C_FLAGS_RELEASE="$2 -DNDEBUG" >/dev/null
    cmake --build "$dir" --parallel "$jobs"
    # live: the build, readme (Release) and ASan runs have them; firmware: its own stage
    ctest --test-dir "$dir" --output-on-failure --parallel "$tjobs" --label-exclude 'live|firmware'
  done
}
stage_fuzz() { scripts/fuzz.sh smoke; }
stage_matrix() { scripts/matrix.sh; }
stage_docs() { scripts/check_docs.sh; }
stage_lint() { scripts/lint.sh; }
stage_mcu() { scripts/mcu_size.sh; }
stage_firmware() { gcc_build >/dev/null && ctest --test-dir build/gcc --output-on-failure -L firmware --no-tests=error; }
stage_bigendian() { scripts/bigendian.sh; }
stage_bench() {
  gcc_build >/dev/null
  scripts/bench.sh
  build/gcc/bench/xfgcu_client_bench latency 500
  build/gcc/bench/xfgcu_client_bench cpu 3
  scripts/bench_send.sh build/gcc/tools/xfgcu 30
}
stage_mutation() { scripts/mutate.sh; }

# One stage, in this process (the driver below starts one process per stage).
if [ "${1:-}" = --run-one ]; then
  set -euo pipefail
  "stage_$2"
  exit
fi

case ${1:-} in
  --list)
    for s in "${stages[@]}"; do printf '%-10s %s\n' "$s" "$(describe "$s")"; done
    exit 0 ;;
  -h|--help)
    sed -n '2,10p' "$0" | sed 's/^# \{0,1\}//'
    exit 0 ;;
esac
selected=("$@")
[ ${#selected[@]} -gt 0 ] || selected=("${stages[@]}")
for s in "${selected[@]}"; do
  describe "$s" >/dev/null || { echo "test.sh: unknown stage '$s' (scripts/test.sh --list)" >&2; exit 2; }
done

scripts/setup.sh --dev
t0=$(date +%s)
rows=()
failed=0
for s in "${selected[@]}"; do
  printf '\n=== %s: %s  (at %ss)\n' "$s" "$(describe "$s")" "$(($(date +%s) - t0))"
  start=$(date +%s)
  if bash "$0" --run-one "$s"; then verdict=pass; else verdict=FAIL; failed=$((failed + 1)); fi
  rows+=("$(printf '%-10s %6s  %s' "$s" "$(($(date +%s) - start))" "$verdict")")
done

printf '\n%-10s %6s  %s\n' stage seconds verdict
printf '%s\n' "${rows[@]}"
printf '%-10s %6s  %s\n' total "$(($(date +%s) - t0))" "$([ $failed -eq 0 ] && echo pass || echo "FAIL ($failed)")"
# the whole suite's time, for docs/performance.md (scripts/perf_page.py): only a full, passing run
if [ $# -eq 0 ] && [ $failed -eq 0 ]; then
  printf 'commit %s\ndate %s\nseconds %s\ncores %s\n' "$(git rev-parse --short HEAD)" "$(date -u +%Y-%m-%d)" \
    "$(($(date +%s) - t0))" "$jobs" >build/test-time.txt
fi
[ $failed -eq 0 ]
