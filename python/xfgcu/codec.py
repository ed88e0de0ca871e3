"""Packets to and from the JSON objects of `xfgcu decode --json` / `xfgcu encode --json`,
named commands, and a stream parser: the text layer the xfgcu program uses, through the native
library."""

from __future__ import annotations

import ctypes
import json
import math
from typing import Any, Dict, List, Mapping, Optional, Tuple

from . import _check
from ._native import PACKET_MAX, lib, messages, report, settings
from .errors import CommandError, CRCError, DecodeError, EncodeError, HeaderError, LengthError, TruncatedError

__all__ = ["decode", "encode", "encode_command", "commands", "Parser"]

# xf_err codes (include/xfgcu/xf_error.h) of the four faults xf_packet_check() reports.
_FAULTS = {
    -10: (HeaderError, "bad header: a packet starts with A8 E5 (host) or 8A 5E (GCU)"),
    -11: (LengthError, "bad length: the length field must be 72..255 and match the bytes"),
    -12: (CRCError, "bad CRC"),
    -13: (TruncatedError, "truncated packet"),
}
_POD = {"auto": 0, "le": 1, "be": 2}
_DIRECTIONS = {None: (0, 1), "host": (0,), "gcu": (1,)}


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

    ``pod_order`` is decode's ``--pod-order``: how to read the flags of pod_status ("auto",
    "le", "be"). Raises a DecodeError subclass (HeaderError, LengthError, CRCError,
    TruncatedError)."""
    data = _check.payload("decode", "data", data)
    pod = _check.text("decode", "pod_order", pod_order)
    if pod not in _POD:
        raise ValueError(f"decode: pod_order={pod!r} is not one of {', '.join(_POD)}")
    view = int(_check.flag("decode", "raw", raw))
    out = ctypes.create_string_buffer(16384)
    rc = lib.xfpy_decode(data, len(data), _POD[pod], view, out, len(out))
    if rc > 0:
        out = ctypes.create_string_buffer(rc)
        rc = lib.xfpy_decode(data, len(data), _POD[pod], view, out, len(out))
    if rc != 0:
        raise _fault(data, rc)
    result: Dict[str, Any] = json.loads(out.value.decode())
    return result


def _protocol(where: str, protocol: object) -> int:
    lo, hi = settings(0)["protocol_version"]
    return _check.integer(where, "protocol", protocol, lo, hi)


def _plain(where: str, path: str, value: object) -> None:
    """What JSON can carry and the library can read: no NaN, no infinity, no NUL."""
    if isinstance(value, str):
        _check.text(where, path, value)
    elif isinstance(value, float) and not math.isfinite(value):
        raise ValueError(f"{where}: {path}={value!r} is not a finite number")
    elif isinstance(value, Mapping):
        for key, item in value.items():
            if not isinstance(key, str):
                raise TypeError(f"{where}: {path} has a key {key!r} that is not a str")
            _check.text(where, f"{path} key", key)
            _plain(where, f"{path}[{key!r}]", item)
    elif isinstance(value, (list, tuple)):
        for i, item in enumerate(value):
            _plain(where, f"{path}[{i}]", item)
    elif value is not None and not isinstance(value, (bool, int, float)):
        raise TypeError(f"{where}: {path} is a {type(value).__name__}, which JSON cannot carry")


def encode(obj: Mapping[str, Any], protocol: int = 1, raw: bool = False) -> bytes:
    """The packet an object of `xfgcu encode --json` describes (the inverse of decode()), its
    fields in engineering units, or wire integers with ``raw``. ``protocol`` is the version when
    the object gives none. A value between two steps of its field, or out of its range, is
    refused, never rounded. Raises EncodeError (a ValueError) or TypeError."""
    if not isinstance(obj, Mapping):
        raise TypeError(f"encode: obj must be a dict, not {type(obj).__name__}")
    _plain("encode", "obj", obj)
    version = _protocol("encode", protocol)
    view = int(_check.flag("encode", "raw", raw))
    text = json.dumps(dict(obj), allow_nan=False).encode()
    out = ctypes.create_string_buffer(PACKET_MAX)
    n = ctypes.c_size_t(0)
    msgs = messages()
    rc = lib.xfpy_encode(text, version, view, out, len(out), ctypes.byref(n), msgs, len(msgs))
    message = report(msgs)
    if rc != 0:
        raise EncodeError(message)
    return out.raw[: n.value]


def encode_command(name: str, protocol: int = 1, **args: Any) -> bytes:
    """The packet `xfgcu encode --protocol PROTOCOL NAME --OPTION VALUE ...` prints: the
    program's command names ("zoom_to" or "zoom-to") and argument names.
    ``encode_command("zoom_to", factor=5.5)`` is ``xfgcu encode zoom-to --factor 5.5``; a switch is
    ``True`` (``osd`` with ``show=True``); a tuple is a comma list (``box=(0, 0, 100, 100)``);
    ``cameras`` is an int mask (3: cameras 1 and 2), a list of camera numbers, or the program's
    text ("1,2", "0x03", "all"). Notes (an order of another version) come as warnings.
    Raises CommandError (a ValueError) or TypeError, naming the argument."""
    given, shown, names, values = _check.command_args("encode_command", name, args)
    version = _protocol("encode_command", protocol)
    count, c_names, c_values = _check.native_args(names, values)
    out = ctypes.create_string_buffer(PACKET_MAX)
    n = ctypes.c_size_t(0)
    msgs = messages()
    rc = lib.xfpy_command(
        given.encode(), count, c_names, c_values, version, out, len(out), ctypes.byref(n), msgs, len(msgs)
    )
    message = report(msgs, 3, lambda m: _check.pythonic(m, given, shown, dict(zip(names, values))))
    if rc != 0:
        raise CommandError(message)
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
        if direction is not None:
            _check.text("Parser", "direction", direction)
        if direction not in _DIRECTIONS:
            raise ValueError(f"Parser: direction={direction!r} is not None, 'host' or 'gcu'")
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
        data = _check.payload("Parser.feed", "data", data)
        found: List[Tuple[int, int, bytes]] = []
        for at in range(0, len(data), 4096):
            chunk = data[at : at + 4096]
            cap = 2 * (len(chunk) // 72 + 2) * (PACKET_MAX + 6)
            out = ctypes.create_string_buffer(cap)
            n = lib.xfpy_parser_feed(self._handle, chunk, len(chunk), out, cap)
            if n < 0:  # pragma: no cover - the capacity above holds every frame
                raise RuntimeError("xfgcu: parser output buffer too small")
            raw, i = out.raw, 0
            while i < n:
                end = int.from_bytes(raw[i : i + 4], "little")
                direction, length = raw[i + 4], raw[i + 5]
                found.append((end, direction, raw[i + 6 : i + 6 + length]))
                i += 6 + length
        found.sort(key=lambda f: f[0])  # both directions, in the order they ended in the stream
        want = _DIRECTIONS[self._direction]
        return [packet for _, direction, packet in found if direction in want]

    def feed(self, data: bytes) -> List[Dict[str, Any]]:
        """Feed bytes; the packets they complete, decoded as decode() does."""
        return [decode(p) for p in self.feed_packets(data)]
