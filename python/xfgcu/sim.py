"""A simulated GCU in this process (the library's xf_sim on a simulator link), to test an
application without hardware."""

from __future__ import annotations

import ctypes
import json
import threading
from typing import Any, Dict, List, Mapping, Optional, Tuple, Union

from . import _check
from ._native import Owned, json_buffer_call, lib, limits, messages, report, settings
from .errors import ClosedError, LinkError

__all__ = ["Simulator", "model_code"]

_PORTS = (0, 65535)
_DEFAULT_PORT = {"udp": 2337, "tcp": 2332}  # the protocol's ports (docs/protocol.md §1)
# Simulator settings that have a keyword of their own (model, protocol, ...).
_OWN = ("version", "model", "state_once", "main_camera", "answer_only")


def model_code(model: Union[int, str]) -> int:
    """A gimbal model's code from its code (0..255) or its name ("Z-9B_V4(T)")."""
    if isinstance(model, str):
        name = _check.text("model_code", "model", model)
        for code in range(256):
            if lib.xfpy_model_name(code).decode() == name:
                return code
        raise ValueError(f"model_code: unknown gimbal model {name!r}")
    lo, hi = settings(1)["model"]
    return _check.integer("model_code", "model", model, lo, hi)


def _order(where: str, order: object) -> int:
    if isinstance(order, str):
        name = _check.text(where, "fail's order", order)
        code = int(lib.xfpy_order_code(name.encode())) if name else -1
        if code < 0:
            raise ValueError(f"{where}: fail: {name!r} is not an order (xfgcu.commands() lists them)")
        return code
    return _check.integer(where, "fail's order", order, 0, 255)


def _parse_spec(spec: object) -> Tuple[str, str, int]:
    """A simulator's spec as (kind, where, port), checked."""
    spec = _check.text("Simulator", "spec", spec)
    kind, _, rest = spec.partition(":")
    if kind == "pty":
        return kind, rest, 0
    if kind not in _DEFAULT_PORT:
        raise ValueError(f"Simulator: spec {spec!r}: give udp:ADDR:PORT, tcp:ADDR:PORT, pty or pty:LINK")
    host, sep, port_text = rest.rpartition(":")
    if not sep or "]" in port_text:  # no port, or an IPv6 address without one
        host, port = rest, _DEFAULT_PORT[kind]
    elif not port_text.isdigit() or not port_text.isascii():
        raise ValueError(f"Simulator: spec {spec!r}: the port {port_text!r} is not a number {_PORTS[0]}..{_PORTS[1]}")
    else:
        port = int(port_text)
        if not _PORTS[0] <= port <= _PORTS[1]:
            raise ValueError(f"Simulator: spec {spec!r}: port {port} is out of range {_PORTS[0]}..{_PORTS[1]}")
    return kind, host.strip("[]") or "127.0.0.1", port


class Simulator(Owned):
    """A simulated GCU that follows the protocol (the library's simulator: once-rule, feedback,
    attitude by mode, zoom, ranging, tracking), on the GCU's end of a link, stepped by a thread
    this object owns. After close() every call but close() raises ClosedError.

    ``spec``: "udp:ADDR:PORT", "tcp:ADDR:PORT" (PORT 0: any free port; ADDR default
    127.0.0.1), "pty" or "pty:LINK" (a new pseudo-terminal, and a symbolic link LINK to it).
    ``spec`` of the object is then what a client opens: ``xfgcu.connect(sim.spec)``.
    ``model``: the model code or name it reports (default 58, Z-9B_V4(T), which has every order);
    ``protocol``: the version of its replies, 1 or 2, in whose ranges and meanings it reads
    every command; ``answer_only``: 1 or 2 answers only host packets of that version byte, as some
    GCUs do (None: every version); ``state_once``: the execution state comes in the first reply
    after an execution only (72-byte replies to the order's repeats); ``main_camera``: 1 or 2,
    whose zoom scales the rates; ``fail``: {order: state}, executions of the order (name or
    number) answer that state, e.g. {"shutter": 1}. ``options``: the simulator's other settings
    (hw_version, fw_version, calibration_ms, feedback_after, seed) and faults (drop_permille,
    delay_ms, ...: fault())."""

    def __init__(
        self,
        spec: str = "udp:127.0.0.1:0",
        model: Union[int, str] = 58,
        protocol: int = 1,
        fail: Optional[Mapping[Union[int, str], int]] = None,
        *,
        answer_only: Optional[int] = None,
        state_once: bool = False,
        main_camera: int = 1,
        **options: int,
    ) -> None:
        self._handle: Optional[int] = None
        kind, where, port = _parse_spec(spec)
        config = self._config(model, protocol, answer_only, state_once, main_camera, options)
        faults = self._faults({k: v for k, v in options.items() if k in settings(2)})
        failures = self._failures(fail)
        self._lock = threading.Lock()
        self._stop = False
        handle = lib.xfpy_sim_new()
        if not handle:
            raise MemoryError("xfgcu: simulator")
        try:
            for key, value in config.items():
                lib.xfpy_sim_config(handle, key.encode(), value)
            for order, state in failures:
                lib.xfpy_sim_fail(handle, order, state)
            msgs = messages()
            if lib.xfpy_sim_open(handle, kind.encode(), where.encode(), port, msgs, len(msgs)) != 0:
                raise LinkError(report(msgs))
            for key, value in faults.items():  # after the open, which starts the simulator afresh
                lib.xfpy_sim_fault(handle, key.encode(), value)
        except BaseException:
            lib.xfpy_sim_free(handle)
            raise
        self._handle = handle
        self.spec: str = lib.xfpy_sim_spec(handle).decode()
        self._thread = threading.Thread(target=self._run, name="xfgcu-sim", daemon=True)
        self._thread.start()

    @staticmethod
    def _config(
        model: object, protocol: object, answer_only: object, state_once: object, main_camera: object,
        options: Mapping[str, object],
    ) -> Dict[str, int]:  # fmt: skip
        table = settings(1)
        config = {
            "model": model_code(model),  # type: ignore[arg-type]
            "version": _check.integer("Simulator", "protocol", protocol, *table["version"]),
            "state_once": int(_check.flag("Simulator", "state_once", state_once)),
            "main_camera": _check.integer("Simulator", "main_camera", main_camera, *table["main_camera"]),
            "answer_only": 0 if answer_only is None else _check.integer(
                "Simulator", "answer_only", answer_only, max(1, table["answer_only"][0]), table["answer_only"][1]
            ),
        }
        for key, value in options.items():
            if key in _OWN or (key not in table and key not in settings(2)):
                known = [k for k in table if k not in _OWN] + list(settings(2))
                raise TypeError(f"Simulator: unexpected option {key!r} (one of {', '.join(known)})")
            if key in table:
                config[key] = _check.setting("Simulator", 1, key, value)
        return config

    @staticmethod
    def _faults(faults: Mapping[str, object], where: str = "Simulator") -> Dict[str, int]:
        return {key: _check.setting(where, 2, key, value) for key, value in faults.items()}

    @staticmethod
    def _failures(fail: object) -> List[Tuple[int, int]]:
        if fail is None:
            return []
        if not isinstance(fail, Mapping):
            raise TypeError(f"Simulator: fail must be a mapping {{order: state}}, not {type(fail).__name__}")
        return [(_order("Simulator", k), _check.integer("Simulator", f"fail[{k!r}]", v, 0, 255)) for k, v in fail.items()]

    def _run(self) -> None:
        fd = ctypes.c_int(-1)
        while not self._stop:
            with self._lock:
                wait = lib.xfpy_sim_step(self._handle, ctypes.byref(fd))
            lib.xfpy_wait(fd.value, wait)

    def _check_open(self) -> None:
        if self._handle is None:
            raise ClosedError("the simulator is closed")

    def fault(self, **faults: int) -> None:
        """Inject faults at any time: drop_next, drop_permille, corrupt_next, corrupt_permille,
        delay_ms, jitter_ms (each packet, both ways, held 0..jitter_ms more: they overtake one
        another), dup_permille (packets that arrive twice), silent (1: answer nothing). All are
        checked before any is set."""
        self._check_open()
        for key in faults:
            if key not in settings(2):
                raise TypeError(f"fault: unexpected fault {key!r} (one of {', '.join(settings(2))})")
        values = self._faults(faults, "fault")
        with self._lock:
            self._check_open()
            for key, value in values.items():
                lib.xfpy_sim_fault(self._handle, key.encode(), value)

    def faults(self) -> Dict[str, int]:
        """The faults as they are set."""
        with self._lock:
            self._check_open()
            return {key: int(lib.xfpy_sim_fault_get(self._handle, key.encode())) for key in settings(2)}

    def configuration(self) -> Dict[str, int]:
        """The simulator's settings as they are set (version, model, answer_only, ...)."""
        with self._lock:
            self._check_open()
            return {key: int(lib.xfpy_sim_config_get(self._handle, key.encode())) for key in settings(1)}

    def disconnect(self, ms: int) -> None:
        """Take the link down for ``ms`` (a TCP client is dropped; nothing is answered)."""
        self._check_open()
        lo, hi, _ = limits()["disconnect.ms"]
        value = _check.integer("disconnect", "ms", ms, int(lo), int(hi))
        with self._lock:
            self._check_open()
            lib.xfpy_sim_disconnect(self._handle, value)

    def _json(self, fn: Any) -> Any:
        with self._lock:
            self._check_open()
            text = json_buffer_call(fn, self._handle)
        if text is None:  # pragma: no cover - out of memory
            raise RuntimeError("simulator: the library gave no answer")
        return json.loads(text.decode())

    def stats(self) -> Dict[str, Any]:
        """What it has seen and done: packets_in, replies, dropped, photos, recordings,
        executed (per order name), ignored (packets of another version than answer_only),
        strict (packets answered by a strict reading: notes()), mode, roll/pitch/yaw (deg),
        zoom_cam1/zoom_cam2 (x)."""
        value: Dict[str, Any] = self._json(lib.xfpy_sim_stats)
        return value

    def notes(self) -> List[str]:
        """Where V2.0.6 leaves a GCU's behaviour open and the simulator took the strict reading
        (a parameter of the wrong length, record with a parameter other than 0x01, ...): the last
        16, oldest first, one line each."""
        value: List[str] = self._json(lib.xfpy_sim_notes)
        return value

    def close(self) -> None:
        """Stop the thread and close the link. Safe to call more than once."""
        lock = getattr(self, "_lock", None)
        if lock is None:
            return
        with lock:
            if self._handle is None or self._stop:
                return  # closed, or another thread is closing it
            self._stop = True
        self._thread.join()
        with self._lock:
            lib.xfpy_sim_free(self._handle)
            self._handle = None
