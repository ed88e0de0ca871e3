#!/usr/bin/env bash
# Firmware in the loop, in one command: the example firmware (examples/mcu, its emulator image)
# runs under qemu-system-arm's netduinoplus2 machine against `xfgcu sim` as the gimbal, which is
# stopped, started again and given faults around it. The firmware's report is printed as it
# comes, then the checks (tests/firmware/firmware_loop.py); about half a minute after the builds.
#   scripts/firmware_loop.sh [--xfgcu PATH] [--qemu PATH] [--build DIR]
#     --xfgcu PATH  the xfgcu program to run as the gimbal (default: built in DIR/host)
#     --qemu PATH   qemu-system-arm (default: from PATH)
#     --build DIR   where the builds and the logs go (default: build/firmware)
# The image is built with short periods for the test: a photo every 2 s, the stand-in INS valid
# after 4 s. Needs qemu-system-arm and gcc-arm-none-eabi (scripts/setup.sh --dev).
# Exit 0 when every check holds, 1 when one fails, 2 on bad usage.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$root/build/firmware
xfgcu=
qemu=qemu-system-arm
usage() { echo "usage: scripts/firmware_loop.sh [--xfgcu PATH] [--qemu PATH] [--build DIR]" >&2; exit 2; }
while [ $# -gt 0 ]; do
  [ $# -ge 2 ] || usage
  case $1 in
    --xfgcu) xfgcu=$2 ;;
    --qemu) qemu=$2 ;;
    --build) build=$2 ;;
    *) usage ;;
  esac
  shift 2
done
for tool in "$qemu" arm-none-eabi-gcc python3; do
  command -v "$tool" >/dev/null || { echo "firmware_loop: $tool not found (scripts/setup.sh --dev installs it)" >&2; exit 1; }
done
mkdir -p "$build"

# run LOG CMD...: its output goes to LOG, and is shown only when it fails
run() {
  local log=$1
  shift
  "$@" >"$log" 2>&1 || { cat "$log" >&2; echo "firmware_loop: failed: $*" >&2; exit 1; }
}

echo "firmware_loop: building the emulator's image (examples/mcu, board_netduinoplus2.c) in $build/m4"
run "$build/m4-configure.log" cmake -S "$root" -B "$build/m4" -DCMAKE_TOOLCHAIN_FILE="$root/cmake/arm-none-eabi.cmake" \
  -DCMAKE_BUILD_TYPE=MinSizeRel -DXFGCU_BUILD_TESTS=OFF -DXFGCU_BUILD_TOOLS=OFF -DXFGCU_BUILD_BENCH=OFF \
  "-DXFGCU_MCU_DEFINES=EXAMPLE_PHOTO_MS=2000u;EXAMPLE_INS_ALIGN_MS=4000u"
run "$build/m4-build.log" cmake --build "$build/m4" --target xfgcu_mcu_qemu --parallel 2
if [ -z "$xfgcu" ]; then
  echo "firmware_loop: building the xfgcu program in $build/host"
  run "$build/host-configure.log" cmake -S "$root" -B "$build/host" -DCMAKE_BUILD_TYPE=Release \
    -DXFGCU_BUILD_TESTS=OFF -DXFGCU_BUILD_BENCH=OFF -DXFGCU_BUILD_EXAMPLES=OFF
  run "$build/host-build.log" cmake --build "$build/host" --target xfgcu --parallel 2
  xfgcu=$build/host/tools/xfgcu
fi
exec python3 "$root/tests/firmware/firmware_loop.py" --qemu "$qemu" --xfgcu "$xfgcu" \
  --elf "$build/m4/examples/mcu/xfgcu_mcu_qemu.elf" --log "$build/log"
