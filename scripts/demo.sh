#!/usr/bin/env bash
# The main job: set up, build, and run the demo against the built-in simulator.
# (Until the client and simulator land, the demo is the codec tour.)
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DXFGCU_BUILD_TESTS=OFF >/dev/null
cmake --build build --parallel "$(nproc)" >/dev/null
exec build/examples/codec_tour
