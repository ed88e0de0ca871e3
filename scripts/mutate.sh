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
    ('flush_keeps',
     'xf_parser_flush() keeps the bytes it holds (rule 5: flush drops them)',
     '    xf__clear(p);\n    return XF_PARSE_MORE;\n',
     '    return XF_PARSE_MORE;\n'),
    ('consumed_whole',
     'consumed = the whole chunk when a frame is returned, not just up to its last byte',
     '    p->stats.bytes_in += (uint32_t)used;\n    if (consumed != NULL) {\n        *consumed = used;\n    }\n    return found ? XF_PARSE_FRAME : XF_PARSE_MORE;',
     '    p->stats.bytes_in += (uint32_t)used;\n    if (consumed != NULL) {\n        *consumed = found ? len : used;\n    }\n    return found ? XF_PARSE_FRAME : XF_PARSE_MORE;'),
    ('settle_latest_end',
     'settle takes the latest end for next, not the soonest',
     'soon = (xf__left(p, k) < xf__left(p, soon)) ? k : soon;',
     'soon = (xf__left(p, k) > xf__left(p, soon)) ? k : soon;'),
    ('crc_zeros_len',
     'a candidate behind another is CRC-checked with len instead of len - 4 zero bytes',
     'xf__crc_zeros(w, xf__len(p, k) - 4u)',
     'xf__crc_zeros(w, xf__len(p, k))'),
    ('length_error_uncounted',
     'a header pair with a bad length is not counted in stats.length_errors (the byte path)',
     '    } else {\n        p->stats.length_errors++;\n',
     '    } else {\n'),
    ('sum_no_wrap',
     "the CRC is not carried round the ring's end",
     '    if (e < s) {\n',
     '    if (0) {\n'),
    ('no_rotate',
     "a frame that wraps round the ring's end is returned unrotated",
     'if (i0 + len > XF_PARSER_RING) {',
     'if (0) { /* MUTANT: never made contiguous */'),
    ('emit_skip_uncounted',
     "bytes before a returned frame's start are not counted in bytes_skipped at emit",
     '        p->stats.bytes_skipped += (unsigned)XF__IX(i0 - p->at[0]);\n    }\n',
     '    }\n'),
    ('given_up_uncounted',
     'running out of credit or slots is not counted in stats.given_up',
     '    if (p->credit < XF__COST) {\n        p->stats.given_up++;',
     '    if (0) {\n        p->stats.given_up++;'),
    ('len_min_71',
     'a length of 71 is taken for a valid one',
     'return len >= XF_PACKET_MIN_LEN && len <= XF_PACKET_MAX_LEN; }',
     'return len + 1u >= XF_PACKET_MIN_LEN && len <= XF_PACKET_MAX_LEN; }'),
    ('len_max_plus1',
     'a length one past XF_PACKET_MAX_LEN is taken for a valid one',
     'return len >= XF_PACKET_MIN_LEN && len <= XF_PACKET_MAX_LEN; }',
     'return len >= XF_PACKET_MIN_LEN && len <= XF_PACKET_MAX_LEN + 1u; }'),
    ('step_no_trim',
     'with no candidate, the byte path keeps a fourth byte held',
     '        xf__trim(p); /* no candidate (a bad length, or none): four bytes held */\n',
     ''),
    ('fast1_no_pair_test',
     'a byte fed alone never completes a header pair',
     '    if (p->ring[XF__IX(e - 3u)] != p->h0 || p->ring[XF__IX(e - 2u)] != xf__h1(p) || xf__deaf(p)) {\n        /* A UART',
     '    if (1) {\n        /* A UART'),
    ('fast1_no_end_test',
     'a byte fed alone never ends a candidate',
     '        if (XF__IX(e + 1u) != p->next) {\n            return xf__store1(p, d[0], consumed, used);',
     '        if (p->n > 0u || XF__IX(e + 1u) != p->next) {\n            return xf__store1(p, d[0], consumed, used);'),
    ('fast1_bad_len_uncounted',
     'a byte fed alone that completes a pair with a bad length is not counted',
     '        p->stats.length_errors++;\n        if (XF__IX(e + 1u) == p->next) {\n            xf__trim(p); /* no candidate: the first of four goes */\n        }\n        return xf__store1',
     '        if (XF__IX(e + 1u) == p->next) {\n            xf__trim(p); /* no candidate: the first of four goes */\n        }\n        return xf__store1'),
    ('fast1_bad_len_stale',
     'a byte fed alone counts a bad length of a pair of stale ring bytes (fewer than three held)',
     '    if ((d[0] != 0u || !xf__len_ok(p->ring[XF__IX(e - 1u)])) && !xf__few(p) &&',
     '    if ((d[0] != 0u || !xf__len_ok(p->ring[XF__IX(e - 1u)])) &&'),
    ('fast1_bad_len_no_trim',
     'hunting, a byte fed alone that completes a pair with a bad length keeps a fourth byte held',
     '            xf__trim(p); /* no candidate: the first of four goes */\n        }\n        return xf__store1',
     '        }\n        return xf__store1'),
    ('fast1_bad_len_skips_end',
     'a byte fed alone that completes a pair with a bad length and ends a candidate is not checked',
     '    if ((d[0] != 0u || !xf__len_ok(p->ring[XF__IX(e - 1u)])) && !xf__few(p) &&\n        (XF__IX(e + 1u) != p->next || p->n == 0u)) {',
     '    if ((d[0] != 0u || !xf__len_ok(p->ring[XF__IX(e - 1u)])) && !xf__few(p)) {'),
    ('fast1_no_trim',
     'a byte fed alone with no candidate keeps a fourth byte held',
     '            xf__trim(p);\n            return xf__store1(p, d[0], consumed, used);',
     '            return xf__store1(p, d[0], consumed, used);'),
    ('scan_skips_low_byte',
     "after a pair with a bad length the search skips its length's low byte (a pair it begins is missed)",
     '            ++*errors;\n            i += 2u;',
     '            ++*errors;\n            i += 3u;'),
    ('scan_misses_last',
     "a pair whose fourth byte is the region's last is not searched for",
     '    while (i + 3u < r) {',
     '    while (i + 4u < r) {'),
    ('run_no_lookbehind',
     "inside a candidate, pairs begun in the three bytes before the chunk's position are not searched for",
     '(i < 3u) ? i : i - 3u, r, &p->stats.length_errors',
     'i, r, &p->stats.length_errors'),
    ('take_no_tail',
     "a pair begun among the bytes held and completed by a chunk's first bytes is missed",
     '        if (i < 3u && !xf__deaf(p) && xf__tail(p)) {',
     '        if (0) {'),
    ('no_give_back',
     'hunting, the bytes held are not given back to the idle path (pairs they begin are missed)',
     '    if (i >= 3u) {\n        XF_ASSERT(xf__held(p) <= 3u);',
     '    if (0) {\n        XF_ASSERT(xf__held(p) <= 3u);'),
    ('direct_no_crc',
     'a whole packet at a chunk\'s start is returned without its CRC checked',
     '    if ((xf__crc_run(0, d, len) >> 16) == 0u) {',
     '    if (1) {'),
    ('direct_ignores_pairs',
     'a packet at a chunk\'s start is taken on the fresh path even with a header pair completing inside',
     '        if (hit[1] == h1) {\n            m = 4;',
     '        if (hit[1] == h1 && hit < d) {\n            m = 4;'),
    ('direct_ignores_last_pair',
     'a packet at a chunk\'s start is taken on the fresh path even when its last byte completes a header pair',
     '    const uint8_t *hit = d, *stop = d + m - 3u;',
     '    const uint8_t *hit = d, *stop = d + m - 4u;'),
    ('fresh_damaged_dropped',
     'a damaged packet at a chunk\'s start is skipped whole: its last three bytes (they may begin a header) not held',
     '    p->stats.crc_errors++;\n    xf__keep(p, d, len);',
     '    p->stats.crc_errors++;\n    p->stats.bytes_skipped += len;'),
    ('fresh_open_next',
     'a candidate opened on the fresh path looks at the byte after its last one',
     '        p->n = 1;\n        p->next = (uint8_t)len;',
     '        p->n = 1;\n        p->next = (uint8_t)(len + 1u);'),
    ('keep_four',
     'with no candidate, four bytes of a chunk are held, not three',
     '        d += m - 3u;\n        m = 3;',
     '        d += m - 4u;\n        m = 4;'),
    ('admit_next_last',
     'a candidate admitted behind others never brings next forward, even when it ends sooner',
     '            p->next = (uint8_t)xf__fin(p, k);\n',
     ''),
    ('ends_first_only',
     'of the candidates that end on the same byte, only the first is checked',
     '            xf__drop(p, k);\n        }\n    } while (k < p->n);',
     '            xf__drop(p, k);\n            break;\n        }\n    } while (k < p->n);'),
    ('feed_no_tail',
     'the in-frame path of a chunk misses a pair begun among the bytes held',
     '    if (len > 0u && p->n > 0u && !xf__tail(p)) {',
     '    if (len > 0u && p->n > 0u) {'),
    ('feed_end_unchecked',
     "the in-frame path stores the soonest end's last byte without checking the candidates",
     '        if (m == left) {\n            found = xf__look(p, 0, frame);',
     '        if (0) {\n            found = xf__look(p, 0, frame);'),
    ('pair1_no_held_check',
     'a byte fed alone completes a pair of stale ring bytes when fewer than three are held',
     '|| xf__few(p)) {\n        return xf__feed1(p, b, consumed, used, frame);',
     ') {\n        return xf__feed1(p, b, consumed, used, frame);'),
    ('settle_keeps_all',
     'with no candidate left after a check, every byte stays held: none is skipped',
     '        if (held > 3u) {',
     '        if (0) {'),
    ('trim_uncounted',
     'a byte dropped while hunting is not counted in bytes_skipped',
     '    p->next = XF__IX(p->next + 1u); /* (and so the first byte held: xf__head) */\n    p->stats.bytes_skipped++;\n',
     '    p->next = XF__IX(p->next + 1u); /* (and so the first byte held: xf__head) */\n'),
    ('idle_skip_uncounted',
     'bytes skipped before a header found in the chunk are not counted',
     '    p->stats.bytes_skipped += xf__held(p) + (uint32_t)(s - *i);',
     '    p->stats.bytes_skipped += xf__held(p);'),
    ('drop_skip_uncounted',
     'when the first candidate fails, the bytes before the next one are not counted in bytes_skipped',
     '        p->stats.bytes_skipped += (unsigned)XF__IX(p->at[XF__K > 1 ? 1 : 0] - p->at[0]); /* (one slot: never) */\n',
     ''),
    ('credit_no_cost',
     'a candidate admitted behind others costs no credit',
     '        p->credit = (uint8_t)(p->credit - XF__COST);\n',
     ''),
    ('credit_no_earn',
     "the bytes CRC'd while candidates are pending earn no credit",
     '    xf__earn(p, (unsigned)XF__IX(e - s));\n',
     ''),
    ('credit_fresh_no_earn',
     'a whole packet checked on the fresh path earns no credit (its bytes would in the byte path)',
     '    xf__earn(p, len); /* as xf__sum at its end */\n',
     ''),
    ('credit_slots_open',
     'taking the last slot leaves the credit as it is: headers are looked at with every slot taken',
     'if (n == XF__K) {',
     'if (n > XF__K) { /* MUTANT: never */'),
    ('credit_lone_deaf',
     'a header after nothing pending is refused when the credit is short',
     'return p->credit < XF__COST && p->n > 0u; }',
     'return p->credit < XF__COST; }'),
    ('credit_cap_four',
     "the credit holds four candidates' cost, not three",
     '#define XF__CAP  (3u * XF__COST)',
     '#define XF__CAP  (4u * XF__COST)'),
    ('credit_clear_keeps',
     'a reset or flush keeps the credit as it was instead of a full one',
     '    xf__empty(p);\n    p->credit = XF__CAP;\n',
     '    xf__empty(p);\n'),
    ('look_ignores_credit',
     'the byte that ends a candidate looks at the pair it completes even when the credit is short',
     '    if (pair && !xf__deaf(p)) {',
     '    if (pair) {'),
    ('fresh_given_up_uncounted',
     'a candidate opened on the fresh path is not taken: with the credit short, given_up does not count it',
     '    xf__taken(p, 1);',
     '    (void)0;'),
    ('emit_skip_second',
     'a returned frame that began second: the bytes before it are not counted in bytes_skipped',
     '    if (k > 0u) { /* the bytes before it',
     '    if (k > 1u) { /* the bytes before it'),
    ('plain_no_end',
     'a few bytes fed together: a byte that ends a candidate is stored unchecked',
     "    } else if (XF__IX(e + 1u) == p->next && p->n > 0u) {\n        return 0; /* a candidate's end */",
     "    } else if (0) {\n        return 0; /* a candidate's end */"),
    ('plain_no_few',
     'a few bytes fed together: a pair of stale ring bytes (fewer than three held) counts a bad length',
     '        if ((b == 0u && xf__len_ok(p->ring[XF__IX(e - 1u)])) || xf__few(p) ||',
     '        if ((b == 0u && xf__len_ok(p->ring[XF__IX(e - 1u)])) ||'),
    ('plain_end_pair',
     'a few bytes fed together: a bad length on a byte that also ends a candidate skips the check',
     '        if ((b == 0u && xf__len_ok(p->ring[XF__IX(e - 1u)])) || xf__few(p) ||\n            (XF__IX(e + 1u) == p->next && p->n > 0u)) {',
     '        if ((b == 0u && xf__len_ok(p->ring[XF__IX(e - 1u)])) || xf__few(p)) {'),
    ('two_middle_unlooked',
     'three bytes fed together: the middle one is stored without a look',
     '    if (len == 3u && !xf__plain(p, data[1])) {',
     '    if (len == 3u && !xf__plain(p, data[1]) && 0) {'),
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
