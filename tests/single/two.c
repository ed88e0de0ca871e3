/* two.c - the second translation unit of the single-definition check (one.c says why). */
#include "xfgcu/xfgcu.h"

size_t two_frames(const uint8_t *data, size_t len);

size_t two_frames(const uint8_t *data, size_t len)
{
    xf_parser p;
    xf_frame f;
    xf_host_packet pkt;
    size_t used = 0, n = 0, frames = 0;
    if (xf_parser_init(&p, XF_DIR_HOST) != XF_OK) {
        return 0;
    }
    while (used < len && xf_parser_feed(&p, data + used, len - used, &n, &f) == XF_PARSE_FRAME) {
        used += n;
        frames += (xf_frame_host(&f, &pkt) == XF_OK && xf_host_pack(&pkt, NULL, 0, &n) == XF_ERR_ARG) ? 1u : 0u;
    }
    return frames;
}
