#!/usr/bin/env bash
# Compile the codec for a Cortex-M4 (as one TU, XF_SEPARATE_IMPLEMENTATION, and header-only)
# with the strict flags, and print its size. Fails on any warning.
set -euo pipefail
cd "$(dirname "$0")/.."
out=build/mcu
mkdir -p "$out"
flags=(-mcpu=cortex-m4 -mthumb -Os -std=c99 -pedantic-errors -Wall -Wextra -Wconversion -Wshadow -Wundef -Werror
       -ffunction-sections -fdata-sections -Iinclude)
arm-none-eabi-gcc "${flags[@]}" -c src/xf_codec.c -o "$out/xf_codec.o"
arm-none-eabi-gcc "${flags[@]}" -mfloat-abi=hard -mfpu=fpv4-sp-d16 -c src/xf_codec.c -o "$out/xf_codec_hf.o"
arm-none-eabi-gcc "${flags[@]}" -DXF_CRC_TABLE_256=1 -c src/xf_codec.c -o "$out/xf_codec_crc256.o"
arm-none-eabi-gcc "${flags[@]}" -DXF_PACKET_MAX_LEN=84 -c src/xf_codec.c -o "$out/xf_codec_max84.o"
# header-only use from an ordinary TU
printf '#include "xfgcu/xfgcu.h"\nint xf_mcu_probe(const uint8_t *b, size_t n);\nint xf_mcu_probe(const uint8_t *b, size_t n) { return (int)xf_packet_check(b, n, XF_DIR_GCU); }\n' > "$out/probe.c"
arm-none-eabi-gcc "${flags[@]}" -c "$out/probe.c" -o "$out/probe.o"
echo "codec for Cortex-M4 (-Os, whole codec incl. unit helpers; a firmware links only what it calls):"
arm-none-eabi-size "$out/xf_codec.o" "$out/xf_codec_hf.o" "$out/xf_codec_crc256.o" "$out/xf_codec_max84.o"
# sizeof(xf_parser) on the target: the size of a sized symbol, read from the object file
printf '#include "xfgcu/xfgcu.h"\nchar xf_parser_size_probe[sizeof(xf_parser)];\n' > "$out/parser_size.c"
for max in 255 84; do
  arm-none-eabi-gcc "${flags[@]}" -DXF_PACKET_MAX_LEN=$max -c "$out/parser_size.c" -o "$out/parser_size.o"
  hex=$(arm-none-eabi-nm -S "$out/parser_size.o" | awk '/xf_parser_size_probe/ {print $2}')
  echo "RAM of one xf_parser with XF_PACKET_MAX_LEN=$max: $((16#$hex)) bytes"
done
