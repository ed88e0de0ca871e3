/* Every public header in one translation unit, for the compiler matrix (C and C++). */
#include "xfgcu/xfgcu.h"
#include "xfgcu/xf_client.h"
#include "xfgcu/xf_hal.h"
#include "xfgcu/xf_mem.h"
#include "xfgcu/posix/xf_link.h"
#include "xfgcu/posix/xf_poll.h"
#include "xfgcu/posix/xf_posix.h"
#include "xfgcu/posix/xf_simlink.h"
#include "xfgcu/xf_sim.h"

int xf_matrix_probe(void);
int xf_matrix_probe(void)
{
    xf_parser p;
    xf_command c;
    if (xf_parser_init(&p, XF_DIR_GCU) != XF_OK) {
        return 1;
    }
    xf_command_init(&c, XF_ORDER_TRACK);
    return (int)xf_order_params_len(c.order) - 10;
}
