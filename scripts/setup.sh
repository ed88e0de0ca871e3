#!/usr/bin/env bash
# Install the Debian packages xfgcu needs, if any is missing.
#   scripts/setup.sh            what building, the demo and the tests need
#   scripts/setup.sh --dev      + the test suite's extras (clang, valgrind, cross compilers)
set -euo pipefail

pkgs=(build-essential cmake pkg-config libjansson-dev libserialport-dev)
if [ "${1:-}" = "--dev" ]; then
  pkgs+=(libcmocka-dev clang libclang-rt-14-dev valgrind gcc-arm-none-eabi libnewlib-arm-none-eabi gcc-riscv64-unknown-elf socat)
fi

missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "setup: installing ${missing[*]}"
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then sudo_cmd=(sudo); else
    echo "setup: need root (or sudo) to apt-get install: ${missing[*]}" >&2; exit 1
  fi
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
