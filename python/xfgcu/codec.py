"""Packets to and from the JSON objects of `xfgcu decode --json` / `xfgcu encode --json`,
named commands, and a stream parser: the xfgcu program's own code, through the native library."""

from __future__ import annotations

import ctypes
import json
from typing import Any, Dict, List, Optional

from ._native import PACKET_MAX, lib, messages, named_args, report
from .errors import (
    CRCError,
    DecodeError,
    EncodeError,
    HeaderError,
    LengthError,
    TruncatedError,
)

__all__ = ["decode", "encode", "encode_command", "commands", "Parser"]

# xf_err codes (include/xfgcu/xf_error.h) of the four faults xf_packet_check() reports.
_FAULTS = {
    -10: (HeaderError, "bad header: a packet starts with A8 E5 (host) or 8A 5E (GCU)"),
    -11: (LengthError, "bad length: the length field must be 72..255 and match the bytes"),
    -12: (CRCError, "bad CRC"),
    -13: (TruncatedError, "truncated packet"),
}
_POD = {"auto": 0, "le": 1, "be": 2}


def _fault(data: bytes, code: int) -> DecodeError:
    cls, text = _FAULTS.get(code, (DecodeError, f"not a packet (error {code})"))
    if cls is CRCError and len(data) >= 4:
        field = data[2] | data[3] << 8
        text += f": the packet says {data[field - 2]:02X} {data[field - 1]:02X}"
    elif cls is TruncatedError and len(data) >= 4:
        text += f": {len(data)} bytes, the length field says {data[2] | data[3] << 8}"
    elif cls is TruncatedError:
        text += f": {len(data)} bytes, a packet has at least 72"
    elif cls is HeaderError and len(data) >= 2:
        text += f" (got {data[0]:02X} {data[1]:02X})"
    return cls(text)


def decode(data: bytes, pod_order: str = "auto", raw: bool = False) -> Dict[str, Any]:
    """One whole packet (host or GCU, found from its header) as the object `xfgcu decode --json`
    prints for it: the same keys, in the same order, with the same values: fields in engineering
    units, or as wire integers with ``raw`` (decode --raw).

    ``pod_order`` is decode's ``--pod-order``: how to read the flags of pod_status.
    Raises a DecodeError subclass (HeaderError, LengthError, CRCError, TruncatedError)."""
    data = bytes(data)
    if pod_order not in _POD:
        raise ValueError("pod_order must be 'auto', 'le' or 'be'")
    out = ctypes.create_string_buffer(16384)
    rc = lib.xfpy_decode(data, len(data), _POD[pod_order], int(raw), out, len(out))
    if rc > 0:
        out = ctypes.create_string_buffer(rc)
        rc = lib.xfpy_decode(data, len(data), _POD[pod_order], int(raw), out, len(out))
    if rc != 0:
        raise _fault(data, rc)
    result: Dict[str, Any] = json.loads(out.value.decode())
    return result


def _check_protocol(protocol: int) -> None:
    if protocol not in (1, 2):  # as the program's --protocol: never cut to a byte
        raise EncodeError(f"encode: protocol {protocol!r}: must be 1 or 2")


def encode(obj: Dict[str, Any], protocol: int = 1, raw: bool = False) -> bytes:
    """The packet an object of `xfgcu encode --json` describes (the inverse of decode()), its
    fields in engineering units, or wire integers with ``raw``. ``protocol`` is the version when
    the object gives none. Raises EncodeError."""
    _check_protocol(protocol)
    text = json.dumps(obj).encode()
    out = ctypes.create_string_buffer(PACKET_MAX)
    n = ctypes.c_size_t(0)
    msgs = messages()
    rc = lib.xfpy_encode(text, protocol, int(raw), out, len(out), ctypes.byref(n), msgs, len(msgs))
    message = report(msgs)
    if rc != 0:
        raise EncodeError(message)
    return out.raw[: n.value]


def encode_command(name: str, protocol: int = 1, **args: Any) -> bytes:
    """The packet `xfgcu encode --protocol PROTOCOL NAME --OPTION VALUE ...` prints: the
    program's command names ("zoom-to" or "zoom_to") and option names, ``-`` written ``_``.
    ``encode_command("zoom-to", factor=5.5)`` is ``xfgcu encode zoom-to --factor 5.5``; a switch is
    ``True`` (``osd`` with ``show=True``); a list is a comma list (``box=(0, 0, 100, 100)``).
    Notes (an order of another version) come as warnings. Raises EncodeError."""
    _check_protocol(protocol)
    count, names, values = named_args(args)
    out = ctypes.create_string_buffer(PACKET_MAX)
    n = ctypes.c_size_t(0)
    msgs = messages()
    rc = lib.xfpy_command(name.encode(), count, names, values, protocol, out, len(out), ctypes.byref(n), msgs, len(msgs))
    message = report(msgs)
    if rc != 0:
        raise EncodeError(message)
    return out.raw[: n.value]


def commands() -> List[str]:
    """The command names, as the program spells them."""
    out = ctypes.create_string_buffer(4096)
    size = lib.xfpy_command_names(out, len(out))
    if size > 0:
        out = ctypes.create_string_buffer(size)
        lib.xfpy_command_names(out, len(out))
    return out.value.decode().split()


class Parser:
    """A stream parser: bytes in any chunking, decoded packets out, each from the call that
    feeds its last byte (the codec's xf_parser; noise, bad CRCs and truncated packets are
    skipped). ``direction`` keeps only "host" or "gcu" packets; None (the default) keeps both."""

    def __init__(self, direction: Optional[str] = None) -> None:
        if direction not in (None, "host", "gcu"):
            raise ValueError("direction must be None, 'host' or 'gcu'")
        self._direction = direction
        self._handle = lib.xfpy_parser_new()
        if not self._handle:
            raise MemoryError("xfgcu: parser")

    def __del__(self) -> None:
        handle = getattr(self, "_handle", None)
        if handle:
            lib.xfpy_parser_free(handle)
            self._handle = None

    def feed_packets(self, data: bytes) -> List[bytes]:
        """Like feed(), but the packets' bytes, undecoded."""
        data = bytes(data)
        found: List[tuple] = []
        for at in range(0, len(data), 4096):
            chunk = data[at : at + 4096]
            cap = 2 * (len(chunk) // 72 + 2) * (PACKET_MAX + 6)
            out = ctypes.create_string_buffer(cap)
            n = lib.xfpy_parser_feed(self._handle, chunk, len(chunk), out, cap)
            if n < 0:
                raise RuntimeError("xfgcu: parser output buffer too small")
            raw, i = out.raw, 0
            while i < n:
                end = int.from_bytes(raw[i : i + 4], "little")
                direction, length = raw[i + 4], raw[i + 5]
                found.append((end, direction, raw[i + 6 : i + 6 + length]))
                i += 6 + length
        found.sort(key=lambda f: f[0])  # both directions, in the order they ended in the stream
        want = {None: (0, 1), "host": (0,), "gcu": (1,)}[self._direction]
        return [packet for _, direction, packet in found if direction in want]

    def feed(self, data: bytes) -> List[Dict[str, Any]]:
        """Feed bytes; the packets they complete, decoded as decode() does."""
        return [decode(p) for p in self.feed_packets(data)]
