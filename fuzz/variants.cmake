# The fuzz harnesses and the build variants each is compiled in; included by fuzz/CMakeLists.txt
# (the libFuzzer binaries) and fuzz/replay.cmake (the ctest replay of the saved inputs).
#
#   (no suffix)  the default options
#   _alt         the 256-entry CRC table, the smallest ring an MCU may configure
#                (XF_PACKET_MAX_LEN=84), and the codec's own memcpy/memset/memchr loops
#   _slots1      one candidate at a time (XF_PARSER_SLOTS=1): given up most often
#
# Each harness is the codec's implementation translation unit (it defines XF_IMPLEMENTATION) and
# checks the codec's internal invariants (fuzz_common.h defines XF_ASSERT).
set(XFGCU_FUZZ_HARNESSES fuzz_parser_raw fuzz_parser_crcfix)
set(XFGCU_FUZZ_VARIANTS default alt slots1)
set(XFGCU_FUZZ_SUFFIX_default "")
set(XFGCU_FUZZ_DEFS_default "")
set(XFGCU_FUZZ_SUFFIX_alt _alt)
set(XFGCU_FUZZ_DEFS_alt XF_CRC_TABLE_256=1 XF_PACKET_MAX_LEN=84 XF_NO_LIBC=1)
set(XFGCU_FUZZ_SUFFIX_slots1 _slots1)
set(XFGCU_FUZZ_DEFS_slots1 XF_PARSER_SLOTS=1)
