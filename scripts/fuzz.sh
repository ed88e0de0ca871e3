#!/usr/bin/env bash
# libFuzzer harnesses of the parser and the codec (fuzz/). Builds with clang
# in build/fuzz; see docs/performance.md ("Fuzzing").
#
#   scripts/fuzz.sh smoke            replay the committed corpus (and fuzz/regressions/)
#                                    through every harness and variant, then fuzz each main harness
#                                    for $FUZZ_SMOKE_SECONDS (default 30) s, side by side. About 40 s.
#                                    (ctest replays the same inputs in any build with the tests:
#                                    the replay_* tests, fuzz/replay.cmake.)
#   scripts/fuzz.sh long [SECONDS]   a long campaign: SECONDS (default 600) per binary, on a
#                                    writable corpus in build/fuzz/corpus-long/ that persists
#                                    between campaigns (seeded from fuzz/corpus/). Its record
#                                    (commit, date, per binary: executions, new inputs, result)
#                                    goes to build/fuzz/campaign.txt, which scripts/perf_page.py
#                                    puts in docs/performance.md.
#   scripts/fuzz.sh corpus           regenerate the committed seed corpus and the hand-made
#                                    regressions (sem-*) of the parser's semantics (fuzz/gen_corpus.c).
#   scripts/fuzz.sh build            just build.
#
# Exits non-zero if any harness crashes or reports a violated invariant; the
# reproducer is left in build/fuzz/artifacts/<harness>/ (copy it to
# fuzz/regressions/<harness>/ so that every smoke run replays it).
set -euo pipefail
cd "$(dirname "$0")/.."

mode="${1:-smoke}"
bdir=build/fuzz
main_harnesses=(fuzz_parser_raw fuzz_parser_crcfix)
# Variants built from the same sources (fuzz/variants.cmake): _alt with XF_CRC_TABLE_256=1,
# XF_PACKET_MAX_LEN=84, XF_NO_LIBC=1; _slots1 with XF_PARSER_SLOTS=1.
variants=(_alt _slots1)

base_of() { # harness name without its variant suffix
  local h="$1" v
  for v in "${variants[@]}"; do h="${h%"$v"}"; done
  echo "$h"
}

cc="${FUZZ_CC:-clang}"
if ! command -v "$cc" >/dev/null 2>&1; then
  echo "fuzz.sh: $cc not found; libFuzzer needs clang (scripts/setup.sh --dev installs it)" >&2
  exit 1
fi

build() {
  cmake -S . -B "$bdir" -DCMAKE_C_COMPILER="$cc" -DCMAKE_BUILD_TYPE= \
    -DXFGCU_BUILD_FUZZ=ON -DXFGCU_BUILD_TESTS=OFF -DXFGCU_BUILD_TOOLS=OFF \
    -DXFGCU_BUILD_EXAMPLES=OFF -DXFGCU_BUILD_BENCH=OFF >/dev/null
  cmake --build "$bdir" --parallel "$(nproc)" >/dev/null
}

# libFuzzer options per harness
opts() {
  local h="$1" base; base=$(base_of "$1")
  local o=(-timeout=10 -rss_limit_mb=2048 -print_final_stats=1 -max_len=4096)
  if [ "$base" = fuzz_parser_raw ]; then o+=(-dict=fuzz/parser.dict); fi
  mkdir -p "$bdir/artifacts/$h"
  o+=(-artifact_prefix="$bdir/artifacts/$h/")
  printf '%s\n' "${o[@]}"
}

failed=()
record="" # when set, run() appends a line per harness to this file
# run NAME LOG libFuzzer-args...: run a harness, remember a failure
run() {
  local h="$1" log="$2" result=ok; shift 2
  local o; mapfile -t o < <(opts "$h")
  if "$bdir/fuzz/$h" "${o[@]}" "$@" >"$log" 2>&1; then
    grep -E '^(stat::number_of_executed_units|stat::new_units_added)' "$log" | tr '\n' ' ' || true
    echo
  else
    result=FAILED
    echo "FAILED (log: $log)"
    grep -E 'invariant violated|ERROR:|SUMMARY:|Test unit written' "$log" | head -5 || true
    failed+=("$h")
  fi
  if [ -n "$record" ]; then
    printf 'binary %s %s %s %s\n' "$h" \
      "$(awk '/^stat::number_of_executed_units/ {print $NF}' "$log")" \
      "$(awk '/^stat::new_units_added/ {print $NF}' "$log")" "$result" >>"$record"
  fi
}

replay() {
  # saved corpus and regressions through every harness (main and variant); the
  # first directory is a scratch one, because libFuzzer copies into the first
  # directory it is given whatever it finds new in the others
  local h v dirs scratch
  for h in "${main_harnesses[@]}"; do
    for v in "$h" "${variants[@]/#/$h}"; do
      scratch="$bdir/replay-scratch/$v"
      rm -rf "$scratch"; mkdir -p "$scratch"
      dirs=("$scratch" "fuzz/corpus/$h")
      if [ -d "fuzz/regressions/$h" ]; then dirs+=("fuzz/regressions/$h"); fi
      printf 'replay  %-32s ' "$v"
      run "$v" "$bdir/logs/replay-$v.log" -runs=0 "${dirs[@]}"
    done
  done
}

case "$mode" in
  build)
    build
    ;;
  corpus)
    build
    for h in "${main_harnesses[@]}"; do mkdir -p "fuzz/corpus/$h" "fuzz/regressions/$h"; done
    "$bdir/fuzz/xfgcu_gen_corpus" fuzz/corpus fuzz/regressions
    du -sh fuzz/corpus fuzz/regressions
    ;;
  smoke)
    secs="${FUZZ_SMOKE_SECONDS:-30}"
    build
    mkdir -p "$bdir/logs"
    replay
    # the harnesses fuzz side by side (libFuzzer uses one core each), each printing its line when done
    pids=()
    for h in "${main_harnesses[@]}"; do
      # new units go to a scratch directory, never into the committed corpus
      work="$bdir/smoke-corpus/$h"
      rm -rf "$work"; mkdir -p "$work"
      (
        out=$(printf 'fuzz    %-32s %ss: ' "$h" "$secs"
              run "$h" "$bdir/logs/smoke-$h.log" -max_total_time="$secs" "$work" "fuzz/corpus/$h")
        printf '%s\n' "$out"
        [[ $out != *FAILED* ]]
      ) &
      pids+=($!)
    done
    for i in "${!pids[@]}"; do wait "${pids[$i]}" || failed+=("${main_harnesses[$i]}"); done
    ;;
  long)
    secs="${2:-600}"
    build
    mkdir -p "$bdir/logs"
    replay
    all=("${main_harnesses[@]}")
    for v in "${variants[@]}"; do all+=("${main_harnesses[@]/%/$v}"); done
    record="$bdir/campaign.txt"
    { echo "commit $(git rev-parse --short HEAD)$(git diff --quiet HEAD -- include src fuzz tests || echo +changes)"
      echo "date $(date -u +%Y-%m-%d)"
      echo "seconds $secs"; } >"$record"
    for h in "${all[@]}"; do
      base=$(base_of "$h")
      work="$bdir/corpus-long/$base"
      mkdir -p "$work"
      cp -n "fuzz/corpus/$base"/* "$work"/ 2>/dev/null || true
      printf 'fuzz    %-32s %ss: ' "$h" "$secs"
      run "$h" "$bdir/logs/long-$h.log" -max_total_time="$secs" "$work"
    done
    echo "corpus kept in $bdir/corpus-long/ (minimise with: <harness> -merge=1 NEW_DIR $bdir/corpus-long/<harness>)"
    ;;
  *)
    sed -n '2,20p' "$0" >&2
    exit 2
    ;;
esac

if [ ${#failed[@]} -gt 0 ]; then
  echo "fuzz.sh: FAILED: ${failed[*]} (reproducers in $bdir/artifacts/)" >&2
  exit 1
fi
[ "$mode" = build ] || [ "$mode" = corpus ] || echo "fuzz.sh: $mode: no crash, no violated invariant"
