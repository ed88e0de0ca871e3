"""A simulated GCU in this process (the library's xf_sim on a simulator link), to test an
application without hardware."""

from __future__ import annotations

import ctypes
import json
import threading
from typing import Any, Dict, Mapping, Optional, Union

from ._native import Owned, lib, messages, report
from .errors import LinkError

__all__ = ["Simulator", "model_code"]

_FAULTS = (
    "drop_next",
    "drop_permille",
    "corrupt_next",
    "corrupt_permille",
    "delay_ms",
    "jitter_ms",
    "dup_permille",
    "silent",
)


def model_code(model: Union[int, str]) -> int:
    """A gimbal model's code from its code or its name ("Z-9B_V4(T)")."""
    if isinstance(model, int):
        return model
    for code in range(256):
        if lib.xfpy_model_name(code).decode() == model:
            return code
    raise ValueError(f"unknown gimbal model {model!r}")


def _by_name(name: str) -> int:
    from .codec import encode

    from .codec import decode

    order: int = decode(encode({"order": name.replace("-", "_")}))["order"]
    return order


class Simulator(Owned):
    """A simulated GCU that follows the protocol (the library's simulator: once-rule, feedback,
    attitude by mode, zoom, ranging, tracking), on the GCU's end of a link, stepped by a thread
    this object owns.

    ``spec``: "udp:ADDR:PORT", "tcp:ADDR:PORT" (PORT 0: any free port; ADDR default
    127.0.0.1), "pty" or "pty:LINK" (a new pseudo-terminal, and a symbolic link LINK to it).
    ``spec`` of the object is then what a client opens: ``xfgcu.connect(sim.spec)``.
    ``model``: the model code or name it reports (default 58, Z-9B_V4(T), which has every order);
    ``protocol``: the version of its replies, 1 or 2; ``fail``: {order: state}, executions of
    the order (name or number) answer that state, e.g. {"shutter": 1}; faults: drop_permille,
    delay_ms, ... (also settable later with fault()); other configuration of xf_sim_config:
    hw_version, fw_version, calibration_ms, feedback_after, state_once, seed."""

    def __init__(
        self,
        spec: str = "udp:127.0.0.1:0",
        model: Union[int, str] = 58,
        protocol: int = 1,
        fail: Optional[Mapping[Union[int, str], int]] = None,
        **options: int,
    ) -> None:
        self._lock = threading.Lock()
        self._stop = False
        self._handle = lib.xfpy_sim_new()
        if not self._handle:
            raise MemoryError("xfgcu: simulator")
        try:
            self._setup(model_code(model), protocol, fail or {}, options)
            self._open(spec)
            # after the open, which starts the simulator afresh (its faults included)
            self.fault(**{key: value for key, value in options.items() if key in _FAULTS})
        except BaseException:
            lib.xfpy_sim_free(self._handle)
            self._handle = None
            raise
        self.spec: str = lib.xfpy_sim_spec(self._handle).decode()
        self._thread = threading.Thread(target=self._run, name="xfgcu-sim", daemon=True)
        self._thread.start()

    def _setup(self, model: int, protocol: int, fail: Mapping[Union[int, str], int], options: Dict[str, int]) -> None:
        self._set_config("model", model)
        self._set_config("version", protocol)
        for key, value in options.items():
            if key not in _FAULTS:
                self._set_config(key, value)
        for order, state in fail.items():
            lib.xfpy_sim_fail(self._handle, _by_name(order) if isinstance(order, str) else order, state)

    def _set_config(self, key: str, value: int) -> None:
        if lib.xfpy_sim_config(self._handle, key.encode(), int(value)) != 0:
            raise ValueError(f"simulator: {key}={value!r} is unknown or out of range")

    def _open(self, spec: str) -> None:
        kind, _, rest = spec.partition(":")
        where, port = rest, 0
        if kind in ("udp", "tcp"):
            host, sep, port_text = rest.rpartition(":")
            where = host if sep else rest
            port = int(port_text) if sep else (2337 if kind == "udp" else 2332)
            where = where.strip("[]") or "127.0.0.1"
        elif kind != "pty":
            raise ValueError(f"simulator spec {spec!r}: udp:ADDR:PORT, tcp:ADDR:PORT, pty or pty:LINK")
        msgs = messages()
        rc = lib.xfpy_sim_open(self._handle, kind.encode(), where.encode(), port, msgs, len(msgs))
        message = report(msgs)
        if rc != 0:
            raise LinkError(message)

    def _run(self) -> None:
        fd = ctypes.c_int(-1)
        while not self._stop:
            with self._lock:
                wait = lib.xfpy_sim_step(self._handle, ctypes.byref(fd))
            lib.xfpy_wait(fd.value, wait)

    def fault(self, **faults: int) -> None:
        """Inject faults at any time: drop_next, drop_permille, corrupt_next, corrupt_permille,
        delay_ms, jitter_ms (each packet, both ways, held 0..jitter_ms more: they overtake one
        another), dup_permille (packets that arrive twice), silent (1: answer nothing)."""
        with self._lock:
            self._check_open()
            for key, value in faults.items():
                if key not in _FAULTS or lib.xfpy_sim_fault(self._handle, key.encode(), int(value)) != 0:
                    raise ValueError(f"simulator fault {key}={value!r} is unknown or out of range")

    def disconnect(self, ms: int) -> None:
        """Take the link down for ``ms`` (a TCP client is dropped; nothing is answered)."""
        with self._lock:
            self._check_open()
            lib.xfpy_sim_disconnect(self._handle, ms)

    def stats(self) -> Dict[str, Any]:
        """What it has seen and done: packets_in, replies, dropped, photos, recordings,
        executed (per order name), mode, roll/pitch/yaw (deg), zoom_cam1/zoom_cam2 (x)."""
        size = 16384
        while True:
            with self._lock:
                self._check_open()
                out = ctypes.create_string_buffer(size)
                rc = lib.xfpy_sim_stats(self._handle, out, len(out))
            if rc == 0:
                value: Dict[str, Any] = json.loads(out.value.decode())
                return value
            if rc < 0:
                raise RuntimeError("simulator: stats")
            size = rc  # the size it needs

    def _check_open(self) -> None:
        if self._handle is None:
            raise LinkError("the simulator is closed")

    def close(self) -> None:
        """Stop the thread and close the link."""
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
