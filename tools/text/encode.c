/*
 * encode.c - a named command as its packet (encode.h).
 */
#include "encode.h"

int encode_command(const cmd_spec *spec, const xf_command *command, uint8_t version, uint8_t *out, size_t cap,
                   size_t *len, text_err *e)
{
    xf_host_packet pkt;
    xf_command cmd = *command;
    xf_field bad = XF_F_NONE;
    xf_err err;
    cmdargs_for_version(&cmd, version); /* --protocol N: N's meaning */
    xf_host_packet_init(&pkt, version); /* no carrier data; sub_request = 0x01 */
    err = xf_host_set_command(&pkt, &cmd, &bad);
    if (err == XF_OK) {
        err = xf_host_pack(&pkt, out, cap, len);
    }
    if (err != XF_OK) {
        return text_fail(e, "encode", "%s: %s%s%s", spec->name, xf_strerror(err), bad != XF_F_NONE ? ": " : "",
                         bad != XF_F_NONE ? xf_field_name(bad) : "");
    }
    return TEXT_OK;
}
