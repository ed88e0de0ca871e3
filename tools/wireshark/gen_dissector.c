/*
 * gen_dissector.c - writes the Wireshark dissector tools/wireshark/xfgcu.lua
 * from its template (xfgcu.lua.in) and the codec's own tables.
 *
 *     gen_dissector TEMPLATE OUTPUT
 *     gen_dissector --check TEMPLATE FILE
 *
 * The template holds the dissector's logic; the line "-- @TABLES@" in it is
 * replaced by Lua tables built here from what the program itself uses: the
 * codec's field table (include/xfgcu/xf_fields.h: every field's name, place,
 * width, sign, step per version, unit, the version that brought it, the
 * names of its values or bits, its one line of meaning), the codec's order
 * table (names, versions, flags, parameter members), the header bytes, ports
 * and length limits. So the dissector cannot name, place, scale or label a
 * field differently from `xfgcu decode --json`: a ctest test regenerates the
 * file and fails when the committed one differs.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fieldtext.h"
#include "xfgcu/posix/xf_posix.h" /* the ports (macros only: nothing of the links is linked) */
#include "xfgcu/xfgcu.h"

#define MARKER "-- @TABLES@"

/* A Lua string literal: quotes, backslashes and control bytes escaped (UTF-8 passes through). */
static void lua_string(FILE *out, const char *s)
{
    fputc('"', out);
    for (; *s != '\0'; s++) {
        unsigned char c = (unsigned char)*s;
        if (c == '"' || c == '\\') {
            fprintf(out, "\\%c", c);
        } else if (c < 0x20u) {
            fprintf(out, "\\%03u", (unsigned)c);
        } else {
            fputc(c, out);
        }
    }
    fputc('"', out);
}

static const char *kind_name(uint8_t kind)
{
    static const char *const names[] = {"number", "context", "enum", "flags", "byte", "reserved"};
    return kind < sizeof(names) / sizeof(names[0]) ? names[kind] : "number";
}

/* The named bits of a flag word: {mask = 0x0001, name = "...", meaning = "..."}, ... */
static void emit_bits(FILE *out, const xf_wire_field *f)
{
    unsigned k;
    fputs(", bits = {\n", out);
    for (k = 0; k < f->nbits; k++) {
        fprintf(out, "        {mask = 0x%04X, name = ", (unsigned)f->bits[k].mask);
        lua_string(out, f->bits[k].name);
        fputs(", meaning = ", out);
        lua_string(out, f->bits[k].meaning);
        fputs("},\n", out);
    }
    fputs("     }", out);
}

/* One row of the field table as a Lua table. */
static void emit_row(FILE *out, const xf_wire_field *f)
{
    fputs("    {name = ", out);
    lua_string(out, f->name);
    fprintf(out, ", offset = %u, size = %u, signed = %s, kind = \"%s\", decimals = {%u, %u}, since = %u, hex = %s",
            (unsigned)f->offset, (unsigned)f->width, f->is_signed ? "true" : "false", kind_name(f->kind),
            xf_wire_field_decimals(f, XF_PROTOCOL_V1), xf_wire_field_decimals(f, XF_PROTOCOL_V2), (unsigned)f->since,
            fieldtext_hex(f) ? "true" : "false");
    fputs(",\n     unit = ", out);
    lua_string(out, f->unit);
    fputs(", meaning = ", out);
    lua_string(out, f->meaning);
    if (f->nbits > 0u) {
        emit_bits(out, f);
    }
    fputs("},\n", out);
}

static void emit_rows(FILE *out, const char *var, xf_wire_group group)
{
    size_t i, n;
    const xf_wire_field *rows = xf_wire_fields(group, &n);
    fprintf(out, "local %s = {\n", var);
    for (i = 0; i < n; i++) {
        emit_row(out, &rows[i]);
    }
    fputs("}\n\n", out);
}

/* The names of the values of every code field (order, gimbal_mode, gimbal_code), by field name,
 * from the codec's own name functions. */
static void emit_value_names(FILE *out)
{
    static const xf_wire_group groups[] = {XF_WIRE_PACKET, XF_WIRE_HOST, XF_WIRE_GCU, XF_WIRE_PARAMS};
    size_t g, i, n;
    unsigned v;
    fputs("-- the names of the values of the code fields, by field\nlocal VALUE_NAMES = {\n", out);
    for (g = 0; g < sizeof(groups) / sizeof(groups[0]); g++) {
        const xf_wire_field *rows = xf_wire_fields(groups[g], &n);
        for (i = 0; i < n; i++) {
            if (rows[i].value_name == NULL) {
                continue;
            }
            fprintf(out, "    %s = {\n", rows[i].name);
            for (v = 0; v < 256u; v++) {
                const char *name = rows[i].value_name((uint8_t)v);
                if (name != NULL) {
                    fprintf(out, "        [0x%02X] = ", v);
                    lua_string(out, name);
                    fputs(",\n", out);
                }
            }
            fputs("    },\n", out);
        }
    }
    fputs("}\n\n", out);
}

static void emit_orders(FILE *out)
{
    size_t i, k;
    fputs("-- order byte -> name, version that brought it, XF_ORDER_* flags, its parameter members in order\n"
          "local ORDERS = {\n",
          out);
    for (i = 0; i < XF_ORDER_COUNT; i++) {
        const xf_order_info *o = xf_order_at(i);
        fprintf(out, "    [0x%02X] = {name = \"%s\", since = %u, flags = %u, params = {", (unsigned)o->order,
                xf_order_name(o->order), (unsigned)o->since, (unsigned)o->flags);
        for (k = 0; k < o->nfields; k++) {
            fprintf(out, "%s\"%s\"", k > 0u ? ", " : "", xf_wire_param((xf_field)o->fields[k])->name);
        }
        fputs("}},\n", out);
    }
    fputs("}\n\n", out);
}

static void emit_constants(FILE *out)
{
    fprintf(out,
            "local HOST_HEADER = {0x%02X, 0x%02X}\n"
            "local GCU_HEADER = {0x%02X, 0x%02X}\n"
            "local OFF_LENGTH, OFF_VERSION, OFF_ORDER, OFF_PARAMS = %u, %u, %u, %u\n"
            "local MIN_LEN, MAX_LEN = %u, %u\n"
            "local PROTOCOL_V1, PROTOCOL_V2 = %u, %u\n"
            "local ORDER_MASK_FAILURE, ORDER_OPERATING = %u, %u\n"
            "local STATE_SUCCESS, STATE_OPERATING = %u, %u\n"
            "local POD_RESERVED_MASK = 0x%04X\n"
            "local GCU_UDP_PORT, HOST_UDP_PORT, GCU_TCP_PORT = %u, %u, %u\n\n",
            XF_HOST_HEADER0, XF_HOST_HEADER1, XF_GCU_HEADER0, XF_GCU_HEADER1, XF_OFF_LENGTH, XF_OFF_VERSION,
            XF_OFF_ORDER, XF_OFF_PARAMS, XF_PACKET_MIN_LEN, XF_PACKET_LIMIT, XF_PROTOCOL_V1, XF_PROTOCOL_V2,
            XF_ORDER_MASK_FAILURE, XF_ORDER_OPERATING, XF_STATE_SUCCESS, XF_STATE_OPERATING, XF_POD_RESERVED_MASK,
            XF_GCU_UDP_PORT, XF_HOST_UDP_PORT, XF_GCU_TCP_PORT);
}

static void emit_tables(FILE *out)
{
    emit_constants(out);
    fputs("-- the field table (include/xfgcu/xf_fields.h): the packet's own bytes, the host's and the GCU's\n"
          "-- frames in wire order, and the parameter members of the orders\n",
          out);
    emit_rows(out, "PACKET_FIELDS", XF_WIRE_PACKET);
    emit_rows(out, "HOST_FIELDS", XF_WIRE_HOST);
    emit_rows(out, "GCU_FIELDS", XF_WIRE_GCU);
    emit_rows(out, "PARAM_FIELDS", XF_WIRE_PARAMS);
    emit_value_names(out);
    emit_orders(out);
}

/* The template with the tables in place of the marker: 0, or 1 when the marker is missing or a
 * read or write failed. */
static int generate(FILE *in, FILE *out)
{
    char line[1024];
    int found = 0;
    fprintf(out, "-- generated by tools/wireshark/gen_dissector.c from tools/wireshark/xfgcu.lua.in: do not edit\n");
    while (fgets(line, sizeof(line), in) != NULL) {
        if (strncmp(line, MARKER, strlen(MARKER)) == 0) {
            emit_tables(out);
            found = 1;
        } else {
            fputs(line, out);
        }
    }
    if (!found) {
        fputs("gen_dissector: no '" MARKER "' line in the template\n", stderr);
    }
    return (!found || ferror(in) || fflush(out) != 0 || ferror(out)) ? 1 : 0;
}

/* Do the two files hold the same bytes? */
static int same_bytes(FILE *a, FILE *b)
{
    int ca, cb;
    rewind(a);
    do {
        ca = getc(a);
        cb = getc(b);
    } while (ca == cb && ca != EOF);
    return ca == cb;
}

/* --check: is the file at @p path what the template gave (@p made)? 0 or 1. */
static int check_against(FILE *made, const char *path, const char *template_path)
{
    FILE *old = fopen(path, "r");
    int rc = 0;
    if (old == NULL || !same_bytes(made, old)) {
        fprintf(stderr,
                "gen_dissector: %s is not what %s and the codec's tables give: regenerate it "
                "(cmake --build BUILD --target wireshark_dissector) and commit it\n",
                path, template_path);
        rc = 1;
    }
    if (old != NULL) {
        fclose(old);
    }
    return rc;
}

int main(int argc, char **argv)
{
    int check = (argc == 4 && strcmp(argv[1], "--check") == 0);
    FILE *in, *out;
    int rc;
    if (argc != 3 && !check) {
        fputs("usage: gen_dissector TEMPLATE OUTPUT\n"
              "       gen_dissector --check TEMPLATE FILE   (is FILE what TEMPLATE gives?)\n",
              stderr);
        return 2;
    }
    in = fopen(argv[1 + check], "r");
    if (in == NULL) {
        perror(argv[1 + check]);
        return 2;
    }
    out = check ? tmpfile() : fopen(argv[2], "w");
    if (out == NULL) {
        perror(check ? "tmpfile" : argv[2]);
        fclose(in);
        return 2;
    }
    rc = generate(in, out);
    fclose(in);
    if (rc == 0 && check) {
        rc = check_against(out, argv[3], argv[2]);
    }
    if (fclose(out) != 0 && rc == 0) {
        fputs("gen_dissector: cannot write the output\n", stderr);
        rc = 1;
    }
    return rc;
}
