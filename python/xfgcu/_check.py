"""Arguments checked before any call into the library: the type Python expects, then the range
(the C type's and the protocol's, read from the library's tables), with a message that names the
function and the parameter: ``zoom_to: factor=300 is out of range 1.0..3276.8``."""

from __future__ import annotations

import ctypes
import math
import numbers
import operator
import re
import threading
from typing import Any, Dict, List, Mapping, Optional, Sequence, Tuple

from . import _native
from .errors import CommandError

__all__ = [
    "integer",
    "real",
    "text",
    "flag",
    "timeout",
    "setting",
    "limited",
    "payload",
    "command_args",
    "native_args",
    "pythonic",
]


def _range(lo: float, hi: float, whole: bool) -> str:
    return f"{int(lo)}..{int(hi)}" if whole else f"{float(lo)!r}..{float(hi)!r}"


def integer(where: str, name: str, value: object, lo: int, hi: int) -> int:
    """``value`` as an int in [lo, hi]: an int (not a bool, not a float), else TypeError;
    outside, ValueError."""
    if isinstance(value, bool):
        raise TypeError(f"{where}: {name} must be an int, not bool")
    try:
        v = operator.index(value)  # type: ignore[arg-type]
    except TypeError:
        raise TypeError(f"{where}: {name} must be an int, not {type(value).__name__}") from None
    if not lo <= v <= hi:
        raise ValueError(f"{where}: {name}={v!r} is out of range {lo}..{hi}")
    return v


def real(where: str, name: str, value: object, lo: float = -math.inf, hi: float = math.inf) -> float:
    """``value`` as a finite float in [lo, hi]: an int or a float (not a bool), else TypeError;
    NaN, an infinity or outside, ValueError."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise TypeError(f"{where}: {name} must be a number, not {type(value).__name__}")
    try:
        v = float(value)
    except OverflowError:  # an int too large for a float
        v = math.inf if value > 0 else -math.inf  # type: ignore[operator]
        if math.isinf(lo) and math.isinf(hi):
            raise ValueError(f"{where}: {name}={value!r} is too large for a float") from None
    if math.isnan(v) or (math.isinf(v) and isinstance(value, float)):
        raise ValueError(f"{where}: {name}={value!r} is not a finite number")
    if not lo <= v <= hi:
        raise ValueError(f"{where}: {name}={value!r} is out of range {_range(lo, hi, False)}")
    return v


def text(where: str, name: str, value: object) -> str:
    """``value`` as a str without NUL (which would end it early in C)."""
    if not isinstance(value, str):
        raise TypeError(f"{where}: {name} must be a str, not {type(value).__name__}")
    if "\0" in value:
        raise ValueError(f"{where}: {name}={value!r} holds a NUL character")
    return value


def flag(where: str, name: str, value: object) -> bool:
    """``value`` as a bool: True, False (or 1, 0)."""
    if isinstance(value, bool):
        return value
    if isinstance(value, int) and value in (0, 1):
        return bool(value)
    raise TypeError(f"{where}: {name} must be True or False, not {value!r}")


def timeout(where: str, name: str, value: object, none_ok: bool = True) -> Optional[float]:
    """A timeout in seconds: None (when ``none_ok``: no limit) or a finite number >= 0."""
    if value is None and none_ok:
        return None
    return real(where, name, value, 0.0, threading.TIMEOUT_MAX)


def setting(where: str, table: int, name: str, value: object) -> int:
    """A value of setting ``name`` of the library's table ``table`` (0 client, 1 simulator,
    2 faults), within the range the library takes."""
    lo, hi = _native.settings(table)[name]
    return integer(where, name, value, lo, hi)


def limited(setter: str, name: str, value: object) -> float:
    """Argument ``name`` of ``setter``, within the range the library's conversion keeps exact."""
    lo, hi, _ = _native.limits()[f"{setter}.{name}"]
    return real(setter, name, value, lo, hi)


def payload(where: str, name: str, value: object) -> bytes:
    """Bytes given as bytes, bytearray or memoryview (not a str, not an int: bytes(5) is five
    zero bytes)."""
    if isinstance(value, (bytes, bytearray, memoryview)):
        return bytes(value)
    raise TypeError(f"{where}: {name} must be bytes, bytearray or memoryview, not {type(value).__name__}")


# ---- a command's arguments ----------------------------------------------------------------


def _command(where: str, name: object) -> Tuple[str, Dict[str, _native.Option]]:
    name = text(where, "name", name)
    options = _native.command_options(name) if name else None
    if options is None:
        raise CommandError(f"{where}: {name!r} is not a command (xfgcu.commands() lists them)")
    return name.replace("-", "_"), options


def _ints(where: str, key: str, value: object, option: _native.Option) -> str:
    if not isinstance(value, (tuple, list)) or len(value) != option.values:
        raise TypeError(f"{where}: {key} must be a tuple of {option.values} ints, not {value!r}")
    items = [integer(where, f"{key}[{i}]", v, int(option.lo), int(option.hi)) for i, v in enumerate(value)]
    return ",".join(str(v) for v in items)


def _cameras(where: str, value: object, option: _native.Option) -> str:
    if isinstance(value, str):
        return text(where, "cameras", value)  # the program's syntax: "1,2", "0x03", "all"
    if isinstance(value, (list, tuple)):
        numbers_ = [integer(where, f"cameras[{i}]", v, 0, 2**31 - 1) for i, v in enumerate(value)]
        return ",".join(str(v) for v in numbers_)  # each camera's own range: the library's check
    return f"0x{integer(where, 'cameras', value, int(option.lo), int(option.hi)):02X}"


def _value(where: str, key: str, value: object, option: _native.Option) -> Optional[str]:
    """The text the library takes for one argument (None: a switch)."""
    if option.values == 0:
        if value is not True:
            raise TypeError(f"{where}: {key} is a switch: give {key}=True, not {value!r}")
        return None
    if option.cameras:
        return _cameras(where, value, option)
    if option.words:
        word = text(where, key, value)
        if word not in option.words:
            raise CommandError(f"{where}: {key}={word!r} is not one of {', '.join(option.words)}")
        return word
    if option.values > 1:
        return _ints(where, key, value, option)
    if option.real:
        try:
            v = real(where, key, value, option.lo, option.hi)
        except ValueError as exc:
            raise CommandError(str(exc)) from None
        return repr(v)
    try:
        return str(integer(where, key, value, int(option.lo), int(option.hi)))
    except ValueError as exc:
        raise CommandError(str(exc)) from None


def command_args(
    where: str, name: object, args: Mapping[str, Any]
) -> Tuple[str, str, List[bytes], List[Optional[bytes]]]:
    """A command and its keyword arguments, checked for ``where`` (the function: "send"): (the
    name given, the name as Python says it ("zoom_to"), the argument names and their values as
    the library takes them). An argument of None, or a switch of False, is left out."""
    shown, options = _command(where, name)
    names: List[bytes] = []
    values: List[Optional[bytes]] = []
    for key, value in args.items():
        key = text(shown, "argument name", key)
        option = options.get(key)
        if option is None:
            known = ", ".join(options) if options else "none"
            raise TypeError(f"{shown}: unexpected argument {key!r} (it takes: {known})")
        if value is None or (value is False and option.values == 0):
            continue
        given = _value(shown, key, value, option)
        names.append(key.encode())
        values.append(None if given is None else given.encode())
    return str(name), shown, names, values


def native_args(
    names: Sequence[bytes], values: Sequence[Optional[bytes]]
) -> Tuple[int, "Any", "Any"]:
    """The argument lists as ctypes arrays."""
    n = len(names)
    return n, (ctypes.c_char_p * max(1, n))(*names), (ctypes.c_char_p * max(1, n))(*values)


_OPTION = re.compile(r"--([a-z][a-z0-9-]*)(?: (?!--)([^\s:;]+))?")
_META = re.compile(r"^[A-Z][A-Z0-9]*(,[A-Z][A-Z0-9]*)*$")  # a value's placeholder: X, N, X0,Y0,X1,Y1


def pythonic(message: str, given: str, shown: str, values: Mapping[bytes, Optional[bytes]]) -> str:
    """A message of the library's text layer in Python's words: the command as Python names it
    (``shown``), ``factor=5.5`` for ``--factor 5.5`` (``values``: what each argument was given
    as), ``start=True`` for the switch ``--start``, a bare name where no value follows."""
    dashed = re.escape(given.replace("_", "-"))
    message = re.sub(rf"(?<![\w-])({dashed}|{re.escape(given)})(?![\w-])", shown, message)  # the command's name
    message = re.sub(r"--protocol (\d)", r"protocol=\1", message)
    options = _native.command_options(given) or {}

    def word(m: "re.Match[str]") -> str:
        key, after = m.group(1).replace("-", "_"), m.group(2)
        option = options.get(key)
        sent = values.get(key.encode())
        if after is not None and ((sent is not None and after == sent.decode()) or _META.match(after)):
            return f"{key}={after}"  # the value given, or the placeholder of one
        rest = f" {after}" if after is not None else ""
        return (f"{key}=True" if option is not None and option.values == 0 else key) + rest

    return _OPTION.sub(word, message)
