/*
 * encode.h - a named command ("zoom-to --rate 5.5", parsed by cmdargs) as
 * the packet `xfgcu encode COMMAND` prints: shared by encode and the
 * Python package's native library (python/native), so both build the
 * same bytes.
 */
#ifndef XFGCU_ENCODE_H
#define XFGCU_ENCODE_H

#include <stddef.h>
#include <stdint.h>

#include "cmdargs.h"

/**
 * Build the host packet of command @p cmd (of @p spec, parsed for protocol
 * @p version) with no carrier data: bytes 5-68 zero except sub_request =
 * 0x01. An osd parsed from --show / --hide gets @p version's value. Writes
 * the packet into @p out (capacity @p cap, at least XF_PACKET_MAX_LEN) and
 * its length into *@p len. Prints any error. @return an exit code.
 */
int encode_command(const cmd_spec *spec, const xf_command *cmd, uint8_t version, uint8_t *out, size_t cap, size_t *len);

#endif /* XFGCU_ENCODE_H */
