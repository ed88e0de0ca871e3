"""Every public function and method, each of its parameters driven by hypothesis with hostile
values (integers of any size, the C types' edges, NaN, infinities, huge and tiny floats, strings
with NUL, bytes, None, bools): each value is refused with a TypeError or a ValueError, or it is
taken and arrives exactly (read back from the library, or from the packet it put on the wire;
a value the wire holds in steps arrives as its nearest step, an angle the library wraps
arrives wrapped)."""

from __future__ import annotations

import asyncio
import ctypes
import math
import re
import time
from dataclasses import dataclass
from typing import Any, Callable, Dict, Iterator

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import xfgcu
import xfgcu.aio
from xfgcu import _native

EDGES = [0, 1, -1, 2**7, 2**8, 2**15, 2**16, 2**31, 2**32, 2**63, 2**64, 2**64 + 1000, -(2**31) - 1, -(2**63) - 1]
HOSTILE = st.one_of(
    st.integers(),
    st.integers(-400, 70000),
    st.sampled_from(EDGES),
    st.floats(),
    st.floats(-400.0, 400.0),
    st.sampled_from([math.nan, math.inf, -math.inf, 1e300, -1e300, 5e-324, 1e18, 2.0**63]),
    st.text(max_size=6),
    st.sampled_from(["", "\0", "1\0", "shutter\0junk", "auto", "3", "0x03", "all", "nan", "inf"]),
    st.booleans(),
    st.none(),
    st.binary(max_size=4),
)

# Each example costs at most a packet period or two; a loaded 2-core machine is slow: no deadline.
FAST = settings(max_examples=100, deadline=None, suppress_health_check=list(HealthCheck), database=None)
SLOW = settings(max_examples=25, deadline=None, suppress_health_check=list(HealthCheck), database=None)


def close(a: float, b: float, step: float) -> bool:
    """``a`` is ``b`` to the nearest ``step`` (and the float error of a C float on the way)."""
    return abs(a - b) <= step / 2 + 1e-6 * max(1.0, abs(b))


def close_wrapped(a: float, b: float, step: float) -> bool:
    return abs((a - b + 180.0) % 360.0 - 180.0) <= step / 2 + 1e-4


# ---- the rig: a simulator and a gimbal in each mode the setters need ---------------------


@dataclass
class Rig:
    sim: xfgcu.Simulator
    rates: xfgcu.Gimbal  #: in head lock: set_rates goes on the wire
    angles: xfgcu.Gimbal  #: in euler: set_angles goes on the wire
    angles_sim: xfgcu.Simulator
    good: bytes  #: a packet


@pytest.fixture(scope="module")
def rig() -> Iterator[Rig]:
    with xfgcu.Simulator() as sim, xfgcu.Simulator() as angles_sim:
        with xfgcu.connect(sim.spec) as rates, xfgcu.connect(angles_sim.spec) as angles:
            assert rates.send("head_lock").ok and angles.send("euler").ok
            yield Rig(sim, rates, angles, angles_sim, xfgcu.encode_command("shutter"))


def sent_after(g: xfgcu.Gimbal) -> Dict[str, Any]:
    """The first packet the client built after now, decoded (wire integers)."""
    start = g.health().packets_sent
    end = time.monotonic() + 5.0
    while g.health().packets_sent < start + 2 and time.monotonic() < end:
        time.sleep(0.002)
    buf = ctypes.create_string_buffer(255)
    n = _native.lib.xfpy_client_last_sent(g._handle, buf, 255)
    return xfgcu.decode(buf.raw[:n], raw=True)


def refused_or(call: Callable[[], Any], accepted: Callable[[Any], None]) -> None:
    try:
        result = call()
    except (TypeError, ValueError) as exc:
        text = str(exc)
        # one line, in Python's words: no "--option" of the program's (a hostile string quoted
        # in the message may hold "--" itself)
        words = re.sub(r"'[^']*'", "", re.sub(r'"[^"]*"', "", text))
        assert text and "\n" not in text and "--" not in words, text
        return
    accepted(result)


# ---- the codec --------------------------------------------------------------------------


@FAST
@given(st.one_of(HOSTILE, st.binary(min_size=72, max_size=80)))
def test_decode_data(value: Any) -> None:
    refused_or(lambda: xfgcu.decode(value), lambda obj: None)
    if isinstance(value, (bytes, bytearray)):
        try:
            obj = xfgcu.decode(value)
        except xfgcu.DecodeError:
            return
        assert xfgcu.encode(obj) == value  # taken: exactly these bytes


@FAST
@given(HOSTILE, HOSTILE)
def test_decode_options(rig: Rig, pod_order: Any, raw: Any) -> None:
    def taken(obj: Dict[str, Any]) -> None:
        assert pod_order in ("auto", "le", "be") and raw in (True, False, 0, 1)
        assert obj["order_name"] == "shutter"

    refused_or(lambda: xfgcu.decode(rig.good, pod_order=pod_order, raw=raw), taken)


# the step of each field in a V0.1 packet (docs/protocol.md §5, §6)
STEPS = {"cam_pitch": 0.01, "cam_yaw": 0.01, "rate_z": 0.01, "zoom_cam1": 0.1, "target_latitude": 1e-7, "gimbal_code": 1}


@FAST
@given(st.sampled_from(sorted(STEPS)), HOSTILE)
def test_encode_field_value(name: str, value: Any) -> None:
    """A field's value is taken only when it is a whole number of steps (within a double's error
    on a decimal text), and then it comes back as given."""
    obj = {"direction": "gcu", name: value}

    def taken(packet: bytes) -> None:
        got = xfgcu.decode(packet)[name]
        assert not isinstance(value, bool) and abs(got - value) <= 1e-3 * STEPS[name], (got, value)

    refused_or(lambda: xfgcu.encode(obj), taken)


@FAST
@given(HOSTILE, HOSTILE, HOSTILE)
def test_encode_arguments(obj: Any, protocol: Any, raw: Any) -> None:
    refused_or(lambda: xfgcu.encode(obj), lambda p: pytest.fail(f"encode took {obj!r}"))

    def taken(packet: bytes) -> None:
        assert protocol in (1, 2) and not isinstance(protocol, bool) and raw in (True, False, 0, 1)
        assert xfgcu.decode(packet)["version"] == protocol

    refused_or(lambda: xfgcu.encode({"order": "shutter"}, protocol=protocol, raw=raw), taken)


def command_checks() -> Dict[str, Callable[[Any], Any]]:
    """(a command and an argument) -> the call; what arrives is checked in test_encode_command."""
    return {
        "name": lambda v: xfgcu.encode_command(v),
        "protocol": lambda v: xfgcu.encode_command("shutter", protocol=v),
        "zoom_to.factor": lambda v: xfgcu.encode_command("zoom_to", factor=v),
        "zoom_to.fraction": lambda v: xfgcu.encode_command("zoom_to", fraction=v),
        "lighting.level": lambda v: xfgcu.encode_command("lighting", level=v),
        "time_zone.hours": lambda v: xfgcu.encode_command("time_zone", hours=v),
        "gaze_geo.lat": lambda v: xfgcu.encode_command("gaze_geo", lat=v, lon=0, alt=0),
        "gaze_geo.alt": lambda v: xfgcu.encode_command("gaze_geo", lat=0, lon=0, alt=v),
        "temp_alarm.high": lambda v: xfgcu.encode_command("temp_alarm", on=True, high=v, low=-3276.8),
        "track.start": lambda v: xfgcu.encode_command("track", start=v, box=(0, 0, 10, 10)),
        "track.box": lambda v: xfgcu.encode_command("track", start=True, box=(v, 0, 10000, 10)),
        "track.box_tuple": lambda v: xfgcu.encode_command("track", start=True, box=v),
        "night_vision.mode": lambda v: xfgcu.encode_command("night_vision", mode=v),
        "zoom_in.cameras": lambda v: xfgcu.encode_command("zoom_in", cameras=v),
    }


def arrived(label: str, value: Any, obj: Dict[str, Any]) -> None:
    """What a taken value gives in the packet: the value, to the wire's step."""
    cmd = obj.get("command", {})
    assert not isinstance(value, bool) or label == "track.start"
    checks: Dict[str, Callable[[], bool]] = {
        "name": lambda: obj["order"] == xfgcu.encode_command(value.replace("-", "_"))[4],
        "protocol": lambda: obj["version"] == value,
        "zoom_to.factor": lambda: close(-cmd["zoom"] / 10.0, value, 0.1),
        "zoom_to.fraction": lambda: cmd["zoom"] == value,
        "lighting.level": lambda: cmd["value"] == value,
        "time_zone.hours": lambda: cmd["hours"] == value,
        "gaze_geo.lat": lambda: close(cmd["latitude"], value, 1e-7),
        "gaze_geo.alt": lambda: close(cmd["altitude"], value, 1e-3),
        "temp_alarm.high": lambda: close(cmd["temp_high"], value, 0.1),
        "track.start": lambda: value is True and cmd["value"] == 1,
        "track.box": lambda: cmd["x0"] == value,
        "track.box_tuple": lambda: [cmd["x0"], cmd["y0"], cmd["x1"], cmd["y1"]] == list(value),
        "night_vision.mode": lambda: ["off", "on", "auto"][cmd["value"]] == value,
        "zoom_in.cameras": lambda: cmd["cameras"] == value if isinstance(value, int) else cmd["cameras"] > 0,
    }
    assert checks[label](), (label, value, obj)


@pytest.mark.filterwarnings("ignore:.*is an order of protocol")  # a V0.2 order in a V0.1 packet: a note
@FAST
@given(st.sampled_from(sorted(command_checks())), HOSTILE)
def test_encode_command(label: str, value: Any) -> None:
    refused_or(lambda: command_checks()[label](value), lambda packet: arrived(label, value, xfgcu.decode(packet)))


@FAST
@given(HOSTILE)
def test_parser(value: Any) -> None:
    refused_or(lambda: xfgcu.Parser(value), lambda p: None if value in (None, "host", "gcu") else pytest.fail(repr(value)))
    refused_or(lambda: xfgcu.Parser().feed(value), lambda got: isinstance(value, bytes) or pytest.fail(repr(value)))


@FAST
@given(HOSTILE)
def test_model_code(value: Any) -> None:
    def taken(code: int) -> None:
        assert code == value if isinstance(value, int) else _native.lib.xfpy_model_name(code).decode() == value

    refused_or(lambda: xfgcu.model_code(value), taken)


# ---- the simulator ----------------------------------------------------------------------


SIM_KEYWORDS = {"model": "model", "protocol": "version", "answer_only": "answer_only", "state_once": "state_once",
                "main_camera": "main_camera"}  # fmt: skip


@SLOW
@given(st.sampled_from(sorted(set(SIM_KEYWORDS) | set(_native.settings(1)) | set(_native.settings(2)))), HOSTILE)
def test_simulator_options(key: str, value: Any) -> None:
    if key in ("version",):
        key = "protocol"

    def taken(sim: xfgcu.Simulator) -> None:
        with sim:
            if key in _native.settings(2):
                assert sim.faults()[key] == value
            else:
                got = sim.configuration()[SIM_KEYWORDS.get(key, key)]
                assert got == (0 if value is None else xfgcu.model_code(value) if key == "model" else int(value))

    refused_or(lambda: xfgcu.Simulator(**{key: value}), taken)


@SLOW
@given(HOSTILE, HOSTILE, HOSTILE)
def test_simulator_spec_and_fail(spec: Any, order: Any, state: Any) -> None:
    refused_or(lambda: xfgcu.Simulator(spec), lambda sim: sim.close())

    def taken(sim: xfgcu.Simulator) -> None:
        sim.close()
        assert isinstance(state, int) and 0 <= state <= 255

    refused_or(lambda: xfgcu.Simulator(fail={"shutter": state}), taken)
    refused_or(lambda: xfgcu.Simulator(fail={order: 1}), lambda sim: sim.close())


@FAST
@given(st.sampled_from(sorted(_native.settings(2))), HOSTILE)
def test_fault(rig: Rig, key: str, value: Any) -> None:
    sim = rig.angles_sim
    before = sim.faults()

    def taken(_: None) -> None:
        assert sim.faults()[key] == value and not isinstance(value, bool)
        sim.fault(**{key: before[key]})

    try:
        refused_or(lambda: sim.fault(**{key: value}), taken)
    finally:
        sim.fault(**before)
    assert sim.faults() == before


@FAST
@given(HOSTILE)
def test_disconnect(value: Any) -> None:
    with xfgcu.Simulator() as sim:  # no client: the outage harms nothing
        refused_or(lambda: sim.disconnect(value), lambda _: isinstance(value, int) and 0 <= value <= 3600000)


# ---- the gimbal -------------------------------------------------------------------------


@SLOW
@pytest.mark.filterwarnings("ignore:rate_hz=.*outside the recommended:UserWarning")  # a rate taken, with its warning
@given(st.sampled_from(list(xfgcu.CONFIG_KEYS) + ["protocol", "connect_timeout_ms", "raise_on_failure"]), HOSTILE)
def test_connect(rig: Rig, key: str, value: Any) -> None:
    def taken(g: xfgcu.Gimbal) -> None:
        with g:
            if key in xfgcu.CONFIG_KEYS:
                assert _native.lib.xfpy_client_config_get(g._handle, key.encode()) == value
            elif key == "protocol":
                assert value in (None, "auto", 1, 2) and not isinstance(value, bool)
            elif key == "raise_on_failure":
                assert g.raise_on_failure == bool(value) and value in (0, 1)

    try:
        refused_or(lambda: xfgcu.connect(rig.sim.spec, **{key: value}), taken)
    except xfgcu.LinkError:
        assert key == "connect_timeout_ms" and value < 50  # too short to hear the GCU: a refusal too


def gimbal_checks(rig: Rig) -> Dict[str, Callable[[Any], Any]]:
    g = rig.rates
    checks: Dict[str, Callable[[Any], Any]] = {
        "send.name": lambda v: g.send(v),
        "send.force": lambda v: g.send("shutter", force=v),
        "send.timeout": lambda v: g.send("shutter", timeout=v),
        "send.check": lambda v: g.send("shutter", check=v),
        "send.factor": lambda v: rig.angles.send("zoom_to", factor=v),  # the rates' gimbal stays at zoom 1
        "submit.name": lambda v: g.submit(v),
        "result.ident": lambda v: g.result(v),
        "result.name": lambda v: g.result(1, v),
        "wait_reply.timeout": lambda v: g.wait_reply(v),
        "set_main_camera.camera": lambda v: g.set_main_camera(v),
        "telemetry_stream.timeout": lambda v: g.telemetry_stream(timeout=v),
        "telemetry_stream.maxsize": lambda v: g.telemetry_stream(maxsize=v),
        "on_telemetry.callback": lambda v: g.on_telemetry(v),
    }
    assert sorted(checks) == sorted(GIMBAL_LABELS)
    return checks


GIMBAL_LABELS = ["send.name", "send.force", "send.timeout", "send.check", "send.factor", "submit.name",
                 "result.ident", "result.name", "wait_reply.timeout", "set_main_camera.camera",
                 "telemetry_stream.timeout", "telemetry_stream.maxsize", "on_telemetry.callback"]  # fmt: skip


@FAST
@given(st.sampled_from(GIMBAL_LABELS), HOSTILE)
def test_gimbal_arguments(rig: Rig, label: str, value: Any) -> None:
    call = gimbal_checks(rig)[label]

    def taken(result: Any) -> None:
        assert not isinstance(value, bool) or label in ("send.force", "send.check")
        if label in ("send.name", "send.force", "send.check", "send.factor", "send.timeout"):
            assert isinstance(result, xfgcu.Result) and result.status in ("ok", "timeout", "failed")
        elif label in ("send.timeout", "wait_reply.timeout", "telemetry_stream.timeout"):
            assert value is None or (value >= 0 and math.isfinite(value))
        elif label == "result.ident":
            assert isinstance(value, int) and 1 <= value < 2**32
        elif label == "set_main_camera.camera":
            assert value in (1, 2)
            rig.rates.set_main_camera(1)
        elif label == "telemetry_stream.maxsize":
            assert isinstance(value, int) and value >= 1
        elif label == "submit.name":
            assert isinstance(result, int) and result > 0
            rig.rates.cancel_all()
        if label in ("send.name", "submit.name"):
            assert rig.rates.send("head_lock").ok  # whatever command it was: the mode set_rates needs

    refused_or(lambda: call(value), taken)


AXES = ("roll", "pitch", "yaw")


@FAST
@given(st.sampled_from(["set_rates", "set_angles"]), st.sampled_from(AXES), HOSTILE)
def test_set_rates_and_angles(rig: Rig, setter: str, axis: str, value: Any) -> None:
    """Rates go on the wire in 0.1 deg/s at zoom 1 (head lock), angles in 0.01 deg (euler),
    roll and yaw wrapped."""
    g = rig.rates if setter == "set_rates" else rig.angles
    args = {a: 0.0 for a in AXES}
    args[axis] = value

    def taken(status: xfgcu.ControlStatus) -> None:
        assert status == "sent"
        if setter == "set_rates":
            assert close(sent_after(g)[f"{axis}_ctrl"] / 10.0, value, 0.1)
        else:
            got = sent_after(g)[f"{axis}_ctrl"] / 100.0
            assert close(got, value, 0.01) if axis == "pitch" else close_wrapped(got, value, 0.01)

    refused_or(lambda: getattr(g, setter)(**args), taken)


CARRIER = ("roll", "pitch", "yaw", "accel_north", "accel_east", "accel_up", "vel_north", "vel_east", "vel_up")


@FAST
@given(st.sampled_from(CARRIER), HOSTILE)
def test_set_carrier(rig: Rig, name: str, value: Any) -> None:
    g = rig.rates
    args = {a: 0.0 for a in CARRIER}
    args[name] = value

    def taken(_: None) -> None:
        got = sent_after(g)[name if name.startswith(("accel", "vel")) else f"carrier_{name}"] / 100.0
        if name in ("roll", "yaw"):
            assert close_wrapped(got, value, 0.01)
        else:
            assert close(got, value, 0.01)

    refused_or(lambda: g.set_carrier(**args), taken)


GNSS = {"latitude": ("latitude", 1e-7), "longitude": ("longitude", 1e-7), "altitude": ("altitude", 1e-3),
        "relative_height": ("relative_height", 1e-3), "satellites": ("satellites", 1), "week": ("gnss_week", 1),
        "ms_of_week": ("gnss_ms", 1)}  # fmt: skip


@FAST
@given(st.sampled_from(sorted(GNSS)), HOSTILE)
def test_set_gnss(rig: Rig, name: str, value: Any) -> None:
    g = rig.rates
    args: Dict[str, Any] = {"latitude": 0.0, "longitude": 0.0, "altitude": 0.0, "week": 2000}
    args[name] = value
    field, step = GNSS[name]

    def taken(_: None) -> None:
        got = sent_after(g)[field] * (step if step < 1 else 1)
        if name == "week" and value is None:
            assert 2000 < got < 5000  # the system clock's week
        else:
            assert not isinstance(value, bool) and close(got, value, step)

    refused_or(lambda: g.set_gnss(**args), taken)


@SLOW
@given(HOSTILE)
def test_async_arguments(rig: Rig, value: Any) -> None:
    ag = xfgcu.aio.AsyncGimbal(rig.rates)

    async def main() -> None:
        refused_or(lambda: ag.telemetry_stream(maxsize=value), lambda s: isinstance(value, int) and value >= 1)
        try:
            result = await ag.send(value)
        except (TypeError, ValueError):
            return
        assert isinstance(value, str) and result.status in ("ok", "timeout", "failed")

    asyncio.run(main())
