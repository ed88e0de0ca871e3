/*
 * example_links.h - what the Linux examples share: opening the link a spec string names
 * (xfgcu/posix/xf_link.h), and their stand-in for a gimbal when none is named: a simulated GCU
 * on a new link of this machine (a pty, or UDP or TCP on 127.0.0.1, any free port) with the spec
 * that reaches it, opened as a real gimbal's would be. A real program opens the spec its user
 * gives, and needs no simulator.
 */
#ifndef XFGCU_EXAMPLE_LINKS_H
#define XFGCU_EXAMPLE_LINKS_H

#include <stdio.h>

#include "xfgcu/posix/xf_link.h"
#include "xfgcu/posix/xf_simlink.h"
#include "xfgcu/xf_sim.h"

/* The spec to open: @p given (a program's argument), or, when it is NULL, the spec that reaches
 * @p sim, started on a new link @p gcu of @p kind (step it in the poll loop: xf_posix_poll()).
 * The text stays valid until the next call. NULL after printing why the simulator did not start. */
static inline const char *example_spec(const char *prog, const char *given, xf_simlink_kind kind, xf_simlink *gcu,
                                       xf_sim *sim)
{
    static char spec[300];
    xf_hal hal;
    xf_err err;
    if (given != NULL) {
        return given;
    }
    err = (kind == XF_SIMLINK_PTY)   ? xf_simlink_open_pty(gcu, NULL)
          : (kind == XF_SIMLINK_UDP) ? xf_simlink_open_udp(gcu, "127.0.0.1", 0)
                                     : xf_simlink_open_tcp(gcu, "127.0.0.1", 0);
    if (err != XF_OK) {
        fprintf(stderr, "%s: simulated GCU: %s\n", prog, gcu->error.text);
        return NULL;
    }
    xf_simlink_hal(gcu, &hal);
    xf_sim_init(sim, NULL);
    xf_sim_attach(sim, &hal);
    (void)xf_simlink_host_spec(gcu, spec, sizeof(spec));
    return spec;
}

/* Open the link @p spec names (NULL: none, refused) and give its xf_hal. 0, or -1 after printing why. */
static inline int example_link_open(const char *prog, xf_link *link, const char *spec, xf_hal *hal)
{
    if (spec == NULL) {
        return -1; /* example_spec() said why */
    }
    if (xf_link_open(link, spec) != XF_OK) {
        fprintf(stderr, "%s: %s\n", prog, link->error.text);
        return -1;
    }
    return xf_link_hal(link, hal) == XF_OK ? 0 : -1;
}

#endif /* XFGCU_EXAMPLE_LINKS_H */
