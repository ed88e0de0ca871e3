#!/usr/bin/env bash
# Instructions per byte of the streaming parser, and per packet of pack and
# unpack, counted with valgrind --tool=callgrind (deterministic: no timing).
#
#   scripts/bench.sh            build (gcc -O2, Release) with the nibble CRC table, with
#                               XFGCU_CRC_TABLE_256=ON, and with XF_PARSER_MEMO=0 in build/bench/,
#                               generate the streams, print the table. Well under a minute.
#   scripts/bench.sh profile    the same builds with -g: where the instructions go, per
#                               function of the headers (inlined code included), for the
#                               2 MiB valid, adversarial and dense streams (needs python3).
#
# Ir per byte = (Ir(parse 2 MiB) - Ir(parse 1 MiB)) / 1 MiB, counting only inside
# xb_parse (--toggle-collect), so start-up and file reading are excluded; the 1 MiB
# stream is a prefix of the 2 MiB one. Per packet likewise with 2N and N packets.
# Figures are printed, never asserted. docs/performance.md explains the streams.
set -euo pipefail
cd "$(dirname "$0")/.."

bdir=build/bench
cc="${BENCH_CC:-gcc}"
for tool in valgrind cmake "$cc"; do
  command -v "$tool" >/dev/null 2>&1 || { echo "bench.sh: $tool not found (scripts/setup.sh --dev)" >&2; exit 1; }
done

mode="${1:-table}"
case "$mode" in table|profile) ;; *) sed -n '2,16p' "$0" >&2; exit 2 ;; esac
extra=""
[ "$mode" = profile ] && extra=" -g"

build() { # dir table256 [extra C flags]
  cmake -S . -B "$bdir/$1" -DCMAKE_BUILD_TYPE=Release -DCMAKE_C_COMPILER="$cc" \
    "-DCMAKE_C_FLAGS_RELEASE=-O2$extra -DNDEBUG" -DXFGCU_CRC_TABLE_256="$2" "-DCMAKE_C_FLAGS=${3:-}" \
    -DXFGCU_BUILD_BENCH=ON -DXFGCU_BUILD_TESTS=OFF -DXFGCU_BUILD_TOOLS=OFF \
    -DXFGCU_BUILD_EXAMPLES=OFF -DXFGCU_BUILD_FUZZ=OFF >/dev/null
  cmake --build "$bdir/$1" --target xfgcu_bench --parallel "$(nproc)" >/dev/null
}

# ir BIN FUNCTION ARGS...: instructions executed inside FUNCTION
ir() {
  local bin="$1" fn="$2" out; shift 2
  out=$(mktemp "$bdir/cg.XXXXXX")
  valgrind --tool=callgrind --callgrind-out-file="$out" --toggle-collect="$fn" \
    "$bin" "$@" >/dev/null 2>"$out.log" || { cat "$out.log" >&2; exit 1; }
  awk '/^totals:/ {print $2; exit}' "$out"
  rm -f "$out" "$out.log"
}

per() { # (a - b) / d, one decimal
  awk -v a="$1" -v b="$2" -v d="$3" 'BEGIN { printf "%.1f", (a - b) / d }'
}

# build directories: build/bench/{nibble,t256}[-CC][-g]
suffix=""
[ "$cc" != gcc ] && suffix="-$(basename "$cc")"
[ "$mode" = profile ] && suffix="$suffix-g"
echo "building ($cc -O2$extra): nibble table, 256-entry table, nibble without memo ..."
build "nibble$suffix" OFF
build "t256$suffix" ON
# the default table without the memoised CRCs (XF_PARSER_MEMO=0, the small-RAM option)
if [ "$mode" = table ]; then build "nomemo$suffix" OFF -DXF_PARSER_MEMO=0; fi

kinds=(valid noisy adversarial dense)
streams="$bdir/streams"
mkdir -p "$streams"
gen="$bdir/nibble$suffix/bench/xfgcu_bench"
declare -A inserted
for k in "${kinds[@]}"; do
  "$gen" gen "$k" 1m "$streams/$k-1m.bin" >/dev/null
  inserted[$k]=$("$gen" gen "$k" 2m "$streams/$k-2m.bin" | awk '{print $1}')
done

if [ "$mode" = profile ]; then
  command -v python3 >/dev/null 2>&1 || { echo "bench.sh: profile needs python3" >&2; exit 1; }
  for t in nibble t256; do
    for k in valid adversarial dense; do
      out="$bdir/callgrind.$t.$k.out"
      valgrind --tool=callgrind --callgrind-out-file="$out" --toggle-collect=xb_parse \
        "$bdir/$t$suffix/bench/xfgcu_bench" parse "$streams/$k-2m.bin" >/dev/null 2>&1
      echo
      echo "== $t table, $k stream (2 MiB): self instructions inside xb_parse"
      python3 bench/cg_breakdown.py "$out" 2097152
    done
  done
  echo
  echo "profiles kept in $bdir/callgrind.*.out (callgrind_annotate --auto=yes FILE for line by line)"
  exit 0
fi

MiB=1048576
N=100000
declare -A res
echo
printf '%-8s %-12s %10s %8s %16s\n' table stream "Ir/byte" "x valid" "frames 2 MiB"
printf '%-8s %-12s %10s %8s %16s\n' -------- ------------ ---------- -------- ----------------
for t in nibble t256 nomemo; do
  b="$bdir/$t$suffix/bench/xfgcu_bench"
  for k in "${kinds[@]}"; do
    i1=$(ir "$b" xb_parse parse "$streams/$k-1m.bin")
    i2=$(ir "$b" xb_parse parse "$streams/$k-2m.bin")
    res[$t.$k]=$(per "$i2" "$i1" "$MiB")
    found=$("$b" parse "$streams/$k-2m.bin" | awk '{print $1}')
    ratio=$(awk -v a="${res[$t.$k]}" -v v="${res[$t.valid]}" 'BEGIN { printf "%.2f", a / v }')
    printf '%-8s %-12s %10s %8s %16s\n' "$t" "$k" "${res[$t.$k]}" "$ratio" "$found / ${inserted[$k]}"
  done
  i1=$(ir "$b" xb_parse decode "$streams/valid-1m.bin")
  i2=$(ir "$b" xb_parse decode "$streams/valid-2m.bin")
  res[$t.decode]=$(per "$i2" "$i1" "$MiB")
  printf '%-8s %-12s %10s %8s %16s\n' "$t" "valid+decode" "${res[$t.decode]}" "" "(parse+xf_frame_gcu+feedback)"
done

echo
printf '%-8s %-28s %10s\n' table operation "Ir/packet"
printf '%-8s %-28s %10s\n' -------- ---------------------------- ----------
for t in nibble t256; do
  b="$bdir/$t$suffix/bench/xfgcu_bench"
  p1=$(ir "$b" xb_pack pack $N); p2=$(ir "$b" xb_pack pack $((2 * N)))
  u1=$(ir "$b" xb_unpack unpack $N); u2=$(ir "$b" xb_unpack unpack $((2 * N)))
  printf '%-8s %-28s %10s\n' "$t" "xf_host_pack (72/75 bytes)" "$(per "$p2" "$p1" $N)"
  printf '%-8s %-28s %10s\n' "$t" "xf_gcu_unpack (72/73 bytes)" "$(per "$u2" "$u1" $N)"
done

echo
verdict() { awk -v a="$1" -v m="$2" 'BEGIN { print (a <= m) ? "ok" : "OVER" }'; }
echo "targets:"
echo "  valid, nibble table   <= 15 Ir/byte           : ${res[nibble.valid]}  $(verdict "${res[nibble.valid]}" 15)"
echo "  valid, 256 table      <= 10 Ir/byte (aim)     : ${res[t256.valid]}  $(verdict "${res[t256.valid]}" 10)"
# "<= 3x that": 3 x the 15 Ir/byte target, and the stricter 3 x the measured clean figure
for t in nibble t256; do
  lim=$(awk -v v="${res[$t.valid]}" 'BEGIN { printf "%.1f", 3 * v }')
  for k in adversarial dense; do
    echo "  $k, $t <= 3 x 15 = 45 : ${res[$t.$k]}  $(verdict "${res[$t.$k]}" 45);" \
      "<= 3 x its valid = $lim : $(verdict "${res[$t.$k]}" "$lim")"
  done
done
echo "(frames 2 MiB: found by the parser / inserted whole by the generator; a few more found than"
echo " inserted in adversarial and dense streams are false candidates whose CRC happens to match:"
echo " about one per 65536 CRC checks. Figures are instructions, not time.)"
