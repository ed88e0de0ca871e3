/*
 * xf_test_assert.h - assertions shared by every test directory (tests/,
 * tests/hal, tests/client). Include it after <cmocka.h>.
 */
#ifndef XFGCU_TEST_ASSERT_H
#define XFGCU_TEST_ASSERT_H

#include <string.h>

#include "xfgcu/xf_error.h"

/* cmocka's _fail() never returns: it leaves the test with longjmp, or aborts,
 * or exits. Saying so lets gcc's flow analysis at -O2/-O3 stop at a failed
 * assertion instead of warning about what the code after it would read. */
#if defined(__GNUC__)
void _fail(const char *const file, const int line) __attribute__((noreturn));
#endif

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
