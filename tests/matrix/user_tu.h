/*
 * user_tu.h - what the two files of the matrix's user program share
 * (scripts/matrix.sh builds user_tu.c and user_tu_values.c into one program):
 * the check counter and its macro, the vendor's packet, a value hidden from
 * the optimiser, and the checks of user_tu_values.c that main() runs.
 * Include after xfgcu/xfgcu.h.
 */
#ifndef XFGCU_MATRIX_USER_TU_H
#define XFGCU_MATRIX_USER_TU_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

extern int utu_checks;
extern int utu_failures;

#define CHECK(cond)                                                                                                    \
    do {                                                                                                               \
        utu_checks++;                                                                                                  \
        if (!(cond)) {                                                                                                 \
            utu_failures++;                                                                                            \
            fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, #cond);                                   \
        }                                                                                                              \
    } while (0)

/* v, read through a volatile 0 at run time: hides sizes and values from the
 * optimiser, so that both the constant-folded and the opaque forms of each
 * call are built. */
size_t hide(size_t v);

/* The vendor's appendix-1 host packet (docs/protocol.md §9.1), CRC E9 D4. */
extern const uint8_t vendor_packet[72];

/* user_tu_values.c: the calls on values and tables */
void test_strerror(void);
void test_bytes(void);
void test_protocol(void);
void test_order_table(void);
void test_names(void);
void test_command_get_set(void);
void test_command_check(void);
void test_units(void);
void test_wire_fields(void);

#endif
