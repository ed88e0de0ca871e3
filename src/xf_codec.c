/*
 * xf_codec.c - the codec's implementation translation unit: every codec
 * function, every table and the build-option symbols are defined here, once
 * (the headers only declare them elsewhere). The xfgcu::codec library is this
 * file; a firmware that does not use the CMake targets compiles it with its
 * own options, or defines XF_IMPLEMENTATION in a file of its own instead.
 */
#define XF_IMPLEMENTATION
#include "xfgcu/xfgcu.h"
