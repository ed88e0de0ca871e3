/*
 * test_c99.c - the public header compiles as strict ISO C99
 * (-std=c99 -pedantic-errors, no extensions), and a few basic calls work.
 * No cmocka here: only the library's own header may be under test.
 */
#include <stdio.h>
#include "xfgcu/xfgcu.h"

int main(void)
{
    static const unsigned char check[9] = {'1', '2', '3', '4', '5', '6', '7', '8', '9'};
    xf_host_packet pkt;
    unsigned char buf[XF_PACKET_MAX_LEN];
    size_t n = 0;
    int failures = 0;

    if (xf_crc16(check, sizeof(check)) != 0x31C3u) {
        fprintf(stderr, "CRC check value wrong\n");
        failures++;
    }
    xf_host_packet_init(&pkt, XF_PROTOCOL_V1);
    if (xf_host_pack(&pkt, buf, sizeof(buf), &n) != XF_OK || n != 72u ||
        xf_packet_check(buf, n, XF_DIR_HOST) != XF_OK) {
        fprintf(stderr, "pack / check failed\n");
        failures++;
    }
    if (xf_order_at(XF_ORDER_COUNT - 1u) == NULL || xf_order_at(XF_ORDER_COUNT) != NULL) {
        fprintf(stderr, "order table\n");
        failures++;
    }
    return failures == 0 ? 0 : 1;
}
