/*
 * encode.h - a named command (built by cmdargs) as the packet `xfgcu encode COMMAND` prints: one
 * function for the program and the Python package, so both build the same bytes.
 */
#ifndef XFGCU_ENCODE_H
#define XFGCU_ENCODE_H

#include <stddef.h>
#include <stdint.h>

#include "cmdargs.h"
#include "text_err.h"

/**
 * Build the host packet of command @p cmd (of @p spec, built for protocol @p version) with no
 * carrier data: bytes 5-68 zero except sub_request = 0x01. An osd built from --show / --hide
 * gets @p version's value. Writes the packet into @p out (capacity @p cap, at least
 * XF_PACKET_MAX_LEN) and its length into *@p len.
 * @return TEXT_OK, or TEXT_BAD with @p e saying why.
 */
int encode_command(const cmd_spec *spec, const xf_command *cmd, uint8_t version, uint8_t *out, size_t cap, size_t *len,
                   text_err *e);

#endif /* XFGCU_ENCODE_H */
