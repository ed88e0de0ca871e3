/*
 * fuzz_parser_raw - raw bytes into the streaming parser, both directions.
 *
 * Input layout:
 *   byte 0          k = (byte & 7) + 1: number of chunk sizes that follow;
 *                   bit 3: end the input with xf_parser_reset() instead of
 *                   xf_parser_flush()
 *   bytes 1..k      chunk sizes, cycled: 0 = empty feed, 255 = the rest
 *   the rest        the stream
 * Inputs shorter than k + 1 bytes are fed whole.
 *
 * Checks (fuzz_common.h): after every call of xf_parser_feed, and when the
 * input ends, every counter and every frame equal the reference model's
 * (tests/parser_ref.h), each frame returned by the call that feeds its last
 * byte, plus the parser's own invariants (XF_ASSERT) and frame decode/encode
 * round trips; on the raw stream itself, unpack == xf_packet_check for both
 * directions and pack(unpack(x)) == x, plus command / feedback decoding of
 * arbitrary parameter bytes.
 */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include "fuzz_common.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const uint8_t *stream = data;
    size_t n = size;
    const uint8_t *sizes = NULL;
    size_t nsizes = 0;
    pr_frame *frames;
    fz_plan plan;
    fz_result res;
    int d, end = FZ_END_FLUSH;

    if (size > 0u) {
        nsizes = (size_t)(data[0] & 7u) + 1u;
        end = (data[0] & 8u) ? FZ_END_RESET : FZ_END_FLUSH;
        if (size > nsizes) {
            sizes = data + 1;
            stream = data + 1 + nsizes;
            n = size - 1u - nsizes;
        } else {
            nsizes = 0;
        }
    }

    frames = (pr_frame *)malloc((n / XF_PACKET_MIN_LEN + 1u) * sizeof(pr_frame));
    FZ_CHECK(frames != NULL);
    for (d = 0; d < 2; d++) {
        xf_direction dir = (d == 0) ? XF_DIR_GCU : XF_DIR_HOST;
        fz_plan_init(&plan, sizes, nsizes);
        fz_feed_checked(stream, n, dir, &plan, end, frames, &res);
    }
    free(frames);

    /* The decoders on the raw bytes: whole stream, and the whole input. */
    fz_check_buffer(stream, n);
    if (n != size) {
        fz_check_buffer(data, size);
    }
    /* The command and feedback decoders on arbitrary bytes. */
    if (n >= 2u) {
        size_t plen = (size_t)(stream[1] % 16u);
        if (plen > n - 2u) {
            plen = n - 2u;
        }
        fz_check_order(stream[0], stream + 2, plen, (uint8_t)(stream[1] >> 4));
    }
    return 0;
}
