/*
 * xf_test_assert.h - assertions shared by every test directory (tests/,
 * tests/hal, tests/client). Include it after <cmocka.h>.
 */
#ifndef XFGCU_TEST_ASSERT_H
#define XFGCU_TEST_ASSERT_H

#include <string.h>

#include "xfgcu/xf_error.h"

/* An xf_err (or parser return) compared with its expected value, both printed by name. */
#define assert_xf(expr, want)                                                                                          \
    do {                                                                                                               \
        int got_ = (int)(expr), want_ = (int)(want);                                                                   \
        if (got_ != want_) {                                                                                           \
            print_error("%s returned %d (%s), expected %d (%s)\n", #expr, got_, xf_strerror(got_), want_,              \
                        xf_strerror(want_));                                                                           \
            fail();                                                                                                    \
        }                                                                                                              \
    } while (0)

/* A string that must contain a fragment (error texts). */
#define assert_contains(hay, needle)                                                                                   \
    do {                                                                                                               \
        const char *hay_ = (hay), *needle_ = (needle);                                                                 \
        if (hay_ == NULL || strstr(hay_, needle_) == NULL) {                                                           \
            print_error("\"%s\" does not contain \"%s\"\n", hay_ != NULL ? hay_ : "(null)", needle_);                  \
            fail();                                                                                                    \
        }                                                                                                              \
    } while (0)

#endif
