/*
 * xf_client_bench.c - figures for the client and simulator:
 *
 *   xfgcu_client_bench latency [N]   reply-to-callback latency percentiles on
 *                                    loopback UDP, TCP and a pty (N replies each)
 *   xfgcu_client_bench cpu [SECONDS] CPU of one thread driving 1 and 64 clients
 *                                    at 50 Hz (simulators run on another thread)
 *   xfgcu_client_bench alloc         heap allocations of clients and simulators
 *                                    in steady state; exits 1 if any (a test)
 *
 * Latency is measured from the simulator's write() of a reply (its thread)
 * to the client's telemetry callback (the main thread, woken by poll()):
 * the path a real application sees, with no sleep in it.
 */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "xfgcu/xf_client.h"
#include "xfgcu/posix/xf_posix.h"
#include "xfgcu/posix/xf_simlink.h"
#include "xfgcu/posix/xf_poll.h"
#include "xfgcu/xf_sim.h"

/* ---- counting the heap ------------------------------------------------------------- */

static atomic_long g_allocs;
static atomic_int g_counting;
extern void *__libc_malloc(size_t);
extern void *__libc_calloc(size_t, size_t);
extern void *__libc_realloc(void *, size_t);
extern void __libc_free(void *);

void *malloc(size_t n)
{
    if (atomic_load(&g_counting)) {
        atomic_fetch_add(&g_allocs, 1);
    }
    return __libc_malloc(n);
}
void *calloc(size_t a, size_t b)
{
    if (atomic_load(&g_counting)) {
        atomic_fetch_add(&g_allocs, 1);
    }
    return __libc_calloc(a, b);
}
void *realloc(void *p, size_t n)
{
    if (atomic_load(&g_counting)) {
        atomic_fetch_add(&g_allocs, 1);
    }
    return __libc_realloc(p, n);
}
void free(void *p) { __libc_free(p); }

/* ---- time ---------------------------------------------------------------------------- */

static uint64_t now_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (uint64_t)ts.tv_sec * 1000000000u + (uint64_t)ts.tv_nsec;
}

static double thread_cpu_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec / 1e9;
}

/* ---- a simulator thread ------------------------------------------------------------------ */

#define MAX_G 64

typedef struct sim_side {
    xf_simlink link[MAX_G];
    xf_sim sim[MAX_G];
    xf_hal inner[MAX_G];
    size_t n;
    atomic_int stop;
    /* latency: when each reply was written (one gimbal) */
    uint64_t *written;
    size_t n_written, cap_written;
} sim_side;

/* The simulator's link, stamped just BEFORE each reply is written: the
 * client's thread may run its callback before write() even returns. */
static sim_side *g_stamp_side;

static xf_err stamped_write(void *ctx, const uint8_t *d, size_t len)
{
    xf_hal *inner = (xf_hal *)ctx;
    sim_side *s = g_stamp_side;
    if (s != NULL && s->written != NULL && s->n_written < s->cap_written && inner == &s->inner[0]) {
        s->written[s->n_written++] = now_ns();
    }
    return inner->write(inner->ctx, d, len);
}

static xf_err pass_read(void *ctx, uint8_t *b, size_t cap, size_t *n)
{
    xf_hal *inner = (xf_hal *)ctx;
    return inner->read(inner->ctx, b, cap, n);
}

static int pass_fd(void *ctx) { return xf_hal_fd((xf_hal *)ctx); }

static void *sim_thread(void *arg)
{
    sim_side *s = (sim_side *)arg;
    xf_sim *ptr[MAX_G];
    size_t i;
    for (i = 0; i < s->n; i++) {
        ptr[i] = &s->sim[i];
    }
    while (!atomic_load(&s->stop)) {
        xf_posix_poll(NULL, 0, ptr, s->n, 2);
    }
    return NULL;
}

static int sim_open(sim_side *s, size_t i, int kind, const char *pty_link)
{
    xf_hal stamped;
    xf_err e = (kind == XF_SIMLINK_UDP)   ? xf_simlink_open_udp(&s->link[i], "127.0.0.1", 0)
               : (kind == XF_SIMLINK_TCP) ? xf_simlink_open_tcp(&s->link[i], "127.0.0.1", 0)
                                          : xf_simlink_open_pty(&s->link[i], pty_link);
    if (e != XF_OK) {
        fprintf(stderr, "xfgcu_client_bench: %s\n", s->link[i].error.text);
        return -1;
    }
    xf_simlink_hal(&s->link[i], &s->inner[i]);
    stamped.ctx = &s->inner[i];
    stamped.write = stamped_write;
    stamped.read = pass_read;
    stamped.fd = pass_fd;
    g_stamp_side = s;
    xf_sim_init(&s->sim[i], NULL);
    xf_sim_attach(&s->sim[i], &stamped);
    return 0;
}

/* ---- the host side ---------------------------------------------------------------------- */

typedef struct host_side {
    xf_client client[MAX_G];
    xf_udp udp[MAX_G];
    xf_tcp tcp[MAX_G];
    xf_serial serial;
    uint64_t *called;
    size_t n_called, cap_called;
} host_side;

static void on_tele(void *user, const xf_telemetry *t)
{
    host_side *h = (host_side *)user;
    (void)t;
    if (h->called != NULL && h->n_called < h->cap_called) {
        h->called[h->n_called++] = now_ns();
    }
}

static int host_open(host_side *h, size_t i, int kind, const sim_side *s, const char *pty_link, uint16_t rate)
{
    xf_hal hal;
    xf_client_config cc;
    xf_err e;
    if (kind == XF_SIMLINK_UDP) {
        xf_udp_config uc;
        xf_udp_config_init(&uc);
        uc.gcu_host = "127.0.0.1";
        uc.gcu_port = s->link[i].port;
        uc.local_port = 0;
        e = xf_udp_open(&h->udp[i], &uc);
        xf_udp_hal(&h->udp[i], &hal);
    } else if (kind == XF_SIMLINK_TCP) {
        xf_tcp_config tc;
        xf_tcp_config_init(&tc);
        tc.host = "127.0.0.1";
        tc.port = s->link[i].port;
        e = xf_tcp_open(&h->tcp[i], &tc);
        xf_tcp_hal(&h->tcp[i], &hal);
    } else {
        e = xf_serial_open(&h->serial, pty_link, 115200);
        xf_serial_hal(&h->serial, &hal);
    }
    if (e != XF_OK) {
        fprintf(stderr, "xfgcu_client_bench: cannot open the host link (%s)\n", xf_strerror(e));
        return -1;
    }
    xf_client_config_init(&cc);
    cc.rate_hz = rate;
    cc.reorder_fixed = 1; /* loopback keeps order: no bound where a loaded machine bunches replies */
    cc.on_telemetry = on_tele;
    cc.user = h;
    return xf_client_init(&h->client[i], &hal, &cc) < 0 ? -1 : 0;
}

static void drive(host_side *h, size_t n, uint32_t ms)
{
    xf_client *ptr[MAX_G];
    size_t i;
    uint32_t start = xf_posix_now_ms();
    for (i = 0; i < n; i++) {
        ptr[i] = &h->client[i];
    }
    while (xf_ms_since(xf_posix_now_ms(), start) < ms) {
        xf_posix_poll(ptr, n, NULL, 0, 50);
    }
}

static int cmp_u64(const void *a, const void *b)
{
    uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return (x > y) - (x < y);
}

/* ---- modes --------------------------------------------------------------------------------- */

static int bench_latency(size_t n)
{
    static const char *names[3] = {"pty", "udp", "tcp"};
    static sim_side s;
    static host_side h;
    char pty_link[64];
    int kind;
    printf("reply-to-callback latency, %zu replies per link at 200 Hz (microseconds)\n", n);
    printf("%-5s %8s %8s %8s %8s %8s\n", "link", "p50", "p90", "p99", "max", "samples");
    snprintf(pty_link, sizeof(pty_link), "/tmp/xfgcu-bench-%d", (int)getpid());
    for (kind = 0; kind < 3; kind++) {
        pthread_t th;
        uint64_t *lat;
        size_t i, j, m;
        memset(&s, 0, sizeof(s));
        memset(&h, 0, sizeof(h));
        s.n = 1;
        if (sim_open(&s, 0, kind, pty_link) != 0 || host_open(&h, 0, kind, &s, pty_link, 200) != 0) {
            return 3;
        }
        drive(&h, 1, 300); /* connect, settle */
        s.cap_written = h.cap_called = n + 64;
        s.written = calloc(s.cap_written, sizeof(uint64_t));
        h.called = calloc(h.cap_called, sizeof(uint64_t));
        pthread_create(&th, NULL, sim_thread, &s);
        drive(&h, 1, (uint32_t)(n * 5u + 300u));
        atomic_store(&s.stop, 1);
        pthread_join(th, NULL);
        /* Question and answer: one reply in flight, so each callback
         * belongs to the last reply written before it. */
        lat = calloc(h.n_called > 0 ? h.n_called : 1, sizeof(uint64_t));
        m = 0;
        for (i = 0, j = 0; i < h.n_called; i++) {
            while (j + 1 < s.n_written && s.written[j + 1] <= h.called[i]) {
                j++;
            }
            if (j < s.n_written && s.written[j] <= h.called[i]) {
                lat[m++] = h.called[i] - s.written[j];
            }
        }
        qsort(lat, m, sizeof(uint64_t), cmp_u64);
        if (m > 0) {
            printf("%-5s %8.1f %8.1f %8.1f %8.1f %8zu\n", names[kind], (double)lat[m / 2] / 1e3,
                   (double)lat[m * 9 / 10] / 1e3, (double)lat[m * 99 / 100] / 1e3, (double)lat[m - 1] / 1e3, m);
        }
        free(lat);
        free(s.written);
        free(h.called);
        s.written = NULL;
        h.called = NULL;
        xf_simlink_close(&s.link[0]);
        xf_udp_close(&h.udp[0]);
        xf_tcp_close(&h.tcp[0]);
        xf_serial_close(&h.serial);
    }
    printf("target: p99 <= 200 us\n");
    return 0;
}

static int bench_cpu(unsigned seconds)
{
    static sim_side s;
    static host_side h;
    size_t counts[2] = {1, 64};
    int k;
    printf("CPU of the thread driving the clients at 50 Hz over loopback UDP (%u s each)\n", seconds);
    for (k = 0; k < 2; k++) {
        pthread_t th;
        size_t i, n = counts[k];
        double cpu0, cpu1;
        uint64_t w0, w1;
        uint32_t replies = 0;
        memset(&s, 0, sizeof(s));
        memset(&h, 0, sizeof(h));
        s.n = n;
        for (i = 0; i < n; i++) {
            if (sim_open(&s, i, XF_SIMLINK_UDP, NULL) != 0 || host_open(&h, i, XF_SIMLINK_UDP, &s, NULL, 50) != 0) {
                return 3;
            }
        }
        pthread_create(&th, NULL, sim_thread, &s);
        drive(&h, n, 500);
        cpu0 = thread_cpu_s();
        w0 = now_ns();
        drive(&h, n, seconds * 1000u);
        cpu1 = thread_cpu_s();
        w1 = now_ns();
        atomic_store(&s.stop, 1);
        pthread_join(th, NULL);
        for (i = 0; i < n; i++) {
            replies += h.client[i].health.replies;
            xf_simlink_close(&s.link[i]);
            xf_udp_close(&h.udp[i]);
        }
        printf("%3zu gimbals: %6.2f %% of one core (%.1f us of CPU per gimbal per packet), %u replies\n", n,
               100.0 * (cpu1 - cpu0) / ((double)(w1 - w0) / 1e9),
               1e6 * (cpu1 - cpu0) / ((double)n * 50.0 * ((double)(w1 - w0) / 1e9)), replies);
    }
    printf("target: 64 gimbals <= 5 %% of one core\n");
    return 0;
}

static int bench_alloc(void)
{
    static sim_side s;
    static host_side h;
    pthread_t th;
    long allocs;
    xf_command cmd;
    memset(&s, 0, sizeof(s));
    s.n = 1;
    if (sim_open(&s, 0, XF_SIMLINK_UDP, NULL) != 0 || host_open(&h, 0, XF_SIMLINK_UDP, &s, NULL, 50) != 0) {
        return 3;
    }
    pthread_create(&th, NULL, sim_thread, &s);
    drive(&h, 1, 200);
    /* Steady state: packets, replies, commands, telemetry. */
    atomic_store(&g_counting, 1);
    xf_command_init(&cmd, XF_ORDER_SHUTTER);
    xf_client_submit(&h.client[0], &cmd, NULL, NULL);
    xf_command_init(&cmd, XF_ORDER_ZOOM_IN);
    xf_client_submit(&h.client[0], &cmd, NULL, NULL);
    xf_client_set_rates(&h.client[0], 0.0f, 1.0f, 2.0f, xf_posix_now_ms());
    drive(&h, 1, 1000);
    atomic_store(&g_counting, 0);
    allocs = atomic_load(&g_allocs);
    atomic_store(&s.stop, 1);
    pthread_join(th, NULL);
    printf("heap allocations by client and simulator in 1 s of steady state (%u replies): %ld\n",
           h.client[0].health.replies, allocs);
    if (h.client[0].health.replies < 40u) {
        printf("too few replies to judge\n");
        return 1;
    }
    return allocs == 0 ? 0 : 1;
}

int main(int argc, char **argv)
{
    if (argc >= 2 && strcmp(argv[1], "latency") == 0) {
        return bench_latency((argc > 2) ? (size_t)strtoul(argv[2], NULL, 10) : 1000u);
    }
    if (argc >= 2 && strcmp(argv[1], "cpu") == 0) {
        return bench_cpu((argc > 2) ? (unsigned)strtoul(argv[2], NULL, 10) : 5u);
    }
    if (argc >= 2 && strcmp(argv[1], "alloc") == 0) {
        return bench_alloc();
    }
    fprintf(stderr, "usage: xfgcu_client_bench latency [N] | cpu [SECONDS] | alloc\n");
    return 2;
}
