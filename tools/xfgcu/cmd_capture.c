/*
 * cmd_capture.c - `xfgcu [LINK] capture [--pcap] FILE [--duration S] [--count N] [COMMAND [ARGS]]`
 * (and `xfgcu record FILE ...`, its old name, kept for scripts: the camera order record is
 * `xfgcu send record`).
 *
 * The link is wrapped in a tap (tap.h) that hands every chunk read or
 * written, with its time, to the capture writer (capture.h), so FILE
 * holds the bytes exactly as the link moved them, both ways, in the text
 * format of docs/capture-format.md or, with --pcap, in pcap (capture_pcap.h).
 * Meanwhile the client keeps the link going with null packets, or runs
 * COMMAND the protocol's way (as send).
 */
#include <arpa/inet.h>
#include <errno.h>
#include <netinet/in.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli.h"
#include "cmdline.h"
#include "linkopts.h"
#include "online.h"
#include "capture.h"
#include "capture_pcap.h"

#define NULLS_AFTER 3u
#define DRAIN_MS    250u

void help_capture(FILE *out)
{
    fputs("usage: xfgcu [LINK OPTIONS] capture [--pcap] FILE [--duration S] [--count N] [--force] [COMMAND [ARGS]]\n\n"
          "Capture every byte the link moves, both ways, with timestamps, into FILE (a text format,\n"
          "one chunk per line: docs/capture-format.md), while null packets keep the link going.\n"
          "`xfgcu replay FILE` decodes it.\n\n"
          "  --pcap         write pcap instead, for Wireshark (tools/wireshark/xfgcu.lua): UDP and\n"
          "                 TCP as IPv4 packets (LINKTYPE_RAW), serial as LINKTYPE_USER0\n"
          "  --duration S   stop after S seconds (0.1..4294967: the capture's 32-bit milliseconds)\n"
          "  --count N      stop after N packets from the GCU (1..1000000000)\n"
          "  --force        replace FILE if it exists (otherwise an existing FILE is an error)\n"
          "  COMMAND        also run a command, as `xfgcu send COMMAND [ARGS]` does, and print its\n"
          "                 result; without --duration or --count the capture then ends with it\n"
          "Otherwise it runs until Ctrl-C. Prints a one-line summary (chunks, bytes, packets).\n"
          "The capture is written to a temporary file beside FILE and takes FILE's name when it is\n"
          "complete. One that is not (a failed write: exit 2; a lost link: exit 3) stays as\n"
          "FILE.partXXXXXX, named on stderr, and FILE is left as it was; when no byte moved, nothing\n"
          "is left.\n\n",
          out);
    help_link_options(out);
    fputs("\n`xfgcu record FILE ...` is the old name of this command, kept for scripts (deprecated; the\n"
          "camera order record is `xfgcu send record`).\n"
          "\nexample: xfgcu --tcp 192.168.144.108 capture shutter.cap shutter\n",
          out);
}

typedef struct record {
    online *o;
    char desc[320]; /* the link's, kept for the summary */
    const char *file;
    char tmp[4096]; /* where the capture is written until it is complete */
    FILE *f;
    int force, pcap;
    xf_capture_writer w;
    pcap_writer pw;
    int begun;
    long count;
    double duration;
    int has_count, has_duration, help;
    int has_spec;
    cmd_spec spec;
    uint32_t sent, received;
    int lost;      /* the link was lost during the capture */
    char why[200]; /* why, for the message */
} record;

/* ---- arguments ---------------------------------------------------------------------- */

enum { O_DURATION = 256, O_COUNT, O_FORCE, O_PCAP, O_HELP };

static const struct option record_options[] = {
    {"duration", required_argument, NULL, O_DURATION},
    {"count", required_argument, NULL, O_COUNT},
    {"force", no_argument, NULL, O_FORCE},
    {"pcap", no_argument, NULL, O_PCAP},
    {"help", no_argument, NULL, O_HELP},
    {NULL, 0, NULL, 0},
};

/* FILE, then COMMAND */
static int take_word(record *r, const char *word)
{
    if (r->file == NULL) {
        r->file = word;
    } else if (!(r->has_spec = cmdargs_find(word, &r->spec))) {
        return cli_fail("capture: unknown command '%s' (see 'xfgcu send --help'); FILE is '%s'", word, r->file);
    }
    return XFGCU_EXIT_OK;
}

static int take_arg(record *r, const cli_args *a, int id)
{
    switch (id) {
    case O_DURATION: return cli_value_real(a, 0.1, 4294967.0, "seconds, 0.1..4294967", &r->duration, &r->has_duration);
    case O_COUNT:
        return cli_value_long(a, 1, 1000000000L, "a number of packets, 1..1000000000", &r->count, &r->has_count);
    case O_FORCE: r->force = 1; return XFGCU_EXIT_OK;
    case O_PCAP: r->pcap = 1; return XFGCU_EXIT_OK;
    case O_HELP: r->help = 1; return XFGCU_EXIT_OK;
    case CLI_ARG: return take_word(r, a->value);
    default: return XFGCU_EXIT_USAGE; /* CLI_BAD: said */
    }
}

/* Options of record up to COMMAND; everything after COMMAND is the command's. */
static int parse_args(record *r, int argc, char **argv, const uint8_t *version, xf_command *cmd)
{
    cli_args a;
    int id, rc = XFGCU_EXIT_OK;
    cli_args_init(&a, argc, argv, CLI_IN_ORDER, record_options, "capture");
    while (rc == XFGCU_EXIT_OK && !r->has_spec && (id = cli_next(&a)) != CLI_END) {
        rc = take_arg(r, &a, id);
    }
    if (rc != XFGCU_EXIT_OK || r->help) {
        return rc;
    }
    if (r->file == NULL) {
        return cli_fail("capture: missing FILE (where the capture goes)");
    }
    return r->has_spec ? cmd_line_command(&r->spec, "capture", argc - a.index, argv + a.index, version, cmd)
                       : XFGCU_EXIT_OK;
}

/* ---- callbacks ------------------------------------------------------------------------ */

/* An IPv4 socket address: its address and port (host order); 0 when it is not IPv4. */
static int ipv4_of(const struct sockaddr_storage *ss, uint32_t *ip, uint16_t *port)
{
    const struct sockaddr_in *in = (const struct sockaddr_in *)(const void *)ss;
    if (ss->ss_family != AF_INET) {
        return 0;
    }
    *ip = ntohl(in->sin_addr.s_addr);
    *port = ntohs(in->sin_port);
    return 1;
}

/* The local address the system sends to @p gcu_ip from (a UDP socket bound to any address has
 * none of its own): what a connected socket is given; 0 when there is none. */
static uint32_t route_source(uint32_t gcu_ip, uint16_t gcu_port)
{
    struct sockaddr_in to, from;
    socklen_t n = sizeof(from);
    uint32_t ip = 0;
    int fd = socket(AF_INET, SOCK_DGRAM, 0);
    memset(&to, 0, sizeof(to));
    to.sin_family = AF_INET;
    to.sin_addr.s_addr = htonl(gcu_ip);
    to.sin_port = htons(gcu_port);
    if (fd >= 0 && connect(fd, (const struct sockaddr *)&to, sizeof(to)) == 0 &&
        getsockname(fd, (struct sockaddr *)&from, &n) == 0) {
        ip = ntohl(from.sin_addr.s_addr);
    }
    if (fd >= 0) {
        close(fd);
    }
    return ip;
}

/* The link's two ends, for the made-up IPv4 headers: the sockets' own when IPv4, else the ports
 * of the options around 0.0.0.0. */
static pcap_kind pcap_ends_of(const online *o, pcap_ends *e)
{
    const xf_link *l = &o->link;
    struct sockaddr_storage ss;
    socklen_t n = sizeof(ss);
    int fd = (l->spec.kind == XF_LINK_KIND_UDP) ? l->as.udp.fd : l->as.tcp.fd;
    memset(e, 0, sizeof(*e));
    if (l->spec.kind != XF_LINK_KIND_UDP && l->spec.kind != XF_LINK_KIND_TCP) {
        return PCAP_KIND_SERIAL;
    }
    e->gcu_port = l->spec.port;
    e->host_port = (l->spec.kind == XF_LINK_KIND_UDP) ? l->as.udp.local_port : 0u;
    if (getsockname(fd, (struct sockaddr *)&ss, &n) == 0) {
        (void)ipv4_of(&ss, &e->host_ip, &e->host_port);
    }
    n = sizeof(ss);
    if (l->spec.kind == XF_LINK_KIND_UDP) {
        (void)ipv4_of(&l->as.udp.gcu, &e->gcu_ip, &e->gcu_port);
    } else if (getpeername(fd, (struct sockaddr *)&ss, &n) == 0) {
        (void)ipv4_of(&ss, &e->gcu_ip, &e->gcu_port);
    }
    if (e->host_ip == 0u && e->gcu_ip != 0u) {
        e->host_ip = route_source(e->gcu_ip, e->gcu_port);
    }
    return (l->spec.kind == XF_LINK_KIND_UDP) ? PCAP_KIND_UDP : PCAP_KIND_TCP;
}

/* The file's header, once the link is known (a byte moved), or at the end when none did. */
static void begin_file(record *r, const online *o, const char *desc)
{
    pcap_ends ends;
    memset(&ends, 0, sizeof(ends));
    r->begun = 1;
    if (r->pcap) {
        pcap_kind kind = (o != NULL) ? pcap_ends_of(o, &ends) : PCAP_KIND_SERIAL;
        (void)pcap_writer_open(&r->pw, r->f, kind, &ends); /* a failure is kept for the end (close_file()) */
        r->f = NULL;                                       /* the writer's now, whatever happened */
    } else {
        (void)xf_capture_begin(&r->w, r->f, desc, xf_capture_wall_ms());
    }
}

static void on_chunk(void *user, xf_direction dir, const uint8_t *data, size_t len, uint32_t now_ms)
{
    record *r = (record *)user;
    if (!r->begun) {
        begin_file(r, r->o, r->o->desc);
    }
    if (r->pcap) {
        pcap_writer_chunk(&r->pw, dir, data, len, now_ms);
    } else {
        xf_capture_chunk(&r->w, dir, data, len, now_ms);
    }
}

static void on_bytes(void *user, xf_direction dir, const uint8_t *data, size_t len, uint32_t now_ms)
{
    record *r = (record *)user;
    (void)data;
    (void)len;
    (void)now_ms;
    if (dir == XF_DIR_HOST) {
        r->sent++;
    } else {
        r->received++;
    }
}

/* ---- running ---------------------------------------------------------------------------- */

/* The errno of the writer's first failed write, or 0: the writer writes nothing after it. */
static int write_error(const record *r) { return r->pcap ? r->pw.error : r->w.error; }

/* The link was up (online_open()) and is down now: the connection closed, the port hung up, or
 * no valid reply for the client's down_ms. The capture of a lost link is not a complete one. */
static int link_lost(const record *r) { return xf_client_link(&r->o->client) == XF_LINK_DOWN; }

static int done(const record *r, uint32_t elapsed)
{
    return cli_stop_requested() || (r->has_count && r->received >= (uint32_t)r->count) ||
           (r->has_duration && cli_seconds(elapsed) >= r->duration);
}

static int run_command(record *r, const xf_command *cmd)
{
    xf_cmd_result res;
    char text[64], what[64];
    int rc = online_run(r->o, cmd, &res, NULL, NULL);
    if (rc != XFGCU_EXIT_OK) {
        return rc;
    }
    online_result_text(&res, text, sizeof(text));
    printf("%s\n", text);
    fflush(stdout);
    if (!r->has_count && !r->has_duration && write_error(r) == 0) {
        online_linger(r->o, NULLS_AFTER);
    }
    snprintf(what, sizeof(what), "capture %s", r->spec.name);
    return online_result_exit(r->o, what, &res);
}

/* The reply to the last packet sent is on its way: let it into the capture. */
static void drain(record *r)
{
    uint32_t start = xf_posix_now_ms();
    while (r->received < r->sent && xf_ms_since(xf_posix_now_ms(), start) < DRAIN_MS) {
        online_poll(r->o, 5);
    }
}

/* Capture until a limit, Ctrl-C, the end of COMMAND, the first failed write or the loss of the
 * link (r->lost, with why in r->why). @return an exit code, the failure said (but not a write's
 * or the loss's: finish_file() says those, with where the capture is). */
static int capture(record *r, const cli_link *link, const xf_command *cmd, uint32_t *elapsed)
{
    online_hooks hooks;
    uint32_t start = xf_posix_now_ms();
    int rc;
    memset(&hooks, 0, sizeof(hooks));
    hooks.tap = on_chunk;
    hooks.on_bytes = on_bytes;
    hooks.user = r;
    rc = online_open(r->o, link, "capture", &hooks);
    if (rc == XFGCU_EXIT_OK && r->has_spec) {
        rc = run_command(r, cmd);
    }
    if (rc == XFGCU_EXIT_OK && (!r->has_spec || r->has_count || r->has_duration)) {
        while (!done(r, xf_ms_since(xf_posix_now_ms(), start)) && write_error(r) == 0 && !(r->lost = link_lost(r))) {
            online_poll(r->o, 50);
        }
    }
    *elapsed = xf_ms_since(xf_posix_now_ms(), start);
    if (r->lost) {
        const char *why = xf_link_error(&r->o->link)->text;
        snprintf(r->why, sizeof(r->why), "%s",
                 xf_client_health(&r->o->client)->transport_closed && why[0] != '\0' ? why
                                                                                     : "the GCU stopped answering");
    } else if (rc != XFGCU_EXIT_LINK && write_error(r) == 0) {
        drain(r);
    }
    return rc;
}

/* The complete capture takes FILE's name: replacing FILE only with --force, and never a FILE
 * that appeared meanwhile without it (link() refuses an existing name, rename() would not).
 * Whatever goes wrong, the capture is never lost: it stays under its temporary name, which is
 * said. */
static int publish(record *r)
{
    int e = 0;
    if (r->force) {
        e = (rename(r->tmp, r->file) != 0) ? errno : 0;
    } else if (link(r->tmp, r->file) != 0) {
        e = errno;
    } else {
        (void)unlink(r->tmp);
    }
    if (e != 0) {
        return cli_fail("capture: cannot name the capture %s: %s%s; it is kept as %s", r->file, strerror(e),
                        e == EEXIST ? " (it appeared meanwhile; --force replaces it)" : "", r->tmp);
    }
    return XFGCU_EXIT_OK;
}

/* Close the file; the errno of the first failure, or 0. */
static int close_file(record *r)
{
    int err;
    if (r->pcap) {
        return pcap_writer_close(&r->pw); /* the writer has the file since begin_file() */
    }
    err = r->w.error;
    if (fclose(r->f) != 0 && err == 0) {
        err = errno;
    }
    return err;
}

/* An incomplete capture: where it is kept (never removed: it may be all there is of what
 * happened), and that FILE was left alone. */
static void kept_text(const record *r, uint32_t elapsed, char *buf, size_t cap)
{
    struct stat st;
    snprintf(buf, cap, "what was captured (%.2f s, %u chunks, %u bytes) is kept as %s; %s %s", cli_seconds(elapsed),
             (unsigned)(r->pcap ? r->pw.chunks : r->w.chunks), (unsigned)(r->pcap ? r->pw.bytes : r->w.bytes), r->tmp,
             r->file, lstat(r->file, &st) == 0 ? "is as it was" : "is not written");
}

/* The end: a complete capture (exit 0, or 1 for COMMAND's failure) takes FILE's name; any other
 * stays under its temporary name, said in the one failure line, or in a note after the line that
 * said why it failed. */
static int finish_file(record *r, int rc, uint32_t elapsed)
{
    char kept[2 * 4096 + 256];
    int err;
    if (!r->begun) {
        begin_file(r, NULL, r->desc);
    }
    err = close_file(r);
    kept_text(r, elapsed, kept, sizeof(kept));
    if (err != 0) {
        return cli_fail("capture: cannot write %s: %s; %s", r->tmp, strerror(err), kept);
    }
    if (r->lost) {
        return cli_fail_link("capture: link lost on %s after %.2f s: %s; %s", r->desc, cli_seconds(elapsed), r->why,
                             kept);
    }
    if (rc != XFGCU_EXIT_OK && rc != XFGCU_EXIT_FAILED) {
        cli_note("capture: %s", kept);
        return rc;
    }
    err = publish(r);
    if (err != XFGCU_EXIT_OK) {
        return err;
    }
    printf("captured %.2f s on %s: %u chunks, %u bytes (%u packets sent, %u received) to %s\n", cli_seconds(elapsed),
           r->desc, (unsigned)(r->pcap ? r->pw.chunks : r->w.chunks), (unsigned)(r->pcap ? r->pw.bytes : r->w.bytes),
           (unsigned)r->sent, (unsigned)r->received, r->file);
    return rc;
}

/* A temporary file beside FILE (the same file system, so that it can take FILE's name), made
 * here: the only file this command may remove. FILE itself is left alone until the end. */
static int open_tmp(record *r)
{
    struct stat st;
    int fd;
    if (r->file == NULL) {
        return XFGCU_EXIT_USAGE; /* parse_args() makes sure it is there */
    }
    if (!r->force && lstat(r->file, &st) == 0) {
        return cli_fail("capture: %s exists; not replaced (--force replaces it)", r->file);
    }
    if ((size_t)snprintf(r->tmp, sizeof(r->tmp), "%s.partXXXXXX", r->file) >= sizeof(r->tmp)) {
        return cli_fail("capture: the file name is too long");
    }
    fd = mkstemp(r->tmp);
    if (fd >= 0) {
        mode_t mask = umask(0);
        umask(mask);
        (void)fchmod(fd, 0666 & ~mask); /* as a new file would have: mkstemp makes it private */
    }
    if (fd < 0 || (r->f = fdopen(fd, "w")) == NULL) {
        int e = errno;
        if (fd >= 0) {
            close(fd);
            (void)unlink(r->tmp);
        }
        return cli_fail("capture: cannot create a file beside %s: %s", r->file, strerror(e));
    }
    return XFGCU_EXIT_OK;
}

static int run_record(record *r, const cli_link *link, const xf_command *cmd)
{
    uint32_t elapsed = 0;
    int rc;
    /* a file size limit (ulimit -f) is a failed write, as a full disk is, not the end of the program */
    (void)signal(SIGXFSZ, SIG_IGN);
    rc = open_tmp(r);
    if (rc != XFGCU_EXIT_OK) {
        return rc;
    }
    r->o = online_new();
    if (r->o == NULL) {
        fclose(r->f);
        (void)unlink(r->tmp);
        return XFGCU_EXIT_USAGE;
    }
    cli_signals_init();
    rc = capture(r, link, cmd, &elapsed);
    snprintf(r->desc, sizeof(r->desc), "%s", r->o->desc);
    online_free(r->o); /* closes the link: nothing more is tapped */
    r->o = NULL;
    if (rc == XFGCU_EXIT_OK || rc == XFGCU_EXIT_FAILED || r->begun) {
        return finish_file(r, rc, elapsed);
    }
    fclose(r->f);         /* not begun: still ours */
    (void)unlink(r->tmp); /* the link never moved a byte: no capture to keep; FILE is untouched */
    return rc;
}

int cmd_capture(const cli_link *link, int argc, char **argv)
{
    record r;
    xf_command cmd;
    int rc;
    memset(&r, 0, sizeof(r));
    if (strcmp(argv[0], "record") == 0) {
        cli_note("'xfgcu record FILE' is the old name of 'xfgcu capture FILE' (the camera order is 'xfgcu send "
                 "record'); it still works, use capture in new scripts");
    }
    /* link options after COMMAND (cli_set_anywhere()) change *link while it is parsed: the command
     * is checked for the protocol version the whole line gives */
    rc = parse_args(&r, argc, argv, &link->protocol, &cmd);
    if (rc == XFGCU_EXIT_OK && r.help) {
        help_capture(stdout);
    } else if (rc == XFGCU_EXIT_OK) {
        rc = linkopts_require(link, "capture");
        if (rc == XFGCU_EXIT_OK) {
            rc = run_record(&r, link, &cmd);
        }
    }
    return rc;
}
