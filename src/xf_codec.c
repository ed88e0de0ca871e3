/*
 * xf_codec.c - the codec compiled once, for builds that define
 * XF_SEPARATE_IMPLEMENTATION (one copy in flash instead of static inline
 * copies in every translation unit).
 */
#ifndef XF_SEPARATE_IMPLEMENTATION
#define XF_SEPARATE_IMPLEMENTATION
#endif
#define XF_IMPLEMENTATION
#include "xfgcu/xfgcu.h"
