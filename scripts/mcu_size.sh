#!/usr/bin/env bash
# Cross builds and their sizes: the Cortex-M4 firmware example (cortex-m4 preset), the codec
# compiled alone with the strict flags of the codec issue, the parser linked alone with each CRC
# table, and the RISC-V preset (no C library).
#
# Failing gates (exit 1 when one is exceeded), all Cortex-M4 -Os:
#   parser + CRC, linked alone: <= 1536 bytes with the 16-entry table, <= 2048 with the 256-entry one
#   sizeof(xf_parser) at the default XF_PACKET_MAX_LEN (255): <= 300 bytes
#   codec + client in the firmware example: <= 8192 bytes of flash, <= 512 bytes of RAM per gimbal
# The figures also go to build/mcu/results.txt (`name value` lines) for scripts/perf_page.py.
set -euo pipefail
cd "$(dirname "$0")/.."
out=build/mcu
mkdir -p "$out"
results="$out/results.txt"
: >"$results"
echo "commit $(git rev-parse --short HEAD)$(git diff --quiet HEAD -- include src examples || echo +changes)" >>"$results"
over=()
# gate VALUE LIMIT WHAT: check a figure against its limit
gate() {
  if [ "$1" -le "$2" ]; then
    echo "  $3: $1 bytes (target <= $2): ok"
  else
    echo "  $3: $1 bytes (target <= $2): OVER"
    over+=("$3")
  fi
}
# figure NAME: a figure recorded above
figure() { awk -v n="$1" '$1 == n {print $2}' "$results"; }

flags=(-mcpu=cortex-m4 -mthumb -Os -std=c99 -pedantic-errors -Wall -Wextra -Wconversion -Werror -Iinclude)
arm-none-eabi-gcc "${flags[@]}" -c src/xf_codec.c -o "$out/xf_codec.o"
echo "the codec compiled once for a Cortex-M4 (-Os; every function, before --gc-sections):"
arm-none-eabi-size "$out/xf_codec.o"
echo "codec_text $(arm-none-eabi-size "$out/xf_codec.o" | awk 'NR == 2 {print $1}')" >>"$results"

# sizeof(xf_parser) and sizeof(xf_client) on the target, read from sized symbols
printf '#include "xfgcu/xf_client.h"\nchar sizeof_xf_parser[sizeof(xf_parser)];\nchar sizeof_xf_client[sizeof(xf_client)];\n' > "$out/sizes.c"
for max in 255 84; do
  arm-none-eabi-gcc "${flags[@]}" -DXF_PACKET_MAX_LEN=$max -c "$out/sizes.c" -o "$out/sizes.o"
  p=$(arm-none-eabi-nm -S "$out/sizes.o" | awk '/sizeof_xf_parser/ {print $2}')
  c=$(arm-none-eabi-nm -S "$out/sizes.o" | awk '/sizeof_xf_client/ {print $2}')
  echo "RAM with XF_PACKET_MAX_LEN=$max: xf_parser $((16#$p)) bytes, xf_client (parser included) $((16#$c)) bytes"
  echo "parser_state_$max $((16#$p))" >>"$results"
  echo "client_state_$max $((16#$c))" >>"$results"
done

# The parser's share of an image: every function and table defined in xf_parser.h, xf_crc.h and
# xf_crc_tables.h, as linked (a compiler's clones, name.constprop.0 and the like, included),
# from the symbol sizes. The names come from the headers, so a new helper is never missed.
defined=$(python3 - include/xfgcu/xf_parser.h include/xfgcu/xf_crc.h include/xfgcu/xf_crc_tables.h <<'PY'
import re, sys
names = set()
for path in sys.argv[1:]:
    # any line at file level (not indented, a comment or a directive) that names an xf_
    # function or table, whatever precedes the name (static, XF_API, an attribute ...)
    for m in re.finditer(r"^(?![#/ *\t}])(?:[^;{=(]|\(\([^)]*\)\))*?\b(xf_\w+)\s*[(\[]", open(path).read(), re.M):
        names.add(m.group(1))
print(" ".join(sorted(names)))
PY
)
parser_bytes() { # ELF: the sizes of the parser's symbols kept in it
  local n=0 size name
  while read -r _ size _ name; do
    for d in $defined; do
      if [ "${name%%.*}" = "$d" ]; then
        n=$((n + 16#$size))
        break
      fi
    done
  done < <(arm-none-eabi-nm -S "$1" | awk 'NF == 4')
  echo "$n"
}

# The parser alone: a stub that initialises a parser, feeds it, resets and flushes it, linked
# with the codec's translation unit (src/xf_codec.c, so that nothing is inlined into the stub)
# and --gc-sections (newlib-nano: memcpy, memmove, memchr and memset are the C library's, as in
# any firmware, and not counted).
cat > "$out/parser_stub.c" <<'EOF'
#include "xfgcu/xf_parser.h"
int main(void);
xf_parser stub_parser;
volatile uint8_t stub_rx[64];
int main(void)
{
    uint8_t chunk[64];
    size_t i, used = 0;
    xf_frame f;
    int frames = 0;
    for (i = 0; i < sizeof(chunk); i++) {
        chunk[i] = stub_rx[i];
    }
    if (xf_parser_init(&stub_parser, XF_DIR_GCU) != XF_OK) {
        return 1;
    }
    frames += xf_parser_feed(&stub_parser, chunk, 1, &used, &f) == XF_PARSE_FRAME;
    frames += xf_parser_feed(&stub_parser, chunk, sizeof(chunk), &used, &f) == XF_PARSE_FRAME;
    xf_parser_reset(&stub_parser);
    frames += xf_parser_flush(&stub_parser, &f) == XF_PARSE_FRAME;
    return frames + (int)xf_parser_pending(&stub_parser);
}
EOF
echo
echo "the parser and the CRC linked alone (a stub that feeds them, -Os, --gc-sections):"
for t in 0 1; do
  arm-none-eabi-gcc "${flags[@]}" -DXF_CRC_TABLE_256=$t -ffunction-sections -fdata-sections \
    -Wl,--gc-sections --specs=nano.specs --specs=nosys.specs "$out/parser_stub.c" src/xf_codec.c \
    -o "$out/parser_stub$t.elf"
done
echo "parser_flash_nibble $(parser_bytes "$out/parser_stub0.elf")" >>"$results"
echo "parser_flash_t256 $(parser_bytes "$out/parser_stub1.elf")" >>"$results"

echo
echo "cortex-m4 preset: firmware example (client at 50 Hz over a UART interrupt HAL, -Os, --gc-sections)"
cmake --preset cortex-m4 >/dev/null
cmake --build --preset cortex-m4 >/dev/null
elf=build/cortex-m4/examples/mcu/xfgcu_mcu_demo.elf
arm-none-eabi-size "$elf"
# The field table (xf_fields.h: rows, their texts and bits, and its functions) is in the codec's
# object, and not in a firmware that never references it: --gc-sections leaves none of it.
table='xf_wire_|xf__wire_|xf__wf_|xf__wb_|xf__bits_'
in_codec=$(arm-none-eabi-nm "$out/xf_codec.o" | grep -cE " ($table)" || true)
in_elf=$(arm-none-eabi-nm "$elf" | grep -cE " ($table)" || true)
echo "the field table: $in_codec symbols in the codec's object, $in_elf in the firmware"
if [ "$in_codec" -eq 0 ] || [ "$in_elf" -ne 0 ]; then
  echo "mcu_size.sh: the firmware links the field table (or the check finds no table to look for)" >&2
  arm-none-eabi-nm "$elf" | grep -E " ($table)" >&2 || true
  exit 1
fi
read -r fw_text fw_bss < <(arm-none-eabi-size "$elf" | awk 'NR == 2 {print $1, $3}')
echo "firmware_text $fw_text" >>"$results"
echo "firmware_bss $fw_bss" >>"$results"
echo "of which the codec and client (input sections kept from xf_codec.c and xf_client.c):"
read -r fw_flash fw_ram < <(python3 - build/cortex-m4/examples/mcu/xfgcu_mcu_demo.map "$elf" <<'PY'
import re, subprocess, sys
flash = 0
in_map = False
pending = None
for line in open(sys.argv[1]):
    if line.startswith("Linker script and memory map"):
        in_map = True  # before it: the sections --gc-sections discarded
        continue
    if not in_map:
        continue
    m = re.match(r"^ (\.(?:text|rodata|data)\S*)\s*$", line)
    if m:
        pending = m.group(1)
        continue
    m = re.match(r"^ (\.(?:text|rodata|data)\S*)?\s+0x[0-9a-f]+\s+0x([0-9a-f]+)\s+(\S+\.obj)", line)
    if m and (m.group(1) or pending) and re.search(r"xf_(client|codec|options)\.c\.obj", m.group(3)):
        flash += int(m.group(2), 16)
    pending = None
nm = subprocess.run(["arm-none-eabi-nm", "-S", sys.argv[2]], capture_output=True, text=True).stdout
ram = sum(int(l.split()[1], 16) for l in nm.splitlines() if l.endswith(" g_gimbal"))
print(flash, ram)
PY
)
echo "  flash $fw_flash bytes; RAM $fw_ram bytes (the one xf_client, parser included)"
fw_parser=$(parser_bytes "$elf")
echo "of which the parser (its functions and the CRC's, and their tables): $fw_parser bytes"
echo "firmware_parser_flash $fw_parser" >>"$results"
echo "firmware_flash $fw_flash" >>"$results"
echo "firmware_ram $fw_ram" >>"$results"

echo
echo "riscv preset: rv32imac, freestanding, no C library: the client's archive, then the codec's"
cmake --preset riscv >/dev/null
cmake --build --preset riscv >/dev/null
riscv64-unknown-elf-size -t build/riscv/src/libxfgcu_client.a | tail -1
riscv64-unknown-elf-size -t build/riscv/src/libxfgcu_codec.a | tail -1
echo "riscv_client_text $(riscv64-unknown-elf-size -t build/riscv/src/libxfgcu_client.a | awk 'END {print $1}')" >>"$results"
echo "riscv_codec_text $(riscv64-unknown-elf-size -t build/riscv/src/libxfgcu_codec.a | awk 'END {print $1}')" >>"$results"

echo
echo "targets (failing gates):"
gate "$(figure parser_flash_nibble)" 1536 "parser + CRC, 16-entry table, linked alone"
gate "$(figure parser_flash_t256)" 2048 "parser + CRC, 256-entry table, linked alone"
gate "$(figure parser_state_255)" 300 "sizeof(xf_parser), XF_PACKET_MAX_LEN=255"
gate "$fw_flash" 8192 "codec + client flash, firmware example"
gate "$fw_ram" 512 "codec + client RAM per gimbal, firmware example"
if [ ${#over[@]} -gt 0 ]; then
  echo "mcu_size.sh: over target: ${over[*]}" >&2
  exit 1
fi
