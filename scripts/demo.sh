#!/usr/bin/env bash
# The main job: set up (Debian packages), build, and run the demo: a simulated GCU and the
# xfgcu client over a real loopback TCP link, on a guided tour. No hardware needed.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
cmake -S . -B build/demo -DCMAKE_BUILD_TYPE=Release -DXFGCU_BUILD_TESTS=OFF -DXFGCU_BUILD_BENCH=OFF \
      -DXFGCU_BUILD_EXAMPLES=OFF >/dev/null
cmake --build build/demo --parallel "$(nproc)" --target xfgcu >/dev/null
exec build/demo/tools/xfgcu demo
