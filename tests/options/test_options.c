/*
 * test_options.c - the run-time half of the build-option check: a caller
 * that reaches the init functions with another option word or struct size
 * (as a foreign-function interface could) gets XF_ERR_CONFIG and its memory
 * is left alone; the library reports its own values.
 */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <string.h>
#include <cmocka.h>
#include "xfgcu/xf_client.h"
#include "xfgcu/xf_sim.h"

static xf_err t_write(void *ctx, const uint8_t *data, size_t len)
{
    (void)ctx;
    (void)data;
    (void)len;
    return XF_OK;
}

static xf_err t_read(void *ctx, uint8_t *buf, size_t cap, size_t *out_len)
{
    (void)ctx;
    (void)buf;
    (void)cap;
    *out_len = 0;
    return XF_OK;
}

/* A client with guard bytes behind it, all set to a canary value. */
typedef struct guarded {
    xf_client c;
    unsigned char guard[4096];
} guarded;

static int untouched(const unsigned char *p, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++) {
        if (p[i] != 0xA5u) {
            return 0;
        }
    }
    return 1;
}

static void test_library_reports_its_options(void **state)
{
    (void)state;
    assert_int_equal(xf_client_size(), sizeof(xf_client));
    assert_int_equal(xf_options_word(), XF_OPTIONS_WORD);
    assert_int_equal(XF_OPTIONS_WORD & 0xFFu, XF_PACKET_MAX_LEN);
    assert_int_equal((XF_OPTIONS_WORD >> 8) & 0x1Fu, XF_PARSER_SLOTS);
    assert_int_equal((XF_OPTIONS_WORD >> 13) & 0x7Fu, XF_CLIENT_QUEUE);
    assert_int_equal((XF_OPTIONS_WORD >> 20) & 0x7Fu, XF_CLIENT_RESULTS);
}

static void test_client_refuses_other_options(void **state)
{
    static guarded g;
    xf_hal hal = {NULL, t_write, t_read, NULL};
    unsigned long other_len = (XF_OPTIONS_WORD & ~0xFFul) | 84ul;
    (void)state;
    memset(&g, 0xA5, sizeof(g));
    /* a caller with a larger struct but another option word, and one with the
     * right word but another size: both refused, nothing written */
    assert_int_equal(xf_client_init_checked(&g.c, &hal, NULL, other_len, sizeof(xf_client)), XF_ERR_CONFIG);
    assert_int_equal(xf_client_init_checked(&g.c, &hal, NULL, XF_OPTIONS_WORD, sizeof(xf_client) - 1u), XF_ERR_CONFIG);
    assert_int_equal(xf_client_init_checked(&g.c, &hal, NULL, XF_OPTIONS_WORD ^ (1ul << 8), sizeof(xf_client)),
                     XF_ERR_CONFIG);
    assert_true(untouched((const unsigned char *)&g, sizeof(g)));
    /* the macro passes this file's values, which are the library's */
    assert_int_equal(xf_client_init(&g.c, &hal, NULL), XF_OK);
    assert_true(untouched(g.guard, sizeof(g.guard)));
    assert_string_equal(xf_strerror(XF_ERR_CONFIG),
                        "library built with other options (XF_PACKET_MAX_LEN, XF_PARSER_SLOTS, XF_CLIENT_QUEUE, "
                        "XF_CLIENT_RESULTS)");
}

static void test_sim_refuses_other_options(void **state)
{
    static xf_sim s;
    (void)state;
    memset(&s, 0xA5, sizeof(s));
    assert_int_equal(xf_sim_init_checked(&s, NULL, XF_OPTIONS_WORD + 1ul, sizeof(xf_sim)), XF_ERR_CONFIG);
    assert_int_equal(xf_sim_init_checked(&s, NULL, XF_OPTIONS_WORD, sizeof(xf_sim) + 8u), XF_ERR_CONFIG);
    assert_true(untouched((const unsigned char *)&s, sizeof(s)));
    assert_int_equal(xf_sim_init(&s, NULL), XF_OK);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_library_reports_its_options),
        cmocka_unit_test(test_client_refuses_other_options),
        cmocka_unit_test(test_sim_refuses_other_options),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
