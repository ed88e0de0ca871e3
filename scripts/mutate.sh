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
# Then, for each mutant, xf_parser.h is rewritten from the pristine copy with one short
# replacement inside one named function, where its text must occur exactly once (a pattern that
# no longer matches stops the run: the list cannot rot silently), only the affected test programs
# are rebuilt, and ctest runs them:
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

# The mutants, in Python so that the patterns need no shell or sed escaping. Each is addressed
# by the function it changes, not by long text: its name (rule<N>_... for a rule of
# docs/codec.md, accel_... for the accelerator, feed_... for the call's bookkeeping), what it
# breaks (one line), the function, and a short exact text that must occur exactly once in that
# function's body, with its replacement. A refactor elsewhere in the file leaves them alone;
# a pattern that no longer matches stops the run, naming the mutant and the function.
# Subcommands: list; check FILE NAME...; apply PRISTINE NAME OUT.
mutants() {
  python3 - "$@" <<'PY'
import re
import sys

M = [
    # rule 1: what a candidate is
    ('rule1_len_min_71', 'a length of 71 is taken for a valid one',
     'xf__look', 'len >= XF_PACKET_MIN_LEN', 'len + 1u >= XF_PACKET_MIN_LEN'),
    ('rule1_len_max_plus1', 'a length one past XF_PACKET_MAX_LEN is taken for a valid one (builds with 84)',
     'xf__look', 'len <= XF_PACKET_MAX_LEN', 'len <= XF_PACKET_MAX_LEN + 1u'),
    ("rule1_high_byte_ignored", "a length's high byte is not checked (0x0148 taken for 0x48)",
     'xf__look', '(w & 0xFFu) == 0u && ', ''),
    ('rule1_bad_length_uncounted', 'a header pair with a bad length is not counted in length_errors',
     'xf__look', 'p->stats.length_errors++;', ';'),
    ('rule1_no_floor', "the bytes before a returned frame's end may begin a header",
     'xf__empty', 'p->last4 = 0;', ';'),
    # rule 2: the checks, earliest start first, the first intact one returned
    ('rule2_crc_unchecked', 'a candidate is returned without its CRC checked',
     'xf__ends', 'xf_crc16(p->buf + p->at[k], xf__len(p, k)) == 0u', '1'),
    ('rule2_crc_error_uncounted', 'a failed candidate is not counted in crc_errors',
     'xf__ends', 'p->stats.crc_errors++;', ';'),
    ('rule2_skips_next', 'after a candidate that does not end here, the next one is skipped',
     'xf__ends', 'k++;', 'k += 2u;'),
    ('rule2_end_late', "a candidate is checked one byte after its last",
     'xf__end', 'p->at[k] + xf__len(p, k)', 'p->at[k] + xf__len(p, k) + 1u'),
    ('rule2_next_not_soonest', "next is the last candidate's end, not the soonest",
     'xf__settle', 'soon = (xf__end(p, k) < soon) ? xf__end(p, k) : soon;', 'soon = xf__end(p, k);'),
    ('rule2_admit_keeps_next', 'a candidate admitted behind others never brings next forward',
     'xf__admit', '(k == 0u || xf__end(p, k) < p->next)', '(k == 0u)'),
    ('rule2_end_unlooked', 'a byte that ends a candidate, but completes no header pair, is not looked at',
     'xf__byte', '(busy && p->held == p->next) || ', ''),
    ('rule2_looks_after_frame', "the byte that completes a frame is looked at as a header's too",
     'xf__look', 'xf__ends(p, frame)) {\n        return 1;', 'xf__ends(p, frame)) {\n        (void)0;'),
    ('rule2_no_move', 'when the earliest candidate fails, the others are not moved to the buffer\'s start',
     'xf__settle', 'XF_MEMMOVE(p->buf, p->buf + shift, p->held - shift);', ';'),
    # rule 3: first come, first served
    ('rule3_given_up_uncounted', 'a valid header that finds every slot taken is not counted in given_up',
     'xf__look', 'p->stats.given_up++;', ';'),
    ('rule3_one_slot_less', 'the slots are full one candidate early',
     'xf__mode_of', 'n < XF_PARSER_SLOTS', 'n + 1u < XF_PARSER_SLOTS'),
    ('rule3_start_off', "a candidate behind others is taken to begin one byte late",
     'xf__admit', 'p->at[k] = (uint8_t)(p->held - 4u);', 'p->at[k] = (uint8_t)(p->held - 3u);'),
    # rule 4: the bytes held, and the bytes skipped where they are dropped
    ('rule4_hunt_holds_four', 'hunting, four bytes are held, not three',
     'xf__look', 'p->held > 3u', 'p->held > 4u'),
    ('rule4_hunt_skip_uncounted', 'hunting, the byte dropped is not counted in bytes_skipped',
     'xf__look', 'p->stats.bytes_skipped++;', ';'),
    ('rule4_settle_skip_uncounted', 'the bytes before the earliest candidate left are not counted in bytes_skipped',
     'xf__settle', 'p->stats.bytes_skipped += shift;', ';'),
    ('rule4_frame_skip_uncounted', "the bytes before a returned frame are not counted in bytes_skipped",
     'xf__ends', 'p->stats.bytes_skipped += p->at[k];', ';'),
    # rule 5: end of input
    ('rule5_flush_keeps', 'xf_parser_flush() keeps the bytes it holds',
     'xf_parser_flush', 'xf_parser_reset(p);', ';'),
    ('rule5_reset_skip_uncounted', 'a reset does not count the bytes it drops in bytes_skipped',
     'xf_parser_reset', 'p->stats.bytes_skipped += p->held;', ';'),
    # the accelerator: it must take no byte the rule path would look at, and store what it takes
    ('accel_takes_end', "the accelerator takes the soonest candidate's last byte",
     'xf__quiet', '(size_t)(p->next - p->held - 1u)', '(size_t)(p->next - p->held)'),
    ('accel_no_lookbehind', 'the accelerator ignores an h0 among the last three bytes held',
     'xf__quiet', 'for (near = 0;', 'for (near = 3;'),
    ('accel_takes_pair_end', 'the accelerator takes the byte that completes a pair begun in its run',
     'xf__quiet', '(size_t)(hit - d) + 3u;', '(size_t)(hit - d) + 4u;'),
    ('accel_window_stale', "after the accelerator's run, the window keeps the bytes before it",
     'xf__keep', 'p->last4 = w;', ';'),
    ('accel_hunt_skip_uncounted', 'hunting, the bytes the accelerator drops are not counted in bytes_skipped',
     'xf__keep', 'p->stats.bytes_skipped += (uint32_t)(p->held + m - keep);', ';'),
    # the call's bookkeeping
    ('feed_consumed_whole', 'consumed is the whole chunk when a frame is returned',
     'xf__feed', '*consumed = i;', '*consumed = len;'),
    ('feed_one_byte_uncounted', 'a byte fed alone is not counted in bytes_in',
     'xf_parser_feed', 'p->stats.bytes_in++;', ';'),
]
by_name = {m[0]: m for m in M}
assert len(by_name) == len(M), "two mutants share a name"


def pick(names):
    for n in names:
        if n not in by_name:
            sys.stderr.write("mutate.sh: no mutant named '%s' (scripts/mutate.sh --list)\n" % n)
            sys.exit(2)
    return [by_name[n] for n in names] if names else M


def body(text, fn):
    """(start, end) of the definition of function fn: from the line at file level that names it
    before a parenthesis and ends with `)` or `}` (a prototype ends with `;`) to the closing brace
    in column 0, or to the end of that line for a one-line function."""
    m = re.search(r"^[A-Za-z_][^\n]*\b%s\([^\n]*[)}][ \t]*$" % re.escape(fn), text, re.M)
    if m is None:
        return None
    one_line = text.find("\n", m.start())
    if text[m.start():one_line].rstrip().endswith("}"):
        return m.start(), one_line
    close = re.compile(r"^}", re.M).search(text, m.start())
    return (m.start(), close.end()) if close else None


def where(text, name, fn, old, new):
    """The offset of old in fn's body, or an error message."""
    span = body(text, fn)
    if span is None:
        return "mutant %s: no function %s in the parser" % (name, fn)
    n = text.count(old, span[0], span[1])
    if n != 1 or old == new:
        return "mutant %s: its pattern occurs %d times in %s (must be exactly once)" % (name, n, fn)
    return text.index(old, span[0], span[1])


cmd, args = sys.argv[1], sys.argv[2:]
if cmd == "list":
    for m in pick(args):
        print("%s\t%s\t%s" % (m[0], m[2], m[1]))
elif cmd == "check":
    text = open(args[0]).read()
    bad = [w for w in (where(text, m[0], m[2], m[3], m[4]) for m in pick(args[1:])) if isinstance(w, str)]
    if bad:
        sys.exit("mutate.sh: stale mutants; update them to the current parser:\n  " + "\n  ".join(bad))
elif cmd == "apply":
    name, _, fn, old, new = pick([args[1]])[0]
    text = open(args[0]).read()
    at = where(text, name, fn, old, new)
    if isinstance(at, str):
        sys.exit("mutate.sh: " + at)
    with open(args[2], "w") as f:
        f.write(text[:at] + new + text[at + len(old):])
else:
    sys.exit("mutate.sh: internal: unknown subcommand " + cmd)
PY
}

if [ "$list_only" = 1 ]; then
  mutants list ${names[@]+"${names[@]}"} | awk -F'\t' '{ printf "%-28s %-16s %s\n", $1, $2, $3 }'
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
while IFS=$'\t' read -r n f d; do desc[$n]="$d ($f)"; done < <(mutants list "${selected[@]}")
status=0
for m in "${selected[@]}"; do
  blog=$logs/$m.build.log
  tlog=$logs/$m.ctest.log
  : >"$blog"
  : >"$tlog"
  mutants apply "$pristine" "$m" "$src/$hdr_rel"
  printf '== %-28s ' "$m"
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
printf '%-28s %-9s %s\n' "MUTANT" "RESULT" "WHAT IT BREAKS (FUNCTION)  [killed by]"
for m in "${selected[@]}"; do
  printf '%-28s %-9s %s  [%s]\n' "$m" "${result[$m]}" "${desc[$m]}" "${killers[$m]}"
done
killed=0
for m in "${selected[@]}"; do [ "${result[$m]}" = KILLED ] && killed=$((killed + 1)); done
echo
echo "$killed of ${#selected[@]} mutants killed; $((SECONDS - t0))s wall; logs in ${logs#"$root"/}"
if [ "$status" != 0 ]; then
  echo "mutate.sh: not every mutant was killed (see the table)" >&2
fi
exit "$status"
