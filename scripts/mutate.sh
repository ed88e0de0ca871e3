#!/usr/bin/env bash
# Mutation check of the streaming parser (include/xfgcu/xf_parser.h): apply named mutants, one at a
# time, to a scratch copy of the tree and show that the parser's ctest suite kills every one.
#
#   scripts/mutate.sh                     every mutant; exit 0 only if each is killed
#   scripts/mutate.sh NAME...             only these mutants
#   scripts/mutate.sh --full [NAME...]    run every parser test on every mutant (slower; the
#                                         table then lists every test that kills each one)
#   scripts/mutate.sh --timeout SEC ...   per-test time limit (default 30; a hang counts as killed)
#   scripts/mutate.sh --list              the mutants and what each breaks, nothing run
#
# How. The working tree (git ls-files -co --exclude-standard: tracked files plus untracked,
# non-ignored ones) is copied to build/mutate/src; the real tree is never written. One Debug
# build is configured there (tests and the benchmark's selftest on; tools, examples, docs, POSIX
# links, install off: the parser tests need none of them), and the parser tests (ctest -R
# 'parser|fuzz_replay|bench_selftest', which covers the fuzz-replay label) must pass unmutated.
# Then, for each mutant, xf_parser.h is rewritten from the pristine copy with one exact string
# replacement that must match exactly once (a pattern that no longer matches stops the run: the
# list cannot rot silently), only the affected test programs are rebuilt, and ctest runs them:
# first test_parser alone (it kills nearly every mutant in a second or two), then, if it
# survived that, every parser test. A failing or timed-out test means KILLED.
#
# Exit status: 0 every mutant killed; 1 a mutant survived, did not build, or the pristine suite
# failed; 2 bad usage. Logs: build/mutate/logs/. Needs git, cmake, ctest, python3, cmocka;
# ninja is used when present (much faster rebuilds than make). One run at a time per tree.
set -euo pipefail

usage="usage: scripts/mutate.sh [--full] [--timeout SEC] [--list] [MUTANT...]"
full=0
list_only=0
timeout=30
names=()
while [ $# -gt 0 ]; do
  case "$1" in
    --full) full=1 ;;
    --list) list_only=1 ;;
    --timeout)
      if [ $# -lt 2 ] || ! [[ "$2" =~ ^[1-9][0-9]*$ ]]; then
        echo "mutate.sh: --timeout needs a whole number of seconds; $usage" >&2
        exit 2
      fi
      timeout=$2
      shift ;;
    -h|--help) echo "$usage"; exit 0 ;;
    -*) echo "mutate.sh: unknown option '$1'; $usage" >&2; exit 2 ;;
    *) names+=("$1") ;;
  esac
  shift
done

root=$(cd "$(dirname "$0")/.." && pwd)
work=$root/build/mutate
src=$work/src
bld=$work/build
logs=$work/logs
hdr_rel=include/xfgcu/xf_parser.h
pristine=$work/xf_parser.h.pristine
# The tests that exercise the parser: its unit tests in every build variant, the reference
# model's test, the fuzz corpus replays, the benchmark's selftest.
test_regex='parser|fuzz_replay|bench_selftest'
first_test=test_parser # the quick first pass

for tool in git cmake ctest python3; do
  command -v "$tool" >/dev/null || { echo "mutate.sh: $tool not found" >&2; exit 1; }
done

# The mutants, in Python so that the patterns are exact multi-line strings with no shell or sed
# escaping. Each: name, what it breaks (one line), the exact text of xf_parser.h, its
# replacement. Subcommands: list; check FILE NAME... (each pattern occurs exactly once);
# apply PRISTINE NAME OUT.
mutants() {
  python3 - "$@" <<'PY'
import sys

M = [
    ("flush_keeps",
     "xf_parser_flush() keeps the bytes it holds (rule 5: flush drops them)",
     "    xf__clear(p);\n    return XF_PARSE_MORE;\n",
     "    return XF_PARSE_MORE;\n"),
    ("consumed_whole",
     "consumed = the whole chunk when a frame is returned, not just up to its last byte",
     "        *consumed = used;\n",
     "        *consumed = found ? len : used;\n"),
    ("direct_ignores_pairs",
     "the no-copy path returns a whole packet even with a header pair inside it",
     "            return 0; /* a header pair inside: the general path applies every rule */\n",
     "            continue; /* MUTANT: header pairs inside are ignored */\n"),
    ("direct_no_crc",
     "the no-copy path returns a whole packet without checking its CRC",
     "    if ((xf__crc_run(0, d, len) >> 16) != 0u) {\n",
     "    if (0) {\n"),
    ("direct_damaged_skips_tail",
     "a damaged whole packet is skipped to its end: a header in its last three bytes is lost",
     "*i += (k == 3u) ? n : n - 3u;",
     "*i += n;"),
    ("admit_tie_flipped",
     "every slot taken: a new candidate ending with the last one replaces it (> for >=)",
     "        if (len - 4u >= xf__left(p, XF_PARSER_SLOTS - 1u)) {\n",
     "        if (len - 4u > xf__left(p, XF_PARSER_SLOTS - 1u)) {\n"),
    ("insert_order_flipped",
     "candidates are inserted latest end first (insertion test < for >)",
     "xf__left(p, k - 1u) > left; k--)",
     "xf__left(p, k - 1u) < left; k--)"),
    ("insert_ties_first",
     "a new candidate goes before older ones that end with it (>= for >): wrong check order",
     "xf__left(p, k - 1u) > left; k--)",
     "xf__left(p, k - 1u) >= left; k--)"),
    ("len_min_71",
     "a length of 71 is accepted (range [71, max] instead of [72, max])",
     "return len >= XF__MIN && len <= XF_PACKET_MAX_LEN;",
     "return len >= XF__MIN - 1u && len <= XF_PACKET_MAX_LEN;"),
    ("len_max_plus1",
     "a length of max + 1 is accepted (range [72, max + 1])",
     "return len >= XF__MIN && len <= XF_PACKET_MAX_LEN;",
     "return len >= XF__MIN && len <= XF_PACKET_MAX_LEN + 1u;"),
    ("prefix_3_dropped",
     "an h0 three bytes back is not held (xf__prefix looks two back at most): its header is lost",
     "(held >= 3u && r[XF__IX(e - 3u)] == h0)",
     "(0 && r[XF__IX(e - 3u)] == h0)"),
    ("no_settle_after_crc_fail",
     "a failed candidate that held the first byte leaves head there (settle skipped)",
     "        moved |= (p->at[0] == p->head) ? 3 : 1;\n",
     "        moved |= 1;\n"),
    ("crc_zeros_len",
     "a candidate behind another is CRC-checked with len instead of len - 4 zero bytes",
     "xf__crc_zeros(w, xf__len(p, 0) - 4u)",
     "xf__crc_zeros(w, xf__len(p, 0))"),
    ("given_up_uncounted",
     "a candidate given up is not counted in stats.given_up",
     "        p->stats.given_up++; /* the new candidate, or the pending one that ends last */\n",
     ""),
    ("length_error_uncounted",
     "a header pair with a bad length is not counted in stats.length_errors",
     "        p->stats.length_errors++;\n",
     ""),
    ("fast1_no_h0_test",
     "the one-byte fast path stores an h0 like any byte (its header is never looked at)",
     "            if (b == p->h0) {\n                return xf__feed_h0(p, consumed);\n            }\n",
     "            if (b == p->h0 && consumed == (size_t *)frame) { /* MUTANT: never */\n"
     "                return xf__feed_h0(p, consumed);\n            }\n"),
    ("fast1_no_next_test",
     "the one-byte fast path stores the byte before next (a candidate's end is never checked)",
     "        if (p->next != XF__IX(e + 1u)) {\n",
     "        if (1) {\n"),
    ("quiet_no_h0_test",
     "the short store loop stores an h0 like any byte (its header is never looked at)",
     "        for (; m < len && d[m] != h0; m++) {\n",
     "        for (; m < len; m++) { /* MUTANT */ (void)h0;\n"),
    ("take_past_next",
     "the main loop stores past next (a candidate's end or a header's fourth byte is skipped)",
     "i += xf__quiet(p, d + i, (m < quiet) ? m : quiet);",
     "i += xf__quiet(p, d + i, m); (void)quiet;"),
    ("plan_ignores_h0",
     "with candidates pending, next ignores an h0 among the last three bytes",
     "    p->next = XF__IX(e + ((k < stop) ? k : stop));\n",
     "    p->next = XF__IX(e + stop + 0u * k);\n"),
    ("h0_keeps_next",
     "an h0 taken before next does not bring next to its fourth byte",
     "    if (XF__IX(p->next - p->end) > 3u) {\n",
     "    if (0) {\n"),
    ("look_keeps_next",
     "a header's fourth byte that opens nothing leaves next where the h0 put it (no new plan)",
     "    } else {\n        xf__plan(p);\n    }\n    return 0;\n}\n",
     "    }\n    return 0;\n}\n"),
    ("hunt_keeps_head",
     "with no candidate, a header pair whose length opens nothing leaves head on its h0 (no settle)",
     "&& xf__open(p) == 0) {\n        xf__settle(p);\n    }\n",
     "&& xf__open(p) == 0) {\n        (void)p; /* MUTANT */\n    }\n"),
    ("hunt_skip_keeps_next",
     "with no candidate, an h0 followed by no h1 moves head but leaves next on the old fourth byte",
     "        p->next = XF__IX(p->head + 4u);\n        return 0;\n",
     "        return 0;\n"),
    ("hunt_skip_uncounted",
     "with no candidate, the bytes dropped before the next h0 are not counted in bytes_skipped",
     "        p->stats.bytes_skipped += k;\n",
     ""),
    ("hunt_skip_past_h0",
     "with no candidate, head skips the h0 right after an h0 followed by no h1 (its header is lost)",
     "    unsigned k = 1;\n",
     "    unsigned k = 2;\n"),
    ("plan_pair_inverted",
     "with candidates pending, next skips an h0 that is followed by h1 (a header pair is never looked at)",
     "(r[XF__IX(e - 3u)] == h0 && r[XF__IX(e - 2u)] == h1)",
     "(r[XF__IX(e - 3u)] == h0 && r[XF__IX(e - 2u)] != h1)"),
    ("admit_no_sum",
     "a candidate admitted behind others takes the CRC as last brought up to date, not up to its header",
     "    xf__sum(p);\n    p->n = (uint8_t)(k + 1u);\n",
     "    p->n = (uint8_t)(k + 1u);\n"),
    ("first_skips_length",
     "the first candidate's running CRC starts after its length bytes (they are never CRC'd)",
     "        p->sum = XF__IX(p->end - 2u);\n",
     "        p->sum = p->end;\n"),
    ("admitted_next_past_end",
     "a header admitted or given up sets next one byte past candidate 0's end (the end is never checked)",
     "(xf__plan's answer) */\n        p->next = XF__IX(p->end + xf__left(p, 0));\n",
     "(xf__plan's answer) */\n        p->next = XF__IX(p->end + xf__left(p, 0) + 1u);\n"),
    ("admitted_no_settle",
     "a header admitted in place of the candidate that held the first byte leaves head there",
     "    if (look & 2) {\n        xf__settle(p);\n    }\n",
     "    if (0) {\n        xf__settle(p);\n    }\n"),
    ("idle_next_past_end",
     "a header opened whole from the caller's chunk sets next one byte past its packet's end",
     "    p->next = (uint8_t)n;\n",
     "    p->next = (uint8_t)(n + 1u);\n"),
    ("idle_skip_uncounted",
     "a header pair with a bad length, skipped whole from the caller's chunk, is no length error",
     "        p->stats.length_errors += (d[1] == xf__h1(p));\n",
     "        p->stats.length_errors += 0u;\n"),
    ("idle_skips_header",
     "a valid header whose whole packet is not in the chunk is skipped as if it were none",
     "    if (d[1] != xf__h1(p) || !xf__len_ok(n)) {\n",
     "    if (d[1] != xf__h1(p) || !xf__len_ok(n) || n > len) {\n"),
    ("sum_no_wrap",
     "the CRC is not carried round the ring's end",
     "    if (e < s) {\n",
     "    if (0) {\n"),
    ("no_rotate",
     "a frame that wraps round the ring's end is returned unrotated",
     "if (i0 + len > XF_PARSER_RING) {",
     "if (0) { /* MUTANT: never made contiguous */"),
    ("emit_skip_uncounted",
     "bytes before a returned frame's start are not counted in bytes_skipped at emit",
     "    p->stats.bytes_skipped += (unsigned)XF__IX(i0 - p->head);\n",
     ""),
]
by_name = {m[0]: m for m in M}
assert len(by_name) == len(M), "two mutants share a name"


def pick(names):
    for n in names:
        if n not in by_name:
            sys.stderr.write("mutate.sh: no mutant named '%s' (scripts/mutate.sh --list)\n" % n)
            sys.exit(2)
    return [by_name[n] for n in names] if names else M


cmd, args = sys.argv[1], sys.argv[2:]
if cmd == "list":
    for m in pick(args):
        print("%s\t%s" % (m[0], m[1]))
elif cmd == "check":
    text = open(args[0]).read()
    bad = []
    for name, _, old, new in pick(args[1:]):
        n = text.count(old)
        if n != 1 or old == new:
            bad.append("  %s: its pattern occurs %d times in %s (must be exactly once)" % (name, n, args[0]))
    if bad:
        sys.exit("mutate.sh: stale mutants; update them to the current parser:\n" + "\n".join(bad))
elif cmd == "apply":
    name, _, old, new = pick([args[1]])[0]
    text = open(args[0]).read()
    if text.count(old) != 1:
        sys.exit("mutate.sh: mutant %s no longer matches exactly once" % name)
    with open(args[2], "w") as f:
        f.write(text.replace(old, new, 1))
else:
    sys.exit("mutate.sh: internal: unknown subcommand " + cmd)
PY
}

if [ "$list_only" = 1 ]; then
  mutants list ${names[@]+"${names[@]}"} | awk -F'\t' '{ printf "%-26s %s\n", $1, $2 }'
  exit 0
fi

t0=$SECONDS
# Fail before any build if a mutant's pattern has rotted (checked against the real header).
mutants check "$root/$hdr_rel" ${names[@]+"${names[@]}"}
mapfile -t selected < <(mutants list ${names[@]+"${names[@]}"} | cut -f1)

# ---- the scratch copy: fresh every run, so that no stale object or file can leak in ----------
echo "== copying the working tree to ${work#"$root"/}/src"
rm -rf "$work"
mkdir -p "$src" "$logs"
# Tracked files (skipping any deleted in the working tree) and untracked, non-ignored ones;
# never build/ itself, whatever .gitignore says.
git -C "$root" ls-files -z -co --exclude-standard |
  (cd "$root" && while IFS= read -r -d '' f; do
     case "$f" in build/*) continue ;; esac
     if [ -e "$f" ]; then printf '%s\0' "$f"; fi
   done) |
  tar -C "$root" --null -T - -cf - | tar -C "$src" -xf -
cp "$src/$hdr_rel" "$pristine"
# However the run ends, leave the scratch header pristine.
trap 'cp "$pristine" "$src/$hdr_rel" 2>/dev/null || true' EXIT

gen=()
if command -v ninja >/dev/null; then
  gen=(-G Ninja)
fi
echo "== configuring one Debug build in ${bld#"$root"/}"
cmake -S "$src" -B "$bld" ${gen[@]+"${gen[@]}"} -DCMAKE_BUILD_TYPE=Debug \
  -DXFGCU_BUILD_TESTS=ON -DXFGCU_BUILD_BENCH=ON -DXFGCU_BUILD_TOOLS=OFF -DXFGCU_BUILD_EXAMPLES=OFF \
  -DXFGCU_BUILD_DOCS=OFF -DXFGCU_BUILD_POSIX=OFF -DXFGCU_BUILD_FUZZ=OFF -DXFGCU_INSTALL=OFF \
  >"$logs/configure.log" 2>&1 || { echo "mutate.sh: configure failed: $logs/configure.log" >&2; exit 1; }

# The parser tests, from ctest itself (so that a new variant is picked up), and the programs they
# run: each test runs the program of its own name, except the benchmark's selftest (checked
# against ctest once they are built). Their per-test time limit: the tests set TIMEOUT 120
# themselves, which ctest --timeout cannot lower, so the limit is appended to the generated test
# files of this scratch build (the real tree is untouched) and read back to make sure it took.
plan=$(ctest --test-dir "$bld" --show-only=json-v1 -R "$test_regex" 2>/dev/null | python3 -c '
import json, sys
tests = json.load(sys.stdin)["tests"]
for t in tests:
    print("test", t["name"], {"bench_selftest": "xfgcu_bench"}.get(t["name"], t["name"]))
print("replays", sum(1 for t in tests for p in t.get("properties", [])
                     if p["name"] == "LABELS" and "fuzz-replay" in p["value"]))
')
mapfile -t tests < <(awk '$1 == "test" { print $2 }' <<<"$plan")
mapfile -t targets < <(awk '$1 == "test" { print $3 }' <<<"$plan" | sort -u)
if [ "${#tests[@]}" = 0 ]; then
  echo "mutate.sh: no parser tests configured (cmocka missing? scripts/setup.sh --dev): $logs/configure.log" >&2
  exit 1
fi
# Every test labelled fuzz-replay must be among them, and the quick first pass must exist.
n_all_replays=$(ctest --test-dir "$bld" -N -L fuzz-replay 2>/dev/null | sed -n 's/^Total Tests: //p')
if [ "$(awk '$1 == "replays" { print $2 }' <<<"$plan")" != "$n_all_replays" ]; then
  echo "mutate.sh: some fuzz-replay tests do not match /$test_regex/" >&2
  exit 1
fi
if ! printf '%s\n' "${tests[@]}" | grep -qx "$first_test"; then
  echo "mutate.sh: no test named $first_test" >&2
  exit 1
fi

find "$bld" -name CTestTestfile.cmake -print0 | while IFS= read -r -d '' f; do
  printf '# scripts/mutate.sh: a mutant may loop forever\nset_tests_properties(%s PROPERTIES TIMEOUT %s)\n' \
    "${tests[*]}" "$timeout" >>"$f"
done
ctest --test-dir "$bld" --show-only=json-v1 -R "$test_regex" 2>/dev/null | python3 -c '
import json, sys
limit = float(sys.argv[1])
for t in json.load(sys.stdin)["tests"]:
    got = [p["value"] for p in t.get("properties", []) if p["name"] == "TIMEOUT"]
    if got != [limit]:
        sys.exit("mutate.sh: the %gs limit did not take for %s (%s)" % (limit, t["name"], got))
' "$timeout"

all_re="^($(IFS='|'; echo "${tests[*]}"))\$"
jobs=$(nproc 2>/dev/null || echo 2)

# build LOG TARGET...: rebuild only these programs.
build() {
  local log=$1
  shift
  cmake --build "$bld" --parallel "$jobs" --target "$@" >>"$log" 2>&1
}

# run_tests LOG REGEX [ctest options...]: run the tests; sets `failed` to the tests that failed
# or timed out ("" when all passed). Returns 1 when ctest failed without naming a failed test
# (ctest itself broken: not a kill).
run_tests() {
  local log=$1 re=$2 rc=0
  shift 2
  ctest --test-dir "$bld" -R "$re" --parallel "$jobs" --timeout "$timeout" --output-on-failure "$@" \
    >>"$log" 2>&1 || rc=$?
  # ctest lists them as "  4 - test_parser (Failed)" or "(Timeout)" after "The following tests FAILED:"
  failed=$(sed -n '/The following tests FAILED:/,$ s/^[[:space:]]*[0-9]* - \([^ ]*\) (\([^)]*\)).*/\1(\2)/p' "$log" |
           sort -u | tr '\n' ' ' | sed 's/ $//')
  if [ "$rc" != 0 ] && [ -z "$failed" ]; then
    return 1
  fi
  return 0
}

# ---- the unmutated suite must pass, or no kill means anything ---------------------------------
echo "== building ${#targets[@]} programs for ${#tests[@]} parser tests (${gen[*]:-default generator})"
build "$logs/pristine.build.log" "${targets[@]}" || { echo "mutate.sh: the pristine build failed: $logs/pristine.build.log" >&2; exit 1; }
# Each test must run one of the programs rebuilt for the mutants, or a mutant would go untested.
ctest --test-dir "$bld" --show-only=json-v1 -R "$test_regex" 2>/dev/null | python3 -c '
import json, os, sys
built = set(sys.argv[1:])
for t in json.load(sys.stdin)["tests"]:
    prog = os.path.basename(t.get("command", ["(not built)"])[0])
    if prog not in built:
        sys.exit("mutate.sh: test %s runs %s, which is not rebuilt for the mutants" % (t["name"], prog))
' "${targets[@]}"
echo "== the unmutated parser tests (${tests[*]})"
if ! run_tests "$logs/pristine.ctest.log" "$all_re" || [ -n "$failed" ]; then
  echo "mutate.sh: the unmutated parser tests fail (${failed:-ctest error}): $logs/pristine.ctest.log" >&2
  exit 1
fi
echo "   all ${#tests[@]} pass ($((SECONDS - t0))s so far)"

# ---- the mutants ---------------------------------------------------------------------------------
declare -A result killers desc
while IFS=$'\t' read -r n d; do desc[$n]=$d; done < <(mutants list "${selected[@]}")
status=0
for m in "${selected[@]}"; do
  blog=$logs/$m.build.log
  tlog=$logs/$m.ctest.log
  : >"$blog"
  : >"$tlog"
  mutants apply "$pristine" "$m" "$src/$hdr_rel"
  printf '== %-26s ' "$m"
  failed=""
  res=""
  if [ "$full" = 0 ]; then
    # Quick pass: test_parser alone (one program to rebuild), stopping at the first failure.
    if ! build "$blog" "$first_test"; then
      res="NO-BUILD"
    elif ! run_tests "$tlog" "^$first_test\$" --stop-on-failure; then
      res="ERROR"
    elif [ -n "$failed" ]; then
      res="KILLED"
    fi
  fi
  if [ -z "$res" ]; then
    # Every parser test (all in --full mode; else what test_parser let through).
    stop=(--stop-on-failure)
    [ "$full" = 1 ] && stop=()
    if ! build "$blog" "${targets[@]}"; then
      res="NO-BUILD"
    elif ! run_tests "$tlog" "$all_re" ${stop[@]+"${stop[@]}"}; then
      res="ERROR"
    elif [ -n "$failed" ]; then
      res="KILLED"
    else
      res="SURVIVED"
    fi
  fi
  case "$res" in
    KILLED) killers[$m]=$failed ;;
    NO-BUILD) killers[$m]="does not compile: $blog"; status=1 ;;
    ERROR) killers[$m]="ctest failed without a failed test: $tlog"; status=1 ;;
    SURVIVED) killers[$m]="every parser test passed: $tlog"; status=1 ;;
  esac
  result[$m]=$res
  echo "$res"
done
cp "$pristine" "$src/$hdr_rel"

# ---- the table -------------------------------------------------------------------------------------
echo
printf '%-26s %-9s %s\n' "MUTANT" "RESULT" "WHAT IT BREAKS  [killed by]"
for m in "${selected[@]}"; do
  printf '%-26s %-9s %s  [%s]\n' "$m" "${result[$m]}" "${desc[$m]}" "${killers[$m]}"
done
killed=0
for m in "${selected[@]}"; do [ "${result[$m]}" = KILLED ] && killed=$((killed + 1)); done
echo
echo "$killed of ${#selected[@]} mutants killed; $((SECONDS - t0))s wall; logs in ${logs#"$root"/}"
if [ "$status" != 0 ]; then
  echo "mutate.sh: not every mutant was killed (see the table)" >&2
fi
exit "$status"
