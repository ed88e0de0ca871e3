#!/usr/bin/env bash
# How long `xfgcu send shutter` takes, from start to exit, against the simulator on loopback at
# the default 50 Hz: the whole program (start, link, the null whose reply lets it start, the
# command, its reply, settling). Prints the minimum, median, 90th percentile and maximum of N
# runs per link. A figure, never asserted (times depend on the machine).
#   scripts/bench_send.sh [XFGCU] [N]     XFGCU: the program (default build/gcc/tools/xfgcu); N: 30
set -euo pipefail
cd "$(dirname "$0")/.."
exe=${1:-build/gcc/tools/xfgcu}
n=${2:-30}
[ -x "$exe" ] || { echo "bench_send.sh: $exe not built" >&2; exit 1; }
out=$(mktemp -d)
trap 'kill $(jobs -p) 2>/dev/null || true; rm -rf "$out"' EXIT

# one link: its name, the simulator's options, a function printing the client's link options
run_link() {
  local name=$1 simopt=$2 port
  "$exe" sim $simopt 0 --duration 120 > "$out/$name.sim" &
  for _ in $(seq 50); do grep -q listening "$out/$name.sim" 2>/dev/null && break; sleep 0.1; done
  port=$(grep -o '127.0.0.1:[0-9]*' "$out/$name.sim" | head -1 | cut -d: -f2)
  for _ in $(seq "$n"); do
    local t0 t1
    t0=$(date +%s%N)
    if [ "$name" = udp ]; then
      "$exe" --udp 127.0.0.1 --gcu-port "$port" --local-port 0 send shutter > /dev/null
    else
      "$exe" --tcp "127.0.0.1:$port" send shutter > /dev/null
    fi
    t1=$(date +%s%N)
    echo $(((t1 - t0) / 1000)) >> "$out/$name.us"
  done
  sort -n "$out/$name.us" | awk -v name="$name" -v n="$n" '{v[NR] = $1}
    END {printf "send shutter, %s loopback, 50 Hz, %d runs: min %.1f ms, median %.1f ms, p90 %.1f ms, max %.1f ms\n",
         name, n, v[1] / 1000, v[int((n + 1) / 2)] / 1000, v[int(n * 0.9 + 0.5)] / 1000, v[n] / 1000}'
}

run_link udp --udp
run_link tcp --tcp
