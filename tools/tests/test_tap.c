/*
 * test_tap.c - the program's tap (tools/xfgcu/tap.h), a link that reports
 * every chunk it moves, stamped with its own clock: around a client's link,
 * against the simulator over the in-memory link and fake clock of the
 * client's tests (tests/client/client_test.h).
 */
#include "client_test.h"
#include "tap.h"

typedef struct tap_seen {
    ct_rig *r;
    size_t host, gcu, clock_calls, wrong_time;
} tap_seen;

static uint32_t tap_clock(void *user)
{
    tap_seen *s = (tap_seen *)user;
    s->clock_calls++;
    return s->r->now + 7u; /* not the client's time: the stamps must come from here */
}

static void tap_chunk(void *user, xf_direction dir, const uint8_t *data, size_t len, uint32_t now_ms)
{
    tap_seen *s = (tap_seen *)user;
    (void)data;
    assert_true(len > 0u);
    if (dir == XF_DIR_HOST) {
        s->host++;
    } else {
        s->gcu++;
    }
    s->wrong_time += (now_ms != s->r->now + 7u);
}

static void test_tap_own_clock(void **state)
{
    ct_rig *r = ct_rig_new(NULL, NULL);
    xf_client_config cc = r->c.cfg;
    xf_tap tap;
    xf_hal tapped;
    tap_seen seen;
    (void)state;
    memset(&seen, 0, sizeof(seen));
    seen.r = r;
    xf_tap_init(&tap, &r->host_hal, tap_chunk, tap_clock, &seen, &tapped);
    assert_xf(xf_hal_check(&tapped), XF_OK);
    assert_int_equal(xf_hal_fd(&tapped), -1);
    assert_xf(xf_client_init(&r->c, &tapped, &cc), XF_OK);
    assert_true(ct_run_link(r, XF_LINK_UP, 1000));
    ct_run(r, 100);
    assert_true(seen.host >= 5u && seen.gcu >= 5u);
    assert_int_equal(seen.clock_calls, seen.host + seen.gcu);
    assert_int_equal(seen.wrong_time, 0);
    assert_int_equal(seen.host, r->c.health.packets_sent);
    ct_rig_free(r);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_tap_own_clock),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
