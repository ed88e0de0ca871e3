/*
 * xf_options.c - one symbol per layout option, named after the value this
 * library was built with (xf_config.h says why). xf_client_init() and
 * xf_sim_init() refer to the symbols of their caller's values, so a program
 * built with other values fails to link, and the linker names the option.
 */
#include "xfgcu/xf_config.h"

#define XF__OPTION_DEFINE(name, value) const unsigned char XF__OPTION_SYM(name, value) = 0;
XF__OPTIONS(XF__OPTION_DEFINE)
