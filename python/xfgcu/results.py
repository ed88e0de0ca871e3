"""What the client reports: statuses as enums (each a str, so ``status == "ok"`` holds), a
command's Result, the GCU's Telemetry (engineering units, with a raw view) and the link's Health.

Telemetry has the names and values of ``xfgcu monitor --json`` (``--raw`` for its ``raw`` view);
the unit of each field comes from the library's field table: ``Telemetry.unit("cam_pitch")``.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field, fields
from enum import Enum
from typing import Any, Dict, Optional, Tuple

from . import _native

__all__ = ["Status", "ControlStatus", "LinkState", "Result", "Telemetry", "Health"]


class _Word(str, Enum):
    """An enum whose members are their words: equal to them, printed as them."""

    def __str__(self) -> str:
        return str(self.value)

    def __format__(self, spec: str) -> str:
        return format(str(self.value), spec)


class Status(_Word):
    """How a command ended (xf_cmd_status's final values)."""

    OK = "ok"
    FAILED = "failed"  #: the GCU answered a failure (Result.failed_cameras says which cameras)
    TIMEOUT = "timeout"  #: no execution state in time
    LINK_LOST = "link_lost"  #: the link went down while it ran
    CANCELLED = "cancelled"  #: cancel_all() or close()


class ControlStatus(_Word):
    """Where the application's setpoint stands (xf_ctrl_status), as set_rates() and set_angles()
    return it and Health.control says it."""

    SENT = "sent"  #: the next packet carries it
    NOT_SET = "not_set"  #: none set
    NO_MODE = "no_mode"  #: the GCU's mode is not known yet
    WRONG_KIND = "wrong_kind"  #: the mode reads the other kind (angles, not rates, or the reverse)
    NOT_READ = "not_read"  #: the mode reads no control quantity
    COMMAND = "command"  #: held while a command runs
    DROPPED = "dropped"  #: the mode changed: set it again


class LinkState(_Word):
    """The link as the client sees it."""

    UP = "up"
    STALE = "stale"  #: no reply for stale_ms
    DOWN = "down"  #: no reply for down_ms


#: xf_cmd_status's final values, by number
STATUS_CODES = {4: Status.OK, 5: Status.FAILED, 6: Status.TIMEOUT, 7: Status.LINK_LOST, 8: Status.CANCELLED}
#: xf_ctrl_status, by number
CONTROL_CODES = dict(enumerate(ControlStatus))


@dataclass(frozen=True)
class Result:
    """A command's outcome, as `xfgcu send` reports it."""

    name: str  #: the command, as it was given
    status: Status
    failed_cameras: int  #: the cameras that failed, for orders that report a mask
    packets: int  #: packets that carried the command
    elapsed_ms: int  #: from first sent to the result
    state: int  #: the GCU's state byte

    @property
    def ok(self) -> bool:
        """Whether the command ran: status "ok"."""
        return self.status is Status.OK


@dataclass(frozen=True)
class Telemetry:
    """One reply of the GCU: the object of `xfgcu monitor --json`, as attributes of the same
    names, fields in engineering units (the unit rule of docs/protocol.md, "Units"); ``raw`` is
    the same reply with wire integers (`monitor --raw`). Keys that this class does not name (added
    by a newer library) are in ``extra``. The fields, their units and meanings (from the
    library's field table) follow."""

    time_mono: float  #: s, CLOCK_MONOTONIC, when the reply came
    time_utc: str  #: when the reply came, ISO 8601 UTC
    direction: str  #: "gcu"
    version: int  #: the reply's protocol version byte
    length: int
    order: int
    params: str  #: the order's parameter bytes, hex
    gimbal_mode: int
    pod_status: int
    pod_flags: Tuple[str, ...]
    target_offset_x: int
    target_offset_y: int
    rel_angle_x: float
    rel_angle_y: float
    rel_angle_z: float
    cam_roll: float
    cam_pitch: float
    cam_yaw: float
    rate_x: float
    rate_y: float
    rate_z: float
    sub_header: int
    hw_version: float
    fw_version: float
    gimbal_code: int
    error_code: int
    target_distance: float  #: 0 or less: no valid measurement
    target_longitude: float
    target_latitude: float
    target_altitude: float
    zoom_cam1: float
    zoom_cam2: float
    order_name: Optional[str] = None
    mode_name: Optional[str] = None
    pod_status_order: Optional[str] = None
    gimbal_model: Optional[str] = None
    thermal_status: Optional[int] = None  #: V0.2 on
    camera_status: Optional[int] = None  #: V0.2 on
    time_zone: Optional[float] = None  #: V0.2 on
    feedback: Optional[Dict[str, Any]] = field(default=None, hash=False)  #: a reply that carries an execution state
    reserved_main: Optional[str] = None
    reserved_sub: Optional[str] = None
    extra: Dict[str, Any] = field(default_factory=dict, hash=False)
    _raw: Optional["Telemetry"] = field(default=None, repr=False, compare=False)
    _source: Dict[str, Any] = field(default_factory=dict, repr=False, compare=False)

    @property
    def raw(self) -> "Telemetry":
        """The same reply with the wire integers (the raw view's own ``raw`` is itself)."""
        return self._raw if self._raw is not None else self

    def as_dict(self) -> Dict[str, Any]:
        """The object of `xfgcu monitor --json` (``--raw`` for the raw view), keys in its order."""
        return json.loads(json.dumps(self._source))  # type: ignore[no-any-return]

    @staticmethod
    def unit(name: str) -> str:
        """The engineering unit of field ``name`` ("deg", "deg/s", "m", "x", ...; "" for a plain
        number or a code), from the library's field table. Raises KeyError."""
        return _units()[name]

    @classmethod
    def from_dict(cls, obj: Dict[str, Any], raw: Optional[Dict[str, Any]] = None) -> "Telemetry":
        """A Telemetry from the objects of `monitor --json` and, optionally, `monitor --raw`."""
        known = _names()
        args: Dict[str, Any] = {k: v for k, v in obj.items() if k in known}
        if "pod_flags" in args:
            args["pod_flags"] = tuple(args["pod_flags"])
        args["extra"] = {k: v for k, v in obj.items() if k not in known}
        args["_source"] = obj
        if raw is not None:
            args["_raw"] = cls.from_dict(raw)
        return cls(**args)


def _names() -> Tuple[str, ...]:
    return tuple(f.name for f in fields(Telemetry) if f.name not in ("extra", "_raw", "_source"))


def _units() -> Dict[str, str]:
    return {f.name: f.unit for group in (0, 2) for f in _native.fields(group)}


def _document() -> None:
    rows = [f"    {f.name}" + (f" ({f.unit})" if f.unit else "") + f": {f.meaning}" for f in _native.fields(2)]
    Telemetry.__doc__ = (Telemetry.__doc__ or "") + "\n\n" + "\n".join(rows) + "\n"


_document()


@dataclass(frozen=True)
class Health:
    """The link's health, as the client counts it (xf_health, the parser's counters)."""

    link: LinkState
    watchdog_active: bool  #: zero rates are sent: the rates went stale
    transport_closed: bool
    reply_rate_hz: int  #: replies in the last full second
    last_rx_ms: int
    packets_sent: int
    replies: int
    replies_missing: int  #: packets of the last full second that got no reply
    send_errors: int
    watchdog_trips: int
    crc_errors: int
    length_errors: int
    bytes_skipped: int
    pending: int  #: commands queued
    control: ControlStatus  #: what became of the setpoint
    version_sent: Optional[int]  #: the version byte the client sends (with protocol auto: the one it tries)
    version_answered: Optional[int]  #: the version byte the GCU answers; None before it has
    version_gcu: Optional[int]  #: the version byte of the GCU's replies, whose meaning the client follows
    in_order: bool  #: the link has shown that it keeps order
    out_of_turn: int  #: replies that came out of turn or twice
    reorder_ms: int  #: the reorder bound in force, ms (the one given, or the client's own)

    @classmethod
    def from_dict(cls, obj: Dict[str, Any]) -> "Health":
        args = {f.name: obj[f.name] for f in fields(cls)}
        args["link"] = LinkState(args["link"])
        args["control"] = ControlStatus(args["control"])
        return cls(**args)
