"""The client: a GCU on a link, driven by a background thread (the library's xf_client)."""

from __future__ import annotations

import ctypes
import json
import queue
import threading
import time
import traceback
import warnings
import weakref
from typing import Any, Callable, Dict, Iterator, List, Mapping, Optional, Union

from . import _check
from ._native import Owned, json_buffer_call, lib, limits, messages, report, settings
from .errors import ClampedWarning, ClosedError, CommandError, CommandFailed, LinkError, TelemetryTimeout
from .errors import UnsupportedCommandError
from .results import CONTROL_CODES, STATUS_CODES, ControlStatus, Health, Result, Status, Telemetry

__all__ = ["connect", "Gimbal", "CONFIG_KEYS"]

# The library's configuration names that connect() sets itself: protocol gives protocol_version
# and version_auto, and a reorder_ms given sets reorder_fixed.
_INTERNAL = ("protocol_version", "version_auto", "reorder_fixed")

#: connect()'s configuration keywords besides ``protocol``: the members of xf_client_config
#: (include/xfgcu/xf_client.h), with the ranges the library takes.
CONFIG_KEYS = tuple(k for k in settings(0) if k not in _INTERNAL)

TelemetryCallback = Callable[[Telemetry], None]


def _json(fn: Any, *args: Any) -> Optional[Dict[str, Any]]:
    text = json_buffer_call(fn, *args)
    if text is None:
        return None
    value: Dict[str, Any] = json.loads(text.decode())
    return value


def _protocol(value: object) -> Optional[int]:
    """connect()'s ``protocol``: None or "auto" (find the GCU's version), or the version 1 or 2."""
    if value is None or value == "auto":
        return None
    lo, hi = settings(0)["protocol_version"]
    if isinstance(value, str):
        raise ValueError(f"connect: protocol={value!r}: give None or 'auto' (find it), or {lo}..{hi}")
    return _check.integer("connect", "protocol", value, lo, hi)


class Gimbal(Owned):
    """A GCU on a link. The library's client (not thread-safe) runs in a thread this object
    owns, stepping at the packet rate; every call into it, from that thread or any other, holds
    one lock. Use as a context manager, or call close(): after close() every call but close()
    raises ClosedError."""

    def __init__(
        self,
        spec: str,
        *,
        protocol: Union[None, int, str] = None,
        connect_timeout_ms: int = 2000,
        raise_on_failure: bool = False,
        **config: int,
    ) -> None:
        self._handle: Optional[int] = None
        spec = _check.text("connect", "spec", spec)
        version = _protocol(protocol)
        wait_ms = _check.integer("connect", "connect_timeout_ms", connect_timeout_ms, 0, 3600000)
        self.raise_on_failure: bool = _check.flag("connect", "raise_on_failure", raise_on_failure)
        values = self._checked(config)
        self._lock = threading.Lock()
        self._cond = threading.Condition()
        self._subscribers: List[TelemetryCallback] = []
        self._closers: List[Callable[[], None]] = []  #: called once closed (telemetry streams end)
        self._stop = False
        self._closing = False
        self._seen = 0
        handle = lib.xfpy_client_new()
        if not handle:
            raise MemoryError("xfgcu: client")
        try:
            self._configure(handle, values, version)
            timeout_ms = values.get("command_timeout_ms", 1000)
            self._settle_s = (2 * timeout_ms + settings(0)["reorder_ms"][1]) / 1000.0
            msgs = messages()
            rc = lib.xfpy_client_open(handle, spec.encode(), msgs, len(msgs))
            message = report(msgs, stacklevel=4)  # a note (a rate outside 30-50 Hz) is a warning
            if rc != 0:
                raise LinkError(message)
        except BaseException:
            lib.xfpy_client_free(handle)
            raise
        self._handle = handle
        self.description: str = lib.xfpy_client_describe(handle).decode()
        self._thread = threading.Thread(target=self._run, name="xfgcu-client", daemon=True)
        self._thread.start()
        if wait_ms > 0 and not self.wait_reply(wait_ms / 1000.0):
            self.close()
            tried = "in protocol version 1 or 2" if version is None else f"in protocol version {version} only"
            hint = "check the link spec and that the GCU is on" + ("" if version is None else "; protocol=None tries both")
            raise LinkError(f"no reply from the GCU on {self.description} within {wait_ms} ms, {tried}: {hint}")

    @staticmethod
    def _checked(config: Mapping[str, object]) -> Dict[str, int]:
        out: Dict[str, int] = {}
        for key, value in config.items():
            if key not in CONFIG_KEYS:
                raise TypeError(f"connect: unexpected configuration {key!r} (one of protocol, {', '.join(CONFIG_KEYS)})")
            out[key] = _check.setting("connect", 0, key, value)
        return out

    @staticmethod
    def _configure(handle: int, values: Dict[str, int], version: Optional[int]) -> None:
        wanted = dict(values)
        wanted["protocol_version"] = 1 if version is None else version
        wanted["version_auto"] = int(version is None)
        wanted["reorder_fixed"] = int("reorder_ms" in values)  # the user's bound stands
        for key, value in wanted.items():
            if lib.xfpy_client_config(handle, key.encode(), value) != 0:  # pragma: no cover - checked above
                raise ValueError(f"connect: {key}={value!r} is out of range")
        problem = lib.xfpy_client_config_problem(handle)
        if problem:
            raise ValueError(f"connect: a configuration that cannot work: {problem.decode()}")

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
            with self._lock:
                t = self._telemetry_locked(seq)
            if t is None:
                continue
            for callback in subscribers:
                try:
                    callback(t)
                except Exception:  # a subscriber's bug must not stop the client
                    traceback.print_exc()

    def _telemetry_locked(self, seq: int) -> Optional[Telemetry]:
        if self._handle is None:
            return None
        if seq == 0:
            seq = int(lib.xfpy_client_replies(self._handle))
        eng = _json(lib.xfpy_client_telemetry, self._handle, seq, 0)
        raw = _json(lib.xfpy_client_telemetry, self._handle, seq, 1)
        if eng is None or raw is None:
            return None
        return Telemetry.from_dict(eng, raw)

    def _wait_for(self, predicate: Callable[[], bool], timeout: Optional[float]) -> bool:
        deadline = None if timeout is None else time.monotonic() + timeout
        with self._cond:
            while not predicate():
                left = None if deadline is None else deadline - time.monotonic()
                if (left is not None and left <= 0) or self._stop:
                    return predicate()
                self._cond.wait(0.1 if left is None else min(left, 0.1))
        return True

    def _check_open(self) -> None:
        if self._handle is None:
            raise ClosedError("the gimbal is closed")

    def _not_from_callback(self, what: str) -> None:
        if threading.current_thread() is getattr(self, "_thread", None):
            raise RuntimeError(f"{what}() from a telemetry callback would wait on the thread that runs it")

    # ---- commands --------------------------------------------------------------------

    def wait_reply(self, timeout: float = 1.0) -> bool:
        """Wait up to ``timeout`` seconds until the GCU has answered at least once.
        Returns whether it has."""
        self._check_open()
        seconds = _check.timeout("wait_reply", "timeout", timeout, none_ok=False)
        self._not_from_callback("wait_reply")
        return self._wait_for(lambda: self._replies() > 0, seconds)

    def _replies(self) -> int:
        with self._lock:
            return 0 if self._handle is None else int(lib.xfpy_client_replies(self._handle))

    def submit(self, name: str, *, force: bool = False, **args: Any) -> int:
        """Queue a command (the names and arguments of `xfgcu send`) and return its id at once.
        Raises CommandError (a ValueError) or TypeError for bad arguments, UnsupportedCommandError
        for an order the GCU's model lacks (unless ``force``)."""
        return self._submit("submit", name, force, args)

    def _submit(self, where: str, name: object, force: object, args: Mapping[str, Any]) -> int:
        self._check_open()
        given, shown, names, values = _check.command_args(where, name, args)
        forced = _check.flag(where, "force", force)
        count, c_names, c_values = _check.native_args(names, values)
        ident = ctypes.c_uint32(0)
        msgs = messages()
        with self._lock:
            self._check_open()
            rc = lib.xfpy_client_submit(
                self._handle, given.encode(), count, c_names, c_values, int(forced), ctypes.byref(ident), msgs,
                len(msgs),
            )  # fmt: skip
        message = report(msgs, 5, lambda m: _check.pythonic(m, given, shown, dict(zip(names, values))))
        if rc == 1:
            raise UnsupportedCommandError(message)
        if rc != 0:
            raise CommandError(message)
        return int(ident.value)

    def result(self, ident: int, name: str = "") -> Optional[Result]:
        """The final result of command ``ident`` (an id submit() gave), or None while it runs
        (and for an id that is not a command's)."""
        self._check_open()
        ident = _check.integer("result", "ident", ident, 1, 2**32 - 1)
        name = _check.text("result", "name", name)
        with self._lock:
            self._check_open()
            return self._result_locked(ident, name)

    def _result_locked(self, ident: int, name: str) -> Optional[Result]:
        cams, packets, state = ctypes.c_int(), ctypes.c_int(), ctypes.c_int()
        elapsed = ctypes.c_long()
        code = lib.xfpy_client_result(
            self._handle, ident, ctypes.byref(cams), ctypes.byref(packets), ctypes.byref(elapsed), ctypes.byref(state)
        )
        status = STATUS_CODES.get(code)
        if status is None:
            return None
        return Result(name, status, cams.value, packets.value, elapsed.value, state.value)

    def send(
        self,
        name: str,
        *,
        force: bool = False,
        timeout: Optional[float] = None,
        check: Optional[bool] = None,
        **args: Any,
    ) -> Result:
        """Run one command the protocol's way and wait for its result (blocking), as `xfgcu send
        NAME --OPTION VALUE ...` does: ``send("zoom_to", factor=5.5)``. The client's own timeouts
        end it (command_timeout_ms; operating_timeout_ms for calibration); ``timeout`` (seconds)
        bounds the wait besides, giving status "timeout". ``force``: send it even if the GCU's
        model lacks the order. ``check`` (default: the gimbal's ``raise_on_failure``): raise
        CommandFailed, carrying the Result, unless it ends "ok". Raises CommandError or TypeError
        for bad arguments, before anything is sent."""
        self._check_open()
        seconds = _check.timeout("send", "timeout", timeout)
        raising = self.raise_on_failure if check is None else _check.flag("send", "check", check)
        self._not_from_callback("send")
        ident = self._submit("send", name, force, args)
        box: List[Optional[Result]] = [None]
        closed = [False]

        def done() -> bool:
            with self._lock:  # the check and the query at once: close() cannot come between
                closed[0] = self._handle is None
                if not closed[0]:
                    box[0] = self._result_locked(ident, name)
            return box[0] is not None or closed[0]

        self._wait_for(done, seconds)
        result = box[0]
        if result is None:
            status = Status.CANCELLED if closed[0] else Status.TIMEOUT  # close() ended it, or the wait
            result = Result(name, status, 0, 0, 0, 0)
        if raising and not result.ok:
            raise CommandFailed(result)
        return result

    def cancel_all(self) -> None:
        """Cancel every queued or running command (status "cancelled")."""
        with self._lock:
            self._check_open()
            lib.xfpy_client_cancel_all(self._handle)

    # ---- control quantities and carrier data -----------------------------------------

    def _control(self, setter: str, fn: Any, roll: object, pitch: object, yaw: object) -> ControlStatus:
        self._check_open()
        values = [_check.limited(setter, n, v) for n, v in (("roll", roll), ("pitch", pitch), ("yaw", yaw))]
        with self._lock:
            self._check_open()
            status = CONTROL_CODES[int(fn(self._handle, *values))]
            limit = float(lib.xfpy_client_rate_limit(self._handle)) if setter == "set_rates" else None
        if limit is not None and any(abs(v) > limit for v in values):
            warnings.warn(
                ClampedWarning(f"set_rates: a rate beyond {limit:.2f} deg/s, the most the wire carries at the main "
                               f"camera's zoom now, is sent as {limit:.2f} deg/s"),
                stacklevel=3,
            )  # fmt: skip
        return status

    def set_rates(self, roll: float = 0.0, pitch: float = 0.0, yaw: float = 0.0) -> ControlStatus:
        """Angular rates, deg/s, each within what the wire carries at zoom 1 (150 deg/s;
        ValueError beyond), sent while the gimbal's mode reads rates (head lock) and refreshed
        within the rate watchdog (rate_watchdog_ms). A rate is scaled by the main camera's zoom
        on the wire, which carries less at a higher zoom: beyond that it is sent clamped, with a
        ClampedWarning. Returns where the setpoint stands."""
        return self._control("set_rates", lib.xfpy_client_set_rates, roll, pitch, yaw)

    def set_angles(self, roll: float = 0.0, pitch: float = 0.0, yaw: float = 0.0) -> ControlStatus:
        """Angles, deg, as the mode reads them (euler: Euler angles; angle-control: relative to
        the carrier): pitch within -180..180, roll and yaw within -360..360 (wrapped into
        -180..180 on the wire); ValueError beyond. Returns where the setpoint stands ("sent",
        "no_mode", "wrong_kind", ...)."""
        return self._control("set_angles", lib.xfpy_client_set_angles, roll, pitch, yaw)

    def set_main_camera(self, camera: int) -> None:
        """The camera on the GCU's main screen (1 or 2), whose zoom scales the rates."""
        self._check_open()
        lo, hi, _ = limits()["set_main_camera.camera"]
        value = _check.integer("set_main_camera", "camera", camera, int(lo), int(hi))
        with self._lock:
            self._check_open()
            lib.xfpy_client_set_main_camera(self._handle, value)

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
        """The carrier's attitude (deg: pitch -90..90, roll and yaw -360..360, wrapped),
        accelerations without gravity (m/s^2) and velocities (m/s), each within what the wire
        carries; sent while younger than carrier_max_age_ms, so call it at its own rate."""
        self._check_open()
        given = {
            "roll": roll, "pitch": pitch, "yaw": yaw, "accel_north": accel_north, "accel_east": accel_east,
            "accel_up": accel_up, "vel_north": vel_north, "vel_east": vel_east, "vel_up": vel_up,
        }  # fmt: skip
        values = (ctypes.c_double * 9)(*[_check.limited("set_carrier", k, v) for k, v in given.items()])
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
        """GNSS position (deg, deg, m), satellites in use, GNSS week and ms of week (week None:
        the system clock's time now), height relative to take-off (m); each within what the
        wire carries (a latitude within -90..90, a week 0..32767, ms within a week)."""
        self._check_open()
        where = "set_gnss"
        numbers = [_check.limited(where, k, v) for k, v in
                   (("latitude", latitude), ("longitude", longitude), ("altitude", altitude),
                    ("relative_height", relative_height))]  # fmt: skip

        def whole(name: str, value: object) -> int:
            lo, hi, _ = limits()[f"{where}.{name}"]
            return _check.integer(where, name, value, int(lo), int(hi))

        sats = whole("satellites", satellites)
        gnss_week = -1 if week is None else whole("week", week)
        ms = whole("ms_of_week", ms_of_week)
        with self._lock:
            self._check_open()
            lib.xfpy_client_set_gnss(self._handle, numbers[0], numbers[1], numbers[2], sats, gnss_week, ms, numbers[3])

    # ---- telemetry and health --------------------------------------------------------

    def telemetry(self) -> Optional[Telemetry]:
        """The last reply, as `xfgcu monitor --json` prints it: engineering units, the raw view
        in ``.raw``. None before the first reply."""
        with self._lock:
            self._check_open()
            return self._telemetry_locked(0)

    def on_telemetry(self, callback: TelemetryCallback) -> Callable[[], None]:
        """Call ``callback(telemetry)`` for every reply, from the client's thread (keep it
        short). Returns a function that unsubscribes."""
        self._check_open()
        if not callable(callback):
            raise TypeError(f"on_telemetry: callback must be callable, not {type(callback).__name__}")
        return self._subscribe(callback)

    def _subscribe(self, callback: TelemetryCallback) -> Callable[[], None]:
        self._subscribers.append(callback)

        def remove() -> None:
            if callback in self._subscribers:
                self._subscribers.remove(callback)

        return remove

    def telemetry_stream(self, timeout: Optional[float] = None, maxsize: int = 256) -> Iterator[Telemetry]:
        """Every reply's telemetry from now on, as it arrives: ``for t in
        gimbal.telemetry_stream(timeout=1.0): ...``. It ends when the gimbal is closed; with
        ``timeout`` (seconds), a wait for the next reply that lasts longer raises
        TelemetryTimeout. When the consumer falls more than ``maxsize`` replies behind, the
        oldest are dropped. Leaving the loop (or dropping the iterator) unsubscribes."""
        self._check_open()
        seconds = _check.timeout("telemetry_stream", "timeout", timeout)
        size = _check.integer("telemetry_stream", "maxsize", maxsize, 1, 2**20)
        box: "queue.Queue[Optional[Telemetry]]" = queue.Queue(size)

        def deliver(t: Optional[Telemetry]) -> None:  # on the client's thread (None: closed)
            while True:
                try:
                    box.put_nowait(t)
                    return
                except queue.Full:  # drop the oldest
                    try:
                        box.get_nowait()
                    except queue.Empty:  # pragma: no cover - the consumer took one meanwhile
                        pass

        def closed() -> None:
            deliver(None)

        remove = self._subscribe(deliver)  # from now on: no reply is missed before the first next()
        self._closers.append(closed)

        def unsubscribe() -> None:
            remove()
            if closed in self._closers:
                self._closers.remove(closed)

        stream = _stream(box, seconds)
        weakref.finalize(stream, unsubscribe)  # when the loop is left, or the iterator dropped
        return stream

    def health(self) -> Health:
        """Link health: link state, reply rate, counters, the control status, the protocol
        versions (sent, answered, the GCU's), whether the link keeps order, replies out of turn
        and the reorder bound in force."""
        with self._lock:
            self._check_open()
            value = _json(lib.xfpy_client_health, self._handle)
        if value is None:  # pragma: no cover - out of memory
            raise RuntimeError("xfgcu: health: the library gave no answer")
        return Health.from_dict(value)

    @property
    def protocol(self) -> Optional[int]:
        """The protocol version byte the GCU answers (the one the client sends); None until it has
        answered."""
        return self.health().version_answered

    @property
    def gcu_protocol(self) -> Optional[int]:
        """The version byte of the GCU's replies, whose ranges and meanings the client follows;
        None before the first reply."""
        return self.health().version_gcu

    def close(self) -> None:
        """Let the client settle (no reply to one of its commands still on the link, where the
        next program could take it for its own; at most twice command_timeout_ms plus the
        largest reorder bound), stop the thread and close the link. Commands still running end
        "cancelled"; telemetry streams end. Safe to call more than once."""
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


def _stream(box: "queue.Queue[Optional[Telemetry]]", timeout: Optional[float]) -> Iterator[Telemetry]:
    while True:
        try:
            t = box.get(timeout=timeout)
        except queue.Empty:
            raise TelemetryTimeout(f"no telemetry within {timeout} s") from None
        if t is None:
            return
        yield t


def connect(
    spec: str,
    *,
    protocol: Union[None, int, str] = None,
    connect_timeout_ms: int = 2000,
    raise_on_failure: bool = False,
    **config: int,
) -> Gimbal:
    """Open the link ``spec`` (the library's link spec: "tcp:HOST[:PORT]",
    "udp:HOST[:PORT][,local=PORT]", "serial:PATH[,baud=N]") and start a client on it; waits for
    the GCU's first reply (``connect_timeout_ms``, default 2000; 0: do not wait).

    ``protocol``: None (the default) finds the version the GCU answers, 1 then 2
    (``Gimbal.protocol`` says which); 1 or 2 speaks that one only. ``raise_on_failure``: every
    send() raises CommandFailed unless its command ends "ok". ``config``: rate_hz,
    command_timeout_ms, operating_timeout_ms, carrier_max_age_ms, gnss_max_age_ms, stale_ms,
    down_ms, rate_watchdog_ms, reorder_ms (the longest the network can delay one packet behind a
    later one; given, it stands; not given, the client judges the link and applies a bound of its
    own while the link has not shown that it keeps order). Raises LinkError, or TypeError /
    ValueError for bad arguments."""
    return Gimbal(
        spec, protocol=protocol, connect_timeout_ms=connect_timeout_ms, raise_on_failure=raise_on_failure, **config
    )
