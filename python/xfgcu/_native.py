"""The native library (libxfgcu_py.so) through ctypes, and its flat C API (python/native/xfpy.h).

Found, in this order: the file named by the environment variable XFGCU_PY_LIB; the copy that
`pip install` put inside this package; ``ctypes.util.find_library("xfgcu_py")``.
"""

from __future__ import annotations

import ctypes
import ctypes.util
import os
import warnings
from typing import Any, Dict, List, Tuple, TypeVar

__all__ = ["lib", "messages", "report", "named_args", "PACKET_MAX", "MESSAGES_MAX"]

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
_u8p = _c.POINTER(_c.c_uint8)
_charpp = _c.POINTER(_c.c_char_p)

_PROTOTYPES = {
    "xfpy_version": (_c.c_char_p, []),
    "xfpy_decode": (_c.c_int, [_c.c_char_p, _sz, _c.c_int, _c.c_int, _c.c_char_p, _sz]),
    "xfpy_encode": (_c.c_int, [_c.c_char_p, _c.c_int, _c.c_int, _c.c_char_p, _sz, _c.POINTER(_sz), _c.c_char_p, _sz]),
    "xfpy_command": (
        _c.c_int,
        [_c.c_char_p, _c.c_int, _charpp, _charpp, _c.c_int, _c.c_char_p, _sz, _c.POINTER(_sz), _c.c_char_p, _sz],
    ),
    "xfpy_model_name": (_c.c_char_p, [_c.c_int]),
    "xfpy_command_names": (_c.c_int, [_c.c_char_p, _sz]),
    "xfpy_parser_new": (_vp, []),
    "xfpy_parser_free": (None, [_vp]),
    "xfpy_parser_feed": (_c.c_long, [_vp, _c.c_char_p, _sz, _c.c_char_p, _sz]),
    "xfpy_wait": (None, [_c.c_int, _c.c_int]),
    "xfpy_client_new": (_vp, []),
    "xfpy_client_config": (_c.c_int, [_vp, _c.c_char_p, _c.c_long]),
    "xfpy_client_config_problem": (_c.c_char_p, [_vp]),
    "xfpy_client_open": (_c.c_int, [_vp, _c.c_char_p, _c.c_char_p, _sz]),
    "xfpy_client_step": (_c.c_int, [_vp, _c.POINTER(_c.c_int)]),
    "xfpy_client_replies": (_c.c_uint32, [_vp]),
    "xfpy_client_settled": (_c.c_int, [_vp]),
    "xfpy_client_telemetry": (_c.c_int, [_vp, _c.c_uint32, _c.c_int, _c.c_char_p, _sz]),
    "xfpy_client_health": (_c.c_int, [_vp, _c.c_char_p, _sz]),
    "xfpy_client_submit": (
        _c.c_int,
        [_vp, _c.c_char_p, _c.c_int, _charpp, _charpp, _c.c_int, _c.POINTER(_c.c_uint32), _c.c_char_p, _sz],
    ),
    "xfpy_client_result": (
        _c.c_int,
        [_vp, _c.c_uint32, _c.POINTER(_c.c_int), _c.POINTER(_c.c_int), _c.POINTER(_c.c_long), _c.POINTER(_c.c_int)],
    ),
    "xfpy_client_cancel_all": (None, [_vp]),
    "xfpy_client_set_rates": (_c.c_int, [_vp, _c.c_double, _c.c_double, _c.c_double]),
    "xfpy_client_set_angles": (_c.c_int, [_vp, _c.c_double, _c.c_double, _c.c_double]),
    "xfpy_client_clear_control": (None, [_vp]),
    "xfpy_client_set_carrier": (None, [_vp, _c.POINTER(_c.c_double)]),
    "xfpy_client_set_gnss": (
        None,
        [_vp, _c.c_double, _c.c_double, _c.c_double, _c.c_int, _c.c_int, _c.c_long, _c.c_double],
    ),
    "xfpy_client_describe": (_c.c_char_p, [_vp]),
    "xfpy_client_free": (None, [_vp]),
    "xfpy_sim_new": (_vp, []),
    "xfpy_sim_config": (_c.c_int, [_vp, _c.c_char_p, _c.c_long]),
    "xfpy_sim_fault": (_c.c_int, [_vp, _c.c_char_p, _c.c_long]),
    "xfpy_sim_fail": (None, [_vp, _c.c_int, _c.c_int]),
    "xfpy_sim_open": (_c.c_int, [_vp, _c.c_char_p, _c.c_char_p, _c.c_int, _c.c_char_p, _sz]),
    "xfpy_sim_spec": (_c.c_char_p, [_vp]),
    "xfpy_sim_step": (_c.c_int, [_vp, _c.POINTER(_c.c_int)]),
    "xfpy_sim_stats": (_c.c_int, [_vp, _c.c_char_p, _sz]),
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


def report(buf: "ctypes.Array[ctypes.c_char]") -> str:
    """The failure of a call's messages ("" when none), after issuing its notes as warnings."""
    error = ""
    for line in buf.value.decode("utf-8", "replace").splitlines():
        if line.startswith("note: "):
            warnings.warn(line[len("note: ") :], stacklevel=3)
        elif line.startswith("error: "):
            error = line[len("error: ") :]
    return error


def _option_value(value: object) -> str:
    if isinstance(value, (list, tuple)):
        return ",".join(_option_value(v) for v in value)
    if isinstance(value, float):
        return repr(value)
    return str(value)


def named_args(args: Dict[str, Any]) -> Tuple[int, "ctypes.Array[ctypes.c_char_p]", "ctypes.Array[ctypes.c_char_p]"]:
    """A command's named arguments as the library takes them: option ``factor=5.5`` is the pair
    ("factor", "5.5"), ``show=True`` the switch ("show", NULL) (False and None: left out), a list
    or a tuple ``box=(0, 0, 10, 10)`` is "0,0,10,10". ``cameras`` takes the program's syntax as a
    string ("1,2", "0x03", "all"), a list of camera numbers, or an int, which is a mask
    (``cameras=3`` is cameras 1 and 2, as "0x03")."""
    names: List[bytes] = []
    values: List[Any] = []
    for key, value in args.items():
        if value is None or value is False:
            continue
        names.append(key.replace("_", "-").encode())
        if key == "cameras" and isinstance(value, int) and not isinstance(value, bool):
            values.append(f"0x{value:02X}".encode())
        elif value is True:
            values.append(None)
        else:
            values.append(_option_value(value).encode())
    return len(names), (ctypes.c_char_p * max(1, len(names)))(*names), (ctypes.c_char_p * max(1, len(values)))(*values)


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
