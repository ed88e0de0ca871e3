#!/usr/bin/env python3
"""Print the constant tables of include/xfgcu/xf_crc.h used by the parser's memo.

G = x^16 + x^12 + x^5 + 1 (CRC-16/XMODEM). x is invertible mod G, since
x * (x^15 + x^11 + x^4) = G + 1, so negative powers of x exist.

  norm[s]  s = 0..15: for each byte b, b * x^(16 - 8s) mod G, split in two
           nibble tables (low nibble, then high nibble: 32 entries per s), so
           that one byte costs two lookups. s is the stream position after
           the byte, mod 16.
  norm8[s] the same as one table of 256 entries per s (8 KB, one lookup a
           byte), for builds with XF_CRC_TABLE_256.
  x128k[k] k = 0..16: the nibble multiples of x^(128k) mod G as
           xf__crc_mul_tab wants them: [i][n] = (n * x^(4i)) * x^(128k) mod G.

Usage: scripts/gen_crc_tables.py norm|norm8|x128k (the C initialiser on stdout).
tests/test_crc.c recomputes every entry bit by bit.
"""
import sys

G = 0x11021
X_INV = 0x8810  # x^15 + x^11 + x^4


def mulmod(a, b):
    r = 0
    while b:
        if b & 1:
            r ^= a
        b >>= 1
        a <<= 1
        if a & 0x10000:
            a ^= G
    return r


def xpow(e):
    base = 2 if e >= 0 else X_INV
    r = 1
    for _ in range(abs(e)):
        r = mulmod(r, base)
    return r


def row(values):
    """One braced row, which clang-format packs (no trailing comma inside)."""
    return "        {" + ", ".join("0x%04X" % v for v in values) + "},"


def main():
    assert mulmod(2, X_INV) == 1
    what = sys.argv[1] if len(sys.argv) > 1 else ""
    if what == "norm":
        for s in range(16):
            c = xpow(16 - 8 * s)
            lo = [mulmod(n, c) for n in range(16)]
            hi = [mulmod(n << 4, c) for n in range(16)]
            print("        /* s = %d: b * x^(%d) */" % (s, 16 - 8 * s))
            print(row(lo + hi))
    elif what == "norm8":
        for s in range(16):
            c = xpow(16 - 8 * s)
            print("        /* s = %d: b * x^(%d) */" % (s, 16 - 8 * s))
            print(row([mulmod(b, c) for b in range(256)]))
    elif what == "x128k":
        for k in range(17):
            c = xpow(128 * k)
            print("        { /* x^(128 * %d) */" % k)
            for i in range(4):
                print("            {" + ", ".join("0x%04X" % mulmod(n << (4 * i), c) for n in range(16)) + "},")
            print("        },")
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main()
