/*
 * app.c - an application of the compiled client and simulator, built by
 * check_options.cmake with the library's options (it must link and init) and
 * with each layout option changed (it must fail to link, naming the option).
 */
#include <stdio.h>
#include "xfgcu/xf_client.h"
#include "xfgcu/xf_sim.h"

static xf_err app_write(void *ctx, const uint8_t *data, size_t len)
{
    (void)ctx;
    (void)data;
    (void)len;
    return XF_OK;
}

static xf_err app_read(void *ctx, uint8_t *buf, size_t cap, size_t *out_len)
{
    (void)ctx;
    (void)buf;
    (void)cap;
    *out_len = 0;
    return XF_OK;
}

int main(void)
{
    static xf_client client;
    static xf_sim sim;
    xf_hal hal = {NULL, app_write, app_read, NULL};
    xf_err c = xf_client_init(&client, &hal, NULL);
    xf_err s = xf_sim_init(&sim, NULL);
    printf("client init: %s; sim init: %s\n", xf_strerror(c), xf_strerror(s));
    return (c == XF_OK && s == XF_OK) ? 0 : 1;
}
