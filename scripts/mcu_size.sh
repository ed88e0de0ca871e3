#!/usr/bin/env bash
# Cross builds and their sizes: the Cortex-M4 firmware example (cortex-m4 preset), the codec
# compiled alone with the strict flags of the codec issue, and the RISC-V preset (no C library).
set -euo pipefail
cd "$(dirname "$0")/.."
out=build/mcu
mkdir -p "$out"

flags=(-mcpu=cortex-m4 -mthumb -Os -std=c99 -pedantic-errors -Wall -Wextra -Wconversion -Werror -Iinclude)
arm-none-eabi-gcc "${flags[@]}" -c src/xf_codec.c -o "$out/xf_codec.o"
echo "the codec compiled once for a Cortex-M4 (-Os; every function, before --gc-sections):"
arm-none-eabi-size "$out/xf_codec.o"

# sizeof(xf_parser) and sizeof(xf_client) on the target, read from sized symbols
printf '#include "xfgcu/xf_client.h"\nchar sizeof_xf_parser[sizeof(xf_parser)];\nchar sizeof_xf_client[sizeof(xf_client)];\n' > "$out/sizes.c"
for max in 255 84; do
  arm-none-eabi-gcc "${flags[@]}" -DXF_PACKET_MAX_LEN=$max -c "$out/sizes.c" -o "$out/sizes.o"
  p=$(arm-none-eabi-nm -S "$out/sizes.o" | awk '/sizeof_xf_parser/ {print $2}')
  c=$(arm-none-eabi-nm -S "$out/sizes.o" | awk '/sizeof_xf_client/ {print $2}')
  echo "RAM with XF_PACKET_MAX_LEN=$max: xf_parser $((16#$p)) bytes, xf_client (parser included) $((16#$c)) bytes"
done

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
echo "of which the codec and client (input sections kept from xf_codec.c and xf_client.c):"
python3 - build/cortex-m4/examples/mcu/xfgcu_mcu_demo.map "$elf" <<'PY'
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
print(f"  flash {flash} bytes; RAM {ram} bytes (the one xf_client, parser included)")
PY

echo
# The parser's share: every function and table defined in xf_parser.h, xf_crc.h and
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
parser=0
while read -r _ size _ name; do
  for d in $defined; do
    if [ "${name%%.*}" = "$d" ]; then
      parser=$((parser + 16#$size))
      break
    fi
  done
done < <(arm-none-eabi-nm -S "$elf" | awk 'NF == 4')
echo "of which the parser (its functions and the CRC's, and their tables): $parser bytes"
echo "riscv preset: rv32imac, freestanding, no C library: the client's archive, then the codec's"
cmake --preset riscv >/dev/null
cmake --build --preset riscv >/dev/null
riscv64-unknown-elf-size -t build/riscv/src/libxfgcu_client.a | tail -1
riscv64-unknown-elf-size -t build/riscv/src/libxfgcu_codec.a | tail -1
