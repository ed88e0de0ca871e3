"""The client: a GCU on a link, driven by a background thread (the library's xf_client)."""

from __future__ import annotations

import ctypes
import json
import threading
import time
from dataclasses import dataclass
from typing import Any, Callable, Dict, List, Optional

from ._native import Owned, lib, messages, named_args, report
from .errors import CommandError, LinkError, UnsupportedCommandError

__all__ = ["connect", "Gimbal", "Result", "CONFIG_KEYS"]

#: connect()'s configuration: the members of xf_client_config (include/xfgcu/xf_client.h);
#: ``protocol`` is protocol_version.
CONFIG_KEYS = (
    "rate_hz",
    "command_timeout_ms",
    "operating_timeout_ms",
    "carrier_max_age_ms",
    "gnss_max_age_ms",
    "stale_ms",
    "down_ms",
    "rate_watchdog_ms",
    "protocol",
    "reorder_ms",
)

# xf_cmd_status (include/xfgcu/xf_client.h): the final ones, as Result.status says them.
_FINAL = {4: "ok", 5: "failed", 6: "timeout", 7: "link_lost", 8: "cancelled"}
_CTRL = {0: "sent", 1: "not_set", 2: "no_mode", 3: "wrong_kind", 4: "not_read", 5: "command", 6: "dropped"}

TelemetryCallback = Callable[[Dict[str, Any]], None]


@dataclass(frozen=True)
class Result:
    """A command's outcome, as `xfgcu send` reports it."""

    name: str
    status: str  #: "ok", "failed", "timeout", "link_lost" (or "cancelled": close() or cancel_all())
    failed_cameras: int  #: the cameras that failed, for orders that report a mask
    packets: int  #: packets that carried the command
    elapsed_ms: int  #: from first sent to the result
    state: int  #: the GCU's state byte

    @property
    def ok(self) -> bool:
        return self.status == "ok"


def _json_call(fn: Callable[..., int], *args: Any) -> Optional[Dict[str, Any]]:
    size = 8192
    while True:
        out = ctypes.create_string_buffer(size)
        rc = fn(*args, out, size)
        if rc == 0:
            value: Dict[str, Any] = json.loads(out.value.decode())
            return value
        if rc < 0:
            return None
        size = rc


class Gimbal(Owned):
    """A GCU on a link. The library's client (not thread-safe) runs in a thread this object
    owns, stepping at the packet rate; every call into it, from that thread or any other, holds
    one lock. Use as a context manager, or call close()."""

    def __init__(self, spec: str, connect_timeout_ms: int = 2000, **config: int) -> None:
        self._lock = threading.Lock()
        self._cond = threading.Condition()
        self._subscribers: List[TelemetryCallback] = []
        self._stop = False
        self._closing = False
        self._closers: List[Callable[[], None]] = []  #: called once closed (telemetry_stream ends)
        self._seen = 0
        self._handle = lib.xfpy_client_new()
        if not self._handle:
            raise MemoryError("xfgcu: client")
        try:
            self._configure(config)
            self._settle_s = (2 * config.get("command_timeout_ms", 1000) + config.get("reorder_ms", 0)) / 1000.0
            msgs = messages()
            rc = lib.xfpy_client_open(self._handle, spec.encode(), msgs, len(msgs))
            message = report(msgs)
            if rc != 0:
                raise LinkError(message)
        except BaseException:
            lib.xfpy_client_free(self._handle)
            self._handle = None
            raise
        self.description: str = lib.xfpy_client_describe(self._handle).decode()
        self._thread = threading.Thread(target=self._run, name="xfgcu-client", daemon=True)
        self._thread.start()
        if connect_timeout_ms > 0 and not self.wait_reply(connect_timeout_ms / 1000.0):
            self.close()
            raise LinkError(f"no reply from the GCU on {self.description} within {connect_timeout_ms} ms")

    def _configure(self, config: Dict[str, int]) -> None:
        for key, value in config.items():
            if key not in CONFIG_KEYS:
                raise TypeError(f"unknown configuration {key!r} (one of {', '.join(CONFIG_KEYS)})")
            name = "protocol_version" if key == "protocol" else key
            if lib.xfpy_client_config(self._handle, name.encode(), int(value)) != 0:
                raise ValueError(f"{key}={value!r} is out of range")
        problem = lib.xfpy_client_config_problem(self._handle)
        if problem:
            raise ValueError(f"configuration that cannot work: {problem.decode()}")

    # ---- the thread ------------------------------------------------------------------

    def _run(self) -> None:
        fd = ctypes.c_int(-1)
        while not self._stop:
            with self._lock:
                wait = lib.xfpy_client_step(self._handle, ctypes.byref(fd))
                replies = lib.xfpy_client_replies(self._handle)
            with self._cond:
                self._cond.notify_all()
            if replies != self._seen:
                self._dispatch(replies)
            lib.xfpy_wait(fd.value, wait)  # no lock held: only poll(2) on the descriptor

    def _dispatch(self, replies: int) -> None:
        first = max(self._seen + 1, replies - 63)
        self._seen = replies
        subscribers = list(self._subscribers)
        if not subscribers:
            return
        for seq in range(first, replies + 1):
            t = self._telemetry(seq)
            if t is None:
                continue
            for callback in subscribers:
                try:
                    callback(t)
                except Exception:  # a subscriber's bug must not stop the client
                    import traceback

                    traceback.print_exc()

    def _telemetry(self, seq: int) -> Optional[Dict[str, Any]]:
        with self._lock:
            if self._handle is None:
                return None
            return _json_call(lib.xfpy_client_telemetry, self._handle, seq, 0)

    def _wait_for(self, predicate: Callable[[], bool], timeout: Optional[float]) -> bool:
        deadline = None if timeout is None else time.monotonic() + timeout
        with self._cond:
            while not predicate():
                left = None if deadline is None else deadline - time.monotonic()
                if (left is not None and left <= 0) or self._stop:
                    return predicate()
                self._cond.wait(0.1 if left is None else min(left, 0.1))
        return True

    # ---- the API ---------------------------------------------------------------------

    def wait_reply(self, timeout: float = 1.0) -> bool:
        """Wait until the GCU has answered at least once. @return whether it has."""
        self._not_from_callback("wait_reply")
        return self._wait_for(lambda: self._replies() > 0, timeout)

    def _replies(self) -> int:
        with self._lock:
            return 0 if self._handle is None else int(lib.xfpy_client_replies(self._handle))

    def submit(self, name: str, *, force: bool = False, **args: Any) -> int:
        """Queue a command (the names and options of `xfgcu send`) and return its id at once."""
        count, names, values = named_args(args)
        ident = ctypes.c_uint32(0)
        msgs = messages()
        with self._lock:
            self._check_open()
            rc = lib.xfpy_client_submit(
                self._handle, name.encode(), count, names, values, int(force), ctypes.byref(ident), msgs, len(msgs)
            )
        message = report(msgs)
        if rc == 1:
            raise UnsupportedCommandError(message)
        if rc != 0:
            raise CommandError(message)
        return int(ident.value)

    def result(self, ident: int, name: str = "") -> Optional[Result]:
        """The final result of command ``ident``, or None while it runs."""
        with self._lock:
            self._check_open()
            return self._result_locked(ident, name)

    def _result_locked(self, ident: int, name: str) -> Optional[Result]:
        cams, packets, state = ctypes.c_int(), ctypes.c_int(), ctypes.c_int()
        elapsed = ctypes.c_long()
        status = lib.xfpy_client_result(
            self._handle, ident, ctypes.byref(cams), ctypes.byref(packets), ctypes.byref(elapsed), ctypes.byref(state)
        )
        if status not in _FINAL:
            return None
        return Result(name, _FINAL[status], cams.value, packets.value, elapsed.value, state.value)

    def send(self, name: str, *, force: bool = False, timeout: Optional[float] = None, **args: Any) -> Result:
        """Run one command the protocol's way and wait for its result (blocking), as `xfgcu send
        NAME --OPTION VALUE ...` does: ``send("zoom-to", factor=5.5)``. The client's own timeouts
        end it (command_timeout_ms; operating_timeout_ms for calibration); ``timeout`` (seconds)
        bounds the wait besides, giving status "timeout". ``force``: send it even if the GCU's
        model lacks the order. Raises CommandError for bad arguments."""
        self._not_from_callback("send")
        ident = self.submit(name, force=force, **args)
        box: List[Optional[Result]] = [None]
        closed = [False]

        def done() -> bool:
            with self._lock:  # the check and the query at once: close() cannot come between
                closed[0] = self._handle is None
                if not closed[0]:
                    box[0] = self._result_locked(ident, name)
            return box[0] is not None or closed[0]

        finished = self._wait_for(done, timeout)
        if closed[0] and box[0] is None:
            return Result(name, "cancelled", 0, 0, 0, 0)  # close() ended it
        if not finished or box[0] is None:
            return Result(name, "timeout", 0, 0, 0, 0)
        return box[0]

    def _not_from_callback(self, what: str) -> None:
        if threading.current_thread() is getattr(self, "_thread", None):
            raise RuntimeError(f"{what}() from a telemetry callback would wait on the thread that runs it")

    def cancel_all(self) -> None:
        """Cancel every queued or running command (status "cancelled")."""
        with self._lock:
            self._check_open()
            lib.xfpy_client_cancel_all(self._handle)

    def set_rates(self, roll: float = 0.0, pitch: float = 0.0, yaw: float = 0.0) -> str:
        """Angular rates, deg/s, sent while the gimbal's mode reads rates (head lock), refreshed
        within the rate watchdog (rate_watchdog_ms). @return the control status ("sent", ...)."""
        with self._lock:
            self._check_open()
            return _CTRL.get(lib.xfpy_client_set_rates(self._handle, roll, pitch, yaw), "?")

    def set_angles(self, roll: float = 0.0, pitch: float = 0.0, yaw: float = 0.0) -> str:
        """Angles, deg, as the mode reads them (euler: Euler angles; angle-control: relative to
        the carrier). @return the control status ("sent", "no_mode", "wrong_kind", ...)."""
        with self._lock:
            self._check_open()
            return _CTRL.get(lib.xfpy_client_set_angles(self._handle, roll, pitch, yaw), "?")

    def clear_control(self) -> None:
        """Stop sending control quantities."""
        with self._lock:
            self._check_open()
            lib.xfpy_client_clear_control(self._handle)

    def set_carrier(
        self,
        roll: float,
        pitch: float,
        yaw: float,
        accel_north: float = 0.0,
        accel_east: float = 0.0,
        accel_up: float = 0.0,
        vel_north: float = 0.0,
        vel_east: float = 0.0,
        vel_up: float = 0.0,
    ) -> None:
        """The carrier's attitude (deg), accelerations without gravity (m/s^2) and velocities
        (m/s); sent while younger than carrier_max_age_ms, so call it at its own rate."""
        values = (ctypes.c_double * 9)(roll, pitch, yaw, accel_north, accel_east, accel_up, vel_north, vel_east, vel_up)
        with self._lock:
            self._check_open()
            lib.xfpy_client_set_carrier(self._handle, values)

    def set_gnss(
        self,
        latitude: float,
        longitude: float,
        altitude: float,
        satellites: int = 0,
        week: Optional[int] = None,
        ms_of_week: int = 0,
        relative_height: float = 0.0,
    ) -> None:
        """GNSS position (deg, deg, m), satellites in use, GNSS week and ms of week (None: the
        system clock's time now), height relative to take-off (m)."""
        with self._lock:
            self._check_open()
            lib.xfpy_client_set_gnss(
                self._handle, latitude, longitude, altitude, satellites, -1 if week is None else week, ms_of_week,
                relative_height,
            )

    def telemetry(self) -> Optional[Dict[str, Any]]:
        """The last reply as `xfgcu monitor --json` prints it (the keys of `decode --json`),
        plus "units": its quantities in physical units (degrees, deg/s, zoom x, metres; as the
        client keeps them). None before the first reply."""
        return self._telemetry(0)

    def on_telemetry(self, callback: TelemetryCallback) -> Callable[[], None]:
        """Call ``callback(telemetry)`` for every reply, from the client's thread (keep it
        short). @return a function that unsubscribes."""
        self._subscribers.append(callback)

        def remove() -> None:
            if callback in self._subscribers:
                self._subscribers.remove(callback)

        return remove

    def health(self) -> Dict[str, Any]:
        """Link health: "link" ("up", "stale", "down"), reply_rate_hz, packets_sent, replies,
        replies_missing, send_errors, watchdog figures, the parser's error counters, pending
        (commands queued), control (what became of the setpoint: as set_rates() says)."""
        with self._lock:
            self._check_open()
            value = _json_call(lib.xfpy_client_health, self._handle)
        if value is None:
            raise RuntimeError("xfgcu: health: the library gave no answer")
        return value

    def _check_open(self) -> None:
        if self._handle is None:
            raise LinkError("the gimbal's link is closed")

    def close(self) -> None:
        """Let the client settle (no reply to one of its commands still on the link, where the
        next program could take it for its own; at most twice command_timeout_ms plus
        reorder_ms), stop the thread and close the link. Commands still running end
        "cancelled"."""
        lock = getattr(self, "_lock", None)
        if lock is None:
            return
        self._not_from_callback("close")  # before it marks itself closing: a later close() still works
        with lock:
            if self._handle is None or self._closing:
                return  # closed, or another thread is closing it
            self._closing = True
        deadline = time.monotonic() + self._settle_s
        while self._thread.is_alive() and time.monotonic() < deadline:
            with self._lock:
                if lib.xfpy_client_settled(self._handle):
                    break
            time.sleep(0.005)
        self._stop = True
        self._thread.join()  # (not from the thread itself: _not_from_callback)
        with self._lock:
            lib.xfpy_client_cancel_all(self._handle)
            lib.xfpy_client_free(self._handle)
            self._handle = None
        with self._cond:
            self._cond.notify_all()
        for closer in list(self._closers):
            closer()


def connect(spec: str, **config: Any) -> Gimbal:
    """Open the link ``spec`` (the library's link spec: "tcp:HOST[:PORT]",
    "udp:HOST[:PORT][,local=PORT]", "serial:PATH[,baud=N]") and start a client on it; waits for
    the GCU's first reply (``connect_timeout_ms``, default 2000; 0: do not wait). ``config``:
    rate_hz, command_timeout_ms, operating_timeout_ms, carrier_max_age_ms, gnss_max_age_ms,
    stale_ms, down_ms, rate_watchdog_ms, protocol, reorder_ms (the longest the network can
    delay one packet behind a later one; 0: it keeps order). Raises LinkError."""
    return Gimbal(spec, **config)
