#!/usr/bin/env bash
# Install the Debian packages xfgcu needs, if any is missing.
#   scripts/setup.sh            what building, the demo and the tests need
#   scripts/setup.sh --dev      + the test suite's extras (clang, valgrind, cross compilers, and a
#                               big-endian s390x toolchain with its libraries for qemu-user)
set -euo pipefail

pkgs=(build-essential cmake pkg-config libjansson-dev libserialport-dev libpcap-dev python3 python3-venv python3-pip python3-setuptools python3-wheel)
dev=0
if [ "${1:-}" = "--dev" ]; then
  dev=1
  pkgs+=(libcmocka-dev doxygen groff-base clang clang-tidy clang-format cppcheck libclang-rt-14-dev valgrind g++
         gcc-arm-none-eabi libnewlib-arm-none-eabi qemu-system-arm gcc-riscv64-unknown-elf socat
         python3-pytest python3-pytest-xdist python3-hypothesis mypy tshark iproute2
         gcc-s390x-linux-gnu libc6-dev-s390x-cross qemu-user libcmocka-dev:s390x libserialport-dev:s390x)
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
# The big-endian test libraries are Debian's s390x packages, installed side by side (multiarch).
if [ "$dev" = 1 ] && ! dpkg --print-foreign-architectures | grep -qx s390x; then
  "${sudo_cmd[@]}" dpkg --add-architecture s390x
fi
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
