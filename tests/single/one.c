/*
 * one.c, two.c - a program of two translation units that both use the
 * parser and the packers. check_single.cmake counts, with nm, the copies of
 * every codec table and function in it: one each, whether the codec comes
 * from the library or from one.c defining XF_IMPLEMENTATION (ONE_IS_IMPL).
 */
#ifdef ONE_IS_IMPL
#define XF_IMPLEMENTATION
#endif
#include <stdio.h>
#include "xfgcu/xfgcu.h"

size_t two_frames(const uint8_t *data, size_t len);
size_t one_frames(const uint8_t *data, size_t len);

size_t one_frames(const uint8_t *data, size_t len)
{
    xf_parser p;
    xf_frame f;
    size_t used = 0, n = 0, frames = 0;
    if (xf_parser_init(&p, XF_DIR_HOST) != XF_OK) {
        return 0;
    }
    while (used < len && xf_parser_feed(&p, data + used, len - used, &n, &f) == XF_PARSE_FRAME) {
        used += n;
        frames++;
    }
    return frames;
}

int main(void)
{
    uint8_t buf[2 * XF_PACKET_MAX_LEN];
    size_t len = 0, n = 0;
    xf_host_packet pkt;
    xf_command cmd;
    xf_host_packet_init(&pkt, XF_PROTOCOL_V1);
    xf_command_init(&cmd, XF_ORDER_SHUTTER);
    if (xf_host_set_command(&pkt, &cmd, NULL) != XF_OK || xf_host_pack(&pkt, buf, sizeof(buf), &n) != XF_OK) {
        return 1;
    }
    len = n;
    if (xf_host_pack(&pkt, buf + len, sizeof(buf) - len, &n) != XF_OK) {
        return 1;
    }
    len += n;
    printf("frames: %zu + %zu (%s)\n", one_frames(buf, len), two_frames(buf, len), xf_order_name(XF_ORDER_SHUTTER));
    return (one_frames(buf, len) == 2u && two_frames(buf, len) == 2u) ? 0 : 1;
}
