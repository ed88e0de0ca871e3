"""The native library (libxfgcu_py.so) through ctypes, and its flat C API (python/native/xfpy.h).

Found, in this order: the file named by the environment variable XFGCU_PY_LIB; the copy that
`pip install` put inside this package; ``ctypes.util.find_library("xfgcu_py")``.

The tables the package checks arguments against (settings, limits, commands' arguments, fields)
are read from the library here, once: the ranges and units live in C only.
"""

from __future__ import annotations

import ctypes
import ctypes.util
import functools
import os
import warnings
from dataclasses import dataclass
from typing import Any, Callable, Dict, List, Optional, Tuple, TypeVar

__all__ = [
    "lib",
    "messages",
    "report",
    "PACKET_MAX",
    "MESSAGES_MAX",
    "Owned",
    "Option",
    "Field",
    "settings",
    "limits",
    "command_options",
    "fields",
    "json_buffer_call",
]

PACKET_MAX = 255  # XF_PACKET_MAX_LEN: a buffer that holds any packet
MESSAGES_MAX = 4096  # the buffer a call writes its notes and error into


def _load() -> ctypes.CDLL:
    here = os.path.dirname(os.path.abspath(__file__))
    candidates = []
    env = os.environ.get("XFGCU_PY_LIB")
    if env:
        candidates.append(env)
    candidates.append(os.path.join(here, "libxfgcu_py.so"))
    found = ctypes.util.find_library("xfgcu_py")
    if found:
        candidates.append(found)
    errors = []
    for path in candidates:
        if path != env and not os.path.exists(path) and os.sep in path:
            continue
        try:
            return ctypes.CDLL(path)
        except OSError as exc:
            errors.append(f"{path}: {exc}")
    raise ImportError(
        "xfgcu: the native library libxfgcu_py.so was not found (install the package with pip, "
        "or set XFGCU_PY_LIB to the file a CMake build with -DXFGCU_BUILD_PYTHON=ON made)"
        + ("; " + "; ".join(errors) if errors else "")
    )


lib = _load()

_c = ctypes
_vp = _c.c_void_p
_sz = _c.c_size_t
_ll = _c.c_longlong
_charpp = _c.POINTER(_c.c_char_p)
_intp = _c.POINTER(_c.c_int)
_dblp = _c.POINTER(_c.c_double)
_llp = _c.POINTER(_c.c_longlong)

_PROTOTYPES: Dict[str, Tuple[Any, List[Any]]] = {
    "xfpy_version": (_c.c_char_p, []),
    "xfpy_decode": (_c.c_int, [_c.c_char_p, _sz, _c.c_int, _c.c_int, _c.c_char_p, _sz]),
    "xfpy_encode": (_c.c_int, [_c.c_char_p, _c.c_int, _c.c_int, _c.c_char_p, _sz, _c.POINTER(_sz), _c.c_char_p, _sz]),
    "xfpy_command": (
        _c.c_int,
        [_c.c_char_p, _c.c_int, _charpp, _charpp, _c.c_int, _c.c_char_p, _sz, _c.POINTER(_sz), _c.c_char_p, _sz],
    ),
    "xfpy_order_code": (_c.c_int, [_c.c_char_p]),
    "xfpy_model_name": (_c.c_char_p, [_c.c_int]),
    "xfpy_command_names": (_c.c_int, [_c.c_char_p, _sz]),
    "xfpy_command_option": (
        _c.c_int,
        [_c.c_char_p, _sz, _charpp, _c.POINTER(_c.c_uint), _intp, _charpp, _intp, _dblp, _dblp, _charpp, _charpp],
    ),
    "xfpy_field_at": (_c.c_int, [_c.c_int, _sz, _charpp, _charpp, _charpp, _intp, _intp]),
    "xfpy_setting_at": (_c.c_int, [_c.c_int, _sz, _charpp, _llp, _llp]),
    "xfpy_limit_at": (_c.c_int, [_sz, _charpp, _dblp, _dblp, _intp]),
    "xfpy_parser_new": (_vp, []),
    "xfpy_parser_free": (None, [_vp]),
    "xfpy_parser_feed": (_c.c_long, [_vp, _c.c_char_p, _sz, _c.c_char_p, _sz]),
    "xfpy_wait": (None, [_c.c_int, _c.c_int]),
    "xfpy_client_new": (_vp, []),
    "xfpy_client_config": (_c.c_int, [_vp, _c.c_char_p, _ll]),
    "xfpy_client_config_get": (_ll, [_vp, _c.c_char_p]),
    "xfpy_client_config_problem": (_c.c_char_p, [_vp]),
    "xfpy_client_open": (_c.c_int, [_vp, _c.c_char_p, _c.c_char_p, _sz]),
    "xfpy_client_step": (_c.c_int, [_vp, _intp]),
    "xfpy_client_replies": (_c.c_uint32, [_vp]),
    "xfpy_client_settled": (_c.c_int, [_vp]),
    "xfpy_client_telemetry": (_c.c_int, [_vp, _c.c_uint32, _c.c_int, _c.c_char_p, _sz]),
    "xfpy_client_health": (_c.c_int, [_vp, _c.c_char_p, _sz]),
    "xfpy_client_last_sent": (_c.c_int, [_vp, _c.c_char_p, _sz]),
    "xfpy_client_rate_limit": (_c.c_double, [_vp]),
    "xfpy_client_set_main_camera": (None, [_vp, _c.c_int]),
    "xfpy_client_submit": (
        _c.c_int,
        [_vp, _c.c_char_p, _c.c_int, _charpp, _charpp, _c.c_int, _c.POINTER(_c.c_uint32), _c.c_char_p, _sz],
    ),
    "xfpy_client_result": (
        _c.c_int,
        [_vp, _c.c_uint32, _intp, _intp, _c.POINTER(_c.c_long), _intp],
    ),
    "xfpy_client_cancel_all": (None, [_vp]),
    "xfpy_client_set_rates": (_c.c_int, [_vp, _c.c_double, _c.c_double, _c.c_double]),
    "xfpy_client_set_angles": (_c.c_int, [_vp, _c.c_double, _c.c_double, _c.c_double]),
    "xfpy_client_clear_control": (None, [_vp]),
    "xfpy_client_set_carrier": (None, [_vp, _dblp]),
    "xfpy_client_set_gnss": (
        None,
        [_vp, _c.c_double, _c.c_double, _c.c_double, _c.c_int, _c.c_int, _c.c_long, _c.c_double],
    ),
    "xfpy_client_describe": (_c.c_char_p, [_vp]),
    "xfpy_client_free": (None, [_vp]),
    "xfpy_sim_new": (_vp, []),
    "xfpy_sim_config": (_c.c_int, [_vp, _c.c_char_p, _ll]),
    "xfpy_sim_config_get": (_ll, [_vp, _c.c_char_p]),
    "xfpy_sim_fault": (_c.c_int, [_vp, _c.c_char_p, _ll]),
    "xfpy_sim_fault_get": (_ll, [_vp, _c.c_char_p]),
    "xfpy_sim_fail": (None, [_vp, _c.c_int, _c.c_int]),
    "xfpy_sim_open": (_c.c_int, [_vp, _c.c_char_p, _c.c_char_p, _c.c_int, _c.c_char_p, _sz]),
    "xfpy_sim_spec": (_c.c_char_p, [_vp]),
    "xfpy_sim_step": (_c.c_int, [_vp, _intp]),
    "xfpy_sim_stats": (_c.c_int, [_vp, _c.c_char_p, _sz]),
    "xfpy_sim_notes": (_c.c_int, [_vp, _c.c_char_p, _sz]),
    "xfpy_sim_disconnect": (None, [_vp, _c.c_long]),
    "xfpy_sim_free": (None, [_vp]),
}

for _name, (_res, _args) in _PROTOTYPES.items():
    _f = getattr(lib, _name)
    _f.restype = _res
    _f.argtypes = _args


def messages() -> "ctypes.Array[ctypes.c_char]":
    """A buffer for the messages of one call (the library keeps no messages of its own)."""
    return ctypes.create_string_buffer(MESSAGES_MAX)


def report(
    buf: "ctypes.Array[ctypes.c_char]", stacklevel: int = 3, words: Optional[Callable[[str], str]] = None
) -> str:
    """The failure of a call's messages ("" when none), after issuing its notes as warnings
    (``stacklevel``: the caller's, as warnings.warn counts), each message put in Python's
    ``words`` first."""
    error = ""
    for line in buf.value.decode("utf-8", "replace").splitlines():
        text = line.split(": ", 1)[1] if ": " in line else line
        if words is not None:
            text = words(text)
        if line.startswith("note: "):
            warnings.warn(text, stacklevel=stacklevel)
        elif line.startswith("error: "):
            error = text
    return error


def json_buffer_call(fn: Any, *args: Any) -> Optional[bytes]:
    """The text a ``fn(*args, out, cap)`` of the API writes (0: done, > 0: the size it needs,
    < 0: none), or None."""
    size = 8192
    while True:
        out = ctypes.create_string_buffer(size)
        rc = int(fn(*args, out, size))
        if rc == 0:
            return out.value
        if rc < 0:
            return None
        size = rc


def _text(p: Optional[bytes]) -> str:
    return "" if p is None else p.decode()


# ---- the tables ------------------------------------------------------------------------


@functools.lru_cache(maxsize=None)
def settings(table: int) -> Dict[str, Tuple[int, int]]:
    """Setting table ``table`` (0 the client's configuration, 1 the simulator's, 2 its faults):
    {name: (lowest, highest)}, in the library's order."""
    out: Dict[str, Tuple[int, int]] = {}
    name, lo, hi = ctypes.c_char_p(), ctypes.c_longlong(), ctypes.c_longlong()
    i = 0
    while lib.xfpy_setting_at(table, i, ctypes.byref(name), ctypes.byref(lo), ctypes.byref(hi)):
        out[_text(name.value)] = (lo.value, hi.value)
        i += 1
    return out


@functools.lru_cache(maxsize=None)
def limits() -> Dict[str, Tuple[float, float, bool]]:
    """The setters' arguments: {"set_angles.pitch": (lowest, highest, wraps), ...}."""
    out: Dict[str, Tuple[float, float, bool]] = {}
    name, lo, hi, wraps = ctypes.c_char_p(), ctypes.c_double(), ctypes.c_double(), ctypes.c_int()
    i = 0
    while lib.xfpy_limit_at(i, ctypes.byref(name), ctypes.byref(lo), ctypes.byref(hi), ctypes.byref(wraps)):
        out[_text(name.value)] = (lo.value, hi.value, bool(wraps.value))
        i += 1
    return out


@dataclass(frozen=True)
class Option:
    """One argument of a command, as the library takes it."""

    name: str  #: the keyword ("factor")
    values: int  #: 0: a switch (True); 1: one value; 2 or 4: a tuple of that many ints
    real: bool  #: a number (int or float); else ints, a word or the cameras
    words: Tuple[str, ...]  #: the words it takes, or ()
    cameras: bool  #: the cameras: a mask (int), camera numbers (list) or the program's text
    lo: float
    hi: float
    field: str  #: the xf_command member it sets (the first of several)
    help: str


@functools.lru_cache(maxsize=None)
def command_options(name: str) -> Optional[Dict[str, Option]]:
    """Command ``name``'s arguments by keyword, or None when there is no such command."""
    out: Dict[str, Option] = {}
    arg, words, field, help_ = ctypes.c_char_p(), ctypes.c_char_p(), ctypes.c_char_p(), ctypes.c_char_p()
    values, real, cameras = ctypes.c_uint(), ctypes.c_int(), ctypes.c_int()
    lo, hi = ctypes.c_double(), ctypes.c_double()
    i = 0
    while True:
        rc = lib.xfpy_command_option(
            name.encode(), i, ctypes.byref(arg), ctypes.byref(values), ctypes.byref(real), ctypes.byref(words),
            ctypes.byref(cameras), ctypes.byref(lo), ctypes.byref(hi), ctypes.byref(field), ctypes.byref(help_),
        )  # fmt: skip
        if rc < 0:
            return None
        if rc == 0:
            return out
        word_text = _text(words.value)
        out[_text(arg.value)] = Option(
            _text(arg.value), values.value, bool(real.value), tuple(word_text.split("|")) if word_text else (),
            bool(cameras.value), lo.value, hi.value, _text(field.value), _text(help_.value),
        )  # fmt: skip
        i += 1


@dataclass(frozen=True)
class Field:
    """A row of the library's field table (include/xfgcu/xf_fields.h)."""

    name: str
    unit: str  #: "deg", "deg/s", "m", "x", ...; "" for a plain number or a code
    meaning: str
    kind: int  #: xf_wire_kind: 0 a quantity, 1 a number without unit, 2 a code, 3 flags, 4 a byte, 5 reserved
    since: int  #: the first protocol version that has it


@functools.lru_cache(maxsize=None)
def fields(group: int) -> Tuple[Field, ...]:
    """The rows of a group of the field table (0 the packet's own bytes, 1 the host's frames,
    2 the GCU's frames, 3 the commands' parameters)."""
    out: List[Field] = []
    name, unit, meaning = ctypes.c_char_p(), ctypes.c_char_p(), ctypes.c_char_p()
    kind, since = ctypes.c_int(), ctypes.c_int()
    i = 0
    while lib.xfpy_field_at(
        group, i, ctypes.byref(name), ctypes.byref(unit), ctypes.byref(meaning), ctypes.byref(kind),
        ctypes.byref(since),
    ):  # fmt: skip
        out.append(Field(_text(name.value), _text(unit.value), _text(meaning.value), kind.value, since.value))
        i += 1
    return tuple(out)


_T = TypeVar("_T", bound="Owned")


class Owned:
    """What owns a native handle: ``with`` closes it, and so does the garbage collector, quietly
    (a subclass defines ``close()``, which must be safe to call more than once)."""

    def close(self) -> None:  # pragma: no cover - every subclass defines it
        raise NotImplementedError

    def __enter__(self: _T) -> _T:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def __del__(self) -> None:
        try:
            self.close()
        except Exception:
            pass
