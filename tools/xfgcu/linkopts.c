/*
 * linkopts.c - the options before COMMAND, and the link they name (linkopts.h).
 *
 * A link is named once: by --serial PATH, --udp HOST[:PORT], --tcp HOST[:PORT] or --link SPEC,
 * or, when none is given, by the environment's XFGCU_LINK. --udp and --tcp read their value as
 * the library reads the spec "udp:VALUE" and "tcp:VALUE"; --link and XFGCU_LINK are specs. The
 * one parser of the grammar is the library's (xf_link_spec_parse()).
 */
#include "linkopts.h"

#include <string.h>

#include "xfgcu/xf_client.h"

static const struct option link_options[] = {
    {"help", no_argument, NULL, LO_HELP},
    {"version", no_argument, NULL, LO_VERSION},
    {"serial", required_argument, NULL, LO_SERIAL},
    {"baud", required_argument, NULL, LO_BAUD},
    {"udp", required_argument, NULL, LO_UDP},
    {"tcp", required_argument, NULL, LO_TCP},
    {"link", required_argument, NULL, LO_LINK},
    {"gcu-port", required_argument, NULL, LO_GCU_PORT},
    {"local-port", required_argument, NULL, LO_LOCAL_PORT},
    {"protocol", required_argument, NULL, LO_PROTOCOL},
    {"rate", required_argument, NULL, LO_RATE},
    {"timeout", required_argument, NULL, LO_TIMEOUT},
    {"reorder", required_argument, NULL, LO_REORDER},
    {"trace", no_argument, NULL, LO_TRACE},
    {"raw", no_argument, NULL, LO_RAW},
    {NULL, 0, NULL, 0},
};

const struct option *linkopts_table(void) { return link_options; }

void help_link_options(FILE *out)
{
    fputs("link options (before or after COMMAND; one link for the online commands: --link, --serial,\n"
          "--udp or --tcp, else the environment's XFGCU_LINK):\n"
          "  --link SPEC           tcp:HOST[:PORT], udp:HOST[:PORT][,local=PORT] or serial:PATH[,baud=N],\n"
          "                        as the library's xf_link_open() takes it\n"
          "  --serial PATH         serial device, e.g. /dev/ttyUSB0\n"
          "  --baud N              115200 (default), 250000, 500000 or 1000000\n"
          "  --udp HOST[:PORT]     UDP to the GCU (port 2337)\n"
          "  --tcp HOST[:PORT]     connect as TCP client (port 2332)\n"
          "  --gcu-port N          the GCU's UDP port (2337) or TCP port (2332)\n"
          "  --local-port N        local UDP port to receive on (2338; 0 = any free port)\n"
          "  --protocol auto|1|2   version byte sent: auto (the default) tries 1, then 2, until the GCU\n"
          "                        answers, and keeps the one it answers; 1 or 2 sends that one only\n"
          "  --rate HZ             the link's packet rate, packets per second, 1..200 (50; the vendor\n"
          "                        recommends 30..50)\n"
          "  --timeout MS          how long to wait for the first reply and for a command's feedback (1000)\n"
          "  --reorder MS          the longest the network can delay one packet behind a later one (0:\n"
          "                        it keeps order, as serial, TCP and a wired LAN do); 0..1000, and a\n"
          "                        packet period plus twice it under 250 ms (114 at 50 Hz). Not given:\n"
          "                        the client judges the link and uses a bound while it is not in order\n"
          "  --trace               print every packet sent and received on stderr, one line each\n"
          "general options (anywhere):\n"
          "  --raw                 fields as wire integers, not engineering units (docs/protocol.md,\n"
          "                        \"Units\"): JSON and text output, and encode --json's input\n"
          "\nexit status: 0 success, 1 the GCU answered with failure, 2 usage error or bad input,\n"
          "3 link error or timeout.\n",
          out);
}

void linkopts_defaults(cli_link *l, const char *env_spec)
{
    memset(l, 0, sizeof(*l));
    l->baud = 115200L;
    l->local_port = 2338L;
    l->protocol = XF_PROTOCOL_V1; /* the version auto tries first */
    l->version_auto = 1u;
    l->rate_hz = 50L;
    l->timeout_ms = 1000L;
    l->view = TEXT_ENGINEERING;
    l->env_spec = (env_spec != NULL && env_spec[0] != '\0') ? env_spec : NULL;
}

/* The library's reason without the text it quotes first ("QUOTED: reason"), when it quoted it whole. */
static const char *spec_reason(const xf_link_spec *spec, const char *quoted)
{
    size_t n = strlen(quoted);
    const char *t = spec->error.text;
    return (strncmp(t, quoted, n) == 0 && strncmp(t + n, ": ", 2) == 0) ? t + n + 2 : t;
}

/* --udp or --tcp's value read as the library reads the spec "KIND:VALUE"; *reason (may be NULL)
 * says what is wrong, without the spec the library's text quotes first. */
static xf_err host_spec(const char *kind, const char *value, xf_link_spec *spec, const char **reason)
{
    char buf[XF_LINK_SPEC_MAX + 2u]; /* a longer text is cut here, and refused as too long */
    xf_err err;
    snprintf(buf, sizeof(buf), "%s:%s", kind, value);
    err = xf_link_spec_parse(buf, spec);
    if (reason != NULL) {
        *reason = spec_reason(spec, buf);
    }
    return err;
}

/* --udp HOST[:PORT], --tcp HOST[:PORT]: checked now, a usage error when bad. */
static int take_host(const cli_args *a, const char **host)
{
    xf_link_spec spec;
    const char *reason = NULL;
    int rc = cli_value_text(a, "HOST[:PORT]", host);
    if (rc == XFGCU_EXIT_OK && strchr(*host, ',') != NULL) {
        return cli_fail("--%s %s: options have no place here: give --link %s:%s (or --local-port, --baud)",
                        a->opt->name, *host, a->opt->name, *host);
    }
    if (rc == XFGCU_EXIT_OK && host_spec(a->opt->name, *host, &spec, &reason) != XF_OK) {
        rc = cli_fail("--%s %s: %s", a->opt->name, *host, reason);
    }
    return rc;
}

/* --link SPEC: checked now, a usage error when bad. */
static int take_spec(const cli_args *a, const char **text)
{
    xf_link_spec spec;
    int rc = cli_value_text(a, "tcp:HOST[:PORT], udp:HOST[:PORT][,local=PORT] or serial:PATH[,baud=N]", text);
    if (rc == XFGCU_EXIT_OK && xf_link_spec_parse(*text, &spec) != XF_OK) {
        rc = cli_fail("--link %s", spec.error.text);
    }
    return rc;
}

int linkopts_take(cli_link *l, const cli_args *a, int id)
{
    unsigned bit = 1u << (unsigned)(id - LO_SERIAL);
    if (l->given & bit) {
        return cli_fail_in(a->context, "--%s given twice", a->opt->name); /* which one would count? */
    }
    l->given |= bit;
    switch (id) {
    case LO_SERIAL: return cli_value_text(a, "a device path", &l->serial);
    case LO_BAUD: l->has_baud = 1; return cli_value_baud(a, &l->baud, NULL);
    case LO_UDP: return take_host(a, &l->udp);
    case LO_TCP: return take_host(a, &l->tcp);
    case LO_LINK: return take_spec(a, &l->spec);
    case LO_GCU_PORT: l->has_gcu_port = 1; return cli_value_long(a, 1, 65535, "a port 1..65535", &l->gcu_port, NULL);
    case LO_LOCAL_PORT:
        l->has_local_port = 1;
        return cli_value_long(a, 0, 65535, "a port 0..65535 (0: any free port)", &l->local_port, NULL);
    case LO_PROTOCOL: return cli_value_protocol_auto(a, &l->protocol, &l->version_auto);
    case LO_RATE: return cli_value_long(a, 1, 200, "packets per second, 1..200", &l->rate_hz, NULL);
    case LO_REORDER:
        l->has_reorder = 1;
        return cli_value_long(a, 0, 1000, "milliseconds, 0..1000", &l->reorder_ms, NULL);
    case LO_TRACE: l->trace = 1; return XFGCU_EXIT_OK;
    case LO_RAW: l->view = TEXT_RAW; return XFGCU_EXIT_OK;
    default: return cli_value_long(a, 1, 3600000L, "milliseconds, 1..3600000", &l->timeout_ms, NULL);
    }
}

/* --udp or --tcp names its port (HOST:PORT or [ADDR]:PORT, read as the library reads the spec). */
static int port_given(const char *kind, const char *value)
{
    xf_link_spec spec;
    return value != NULL && host_spec(kind, value, &spec, NULL) == XF_OK && spec.port_given;
}

/* The per-link options given with a spec (--link, or XFGCU_LINK as @p named): the spec says them. */
static int spec_options(const cli_link *l, const char *named)
{
    if (l->has_baud) {
        return cli_fail("--baud is for --serial; with %s, the spec says it: serial:PATH,baud=N", named);
    }
    if (l->has_gcu_port || l->has_local_port) {
        return cli_fail("--%s is for --udp or --tcp; with %s, the spec says it: udp:HOST:PORT,local=PORT",
                        l->has_gcu_port ? "gcu-port" : "local-port", named);
    }
    return XFGCU_EXIT_OK;
}

int linkopts_check(const cli_link *l)
{
    int n = (l->serial != NULL) + (l->udp != NULL) + (l->tcp != NULL) + (l->spec != NULL);
    const char *net = (l->udp != NULL) ? "udp" : "tcp";
    if (n > 1) {
        return cli_fail("give only one of --serial, --udp, --tcp, --link: they name one link each");
    }
    if (l->spec != NULL) {
        return spec_options(l, "--link");
    }
    if (l->has_baud && (l->udp != NULL || l->tcp != NULL)) {
        return cli_fail("--baud is for --serial, not --%s", net);
    }
    if ((l->has_gcu_port || l->has_local_port) && l->serial != NULL) {
        return cli_fail("--%s is for --udp or --tcp, not --serial", l->has_gcu_port ? "gcu-port" : "local-port");
    }
    if (l->has_local_port && l->tcp != NULL) {
        return cli_fail("--local-port is for --udp, not --tcp");
    }
    if (l->has_gcu_port && port_given(net, l->udp != NULL ? l->udp : l->tcp)) {
        return cli_fail("--gcu-port and the port of --%s %s: give the port once", net,
                        l->udp != NULL ? l->udp : l->tcp);
    }
    return XFGCU_EXIT_OK;
}

int linkopts_require(const cli_link *l, const char *context)
{
    if (l->serial == NULL && l->udp == NULL && l->tcp == NULL && l->spec == NULL && l->env_spec == NULL) {
        return cli_fail("%s needs a link: give --link SPEC, --serial PATH, --udp HOST or --tcp HOST[:PORT] before "
                        "'%s' (or set XFGCU_LINK)",
                        context, context);
    }
    return XFGCU_EXIT_OK;
}

/* A spec string (--link, XFGCU_LINK) into @p spec; @p named says which in messages. */
static int spec_of_text(const char *text, const char *named, xf_link_spec *spec)
{
    if (xf_link_spec_parse(text, spec) != XF_OK) {
        return cli_fail("%s: %s", named, spec->error.text);
    }
    return XFGCU_EXIT_OK;
}

/* --serial PATH with --baud, --udp HOST[:PORT] with --gcu-port and --local-port, --tcp HOST[:PORT] with --gcu-port. */
static int spec_of_options(const cli_link *l, xf_link_spec *spec, const char *option)
{
    const char *reason = NULL;
    xf_err err;
    if (l->serial != NULL) {
        err = xf_link_spec_init(spec, XF_LINK_KIND_SERIAL, l->serial);
        spec->baud = (uint32_t)l->baud;
        reason = spec_reason(spec, l->serial);
    } else {
        err = host_spec(l->udp != NULL ? "udp" : "tcp", l->udp != NULL ? l->udp : l->tcp, spec, &reason);
        spec->local_port = (uint16_t)l->local_port;
    }
    if (l->gcu_port != 0 && !spec->port_given) {
        spec->port = (uint16_t)l->gcu_port;
    }
    return (err == XF_OK) ? XFGCU_EXIT_OK : cli_fail("%s: %s", option, reason);
}

int linkopts_spec(const cli_link *l, xf_link_spec *spec, char *option, size_t cap)
{
    int rc;
    if (l->spec != NULL) {
        snprintf(option, cap, "--link %s", l->spec);
        rc = spec_of_text(l->spec, "--link", spec);
    } else if (l->serial != NULL || l->udp != NULL || l->tcp != NULL) {
        const char *name = (l->serial != NULL) ? "serial" : (l->udp != NULL) ? "udp" : "tcp";
        snprintf(option, cap, "--%s %s", name, l->serial != NULL ? l->serial : l->udp != NULL ? l->udp : l->tcp);
        rc = spec_of_options(l, spec, option);
    } else {
        snprintf(option, cap, "XFGCU_LINK=%s", l->env_spec != NULL ? l->env_spec : "");
        rc = spec_options(l, "XFGCU_LINK");
        if (rc == XFGCU_EXIT_OK) {
            rc = spec_of_text(l->env_spec != NULL ? l->env_spec : "", "XFGCU_LINK", spec);
        }
    }
    if (rc == XFGCU_EXIT_OK && spec->kind == XF_LINK_KIND_TCP) {
        spec->connect_timeout_ms = (uint32_t)l->timeout_ms;
    }
    return rc;
}

/* ---- timing ------------------------------------------------------------------------- */

static long lowest_rate(xf_client_config cc)
{
    xf_client_timing t;
    for (cc.rate_hz = 1; cc.rate_hz <= 200u; cc.rate_hz++) {
        if (xf_client_config_timing(&cc, &t) == XF_OK && t.gap_ms < cc.stale_ms) {
            return (long)cc.rate_hz;
        }
    }
    return 0;
}
int linkopts_check_timing(const cli_link *l)
{
    xf_client_config cc;
    xf_client_timing t;
    xf_client_config_init(&cc); /* stale_ms: the program keeps the library's default */
    cc.rate_hz = (uint16_t)l->rate_hz;
    cc.reorder_ms = (uint16_t)l->reorder_ms;
    if (xf_client_config_timing(&cc, &t) != XF_OK) {
        return cli_fail("--rate %ld: give 1 to 200", l->rate_hz);
    }
    if (t.gap_ms >= cc.stale_ms) {
        long low = lowest_rate(cc);
        if (low == 0) {
            return cli_fail("--reorder %ld: too long; silence of twice that around each command would read as a "
                            "stale link (%u ms)",
                            l->reorder_ms, (unsigned)cc.stale_ms);
        }
        return cli_fail("--rate %ld: a packet every %lu ms%s, but the link reads stale after %u ms without a reply: "
                        "give --rate %ld or more",
                        l->rate_hz, (unsigned long)t.period_ms, l->reorder_ms > 0 ? " and twice --reorder" : "",
                        (unsigned)cc.stale_ms, low);
    }
    if (l->timeout_ms < (long)t.round_trip_ms) {
        return cli_fail("--timeout %ld: shorter than a round trip at --rate %ld (two packets, %lu ms%s): give "
                        "--timeout %lu or more",
                        l->timeout_ms, l->rate_hz, 2ul * t.period_ms, l->reorder_ms > 0 ? ", plus twice --reorder" : "",
                        (unsigned long)t.round_trip_ms);
    }
    return XFGCU_EXIT_OK;
}
