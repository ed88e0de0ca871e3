"""Every argument is checked before it reaches C: the cases where a value used to arrive as
another value (cut to its C type, cut at a NUL, clamped in silence), each refused now with a
TypeError or ValueError that names the function, the parameter and the range, with nothing sent
and nothing changed."""

from __future__ import annotations

import ctypes
import math
import time
from typing import Any, Callable, Dict, Iterator

import pytest

import xfgcu
from xfgcu import _native

BIG = 2**64  # what ctypes cut away: 2**64 + 1000 arrived as 1000


def last_sent(g: xfgcu.Gimbal) -> Dict[str, Any]:
    """The last packet the client sent, decoded."""
    buf = ctypes.create_string_buffer(255)
    n = _native.lib.xfpy_client_last_sent(g._handle, buf, 255)
    assert n >= 72
    return xfgcu.decode(buf.raw[:n], raw=True)


def refused(error: type, message: str, call: Callable[[], Any]) -> None:
    """``call`` raises ``error`` with ``message`` (a regular expression, from the start)."""
    with pytest.raises(error, match="^" + message):
        call()


@pytest.fixture(scope="module")
def rig() -> Iterator[Any]:
    with xfgcu.Simulator("udp:127.0.0.1:0") as sim, xfgcu.connect(sim.spec) as g:
        yield sim, g


# ---- connect(): each configuration, never cut to its C type --------------------------------


@pytest.mark.parametrize(
    "key,value,message",
    [
        ("command_timeout_ms", BIG + 1000, r"connect: command_timeout_ms=18446744073709552616 is out of range 1\.\.3600000"),
        ("rate_hz", BIG + 50, r"connect: rate_hz=18446744073709551666 is out of range 1\.\.200"),
        ("reorder_ms", BIG + 100, r"connect: reorder_ms=18446744073709551716 is out of range 0\.\.1000"),
        ("stale_ms", -1, r"connect: stale_ms=-1 is out of range 1\.\.65535"),
        ("protocol", BIG + 1, r"connect: protocol=18446744073709551617 is out of range 1\.\.2"),
        ("protocol", 257, r"connect: protocol=257 is out of range 1\.\.2"),
    ],
)
def test_connect_configuration_out_of_range(key: str, value: int, message: str) -> None:
    with xfgcu.Simulator("udp:127.0.0.1:0") as sim:
        refused(ValueError, message, lambda: xfgcu.connect(sim.spec, **{key: value}))
        time.sleep(0.05)
        assert sim.stats()["packets_in"] == 0  # refused before a link was opened


def test_connect_configuration_of_the_wrong_type() -> None:
    refused(TypeError, "connect: rate_hz must be an int, not str", lambda: xfgcu.connect("udp:127.0.0.1:9", rate_hz="50"))
    refused(TypeError, "connect: rate_hz must be an int, not float", lambda: xfgcu.connect("udp:127.0.0.1:9", rate_hz=50.0))
    refused(TypeError, "connect: spec must be a str, not bytes", lambda: xfgcu.connect(b"udp:127.0.0.1:9"))  # type: ignore[arg-type]
    refused(ValueError, "connect: spec='udp:127.0.0.1:9\\\\x00junk' holds a NUL", lambda: xfgcu.connect("udp:127.0.0.1:9\0junk"))


# ---- the Simulator's options, faults, failures, ports ---------------------------------------


@pytest.mark.parametrize(
    "kwargs,message",
    [
        ({"model": BIG + 58}, r"model_code: model=18446744073709551674 is out of range 0\.\.255"),
        ({"protocol": BIG + 1}, r"Simulator: protocol=18446744073709551617 is out of range 1\.\.2"),
        ({"hw_version": BIG + 31}, r"Simulator: hw_version=18446744073709551647 is out of range 0\.\.255"),
        ({"calibration_ms": BIG}, r"Simulator: calibration_ms=18446744073709551616 is out of range 0\.\.600000"),
        ({"seed": 2**32 + 1}, r"Simulator: seed=4294967297 is out of range 0\.\.2147483647"),
        ({"delay_ms": BIG + 10}, r"Simulator: delay_ms=18446744073709551626 is out of range 0\.\.10000"),
        ({"answer_only": 3}, r"Simulator: answer_only=3 is out of range 1\.\.2"),
        ({"fail": {"shutter": 256}}, r"Simulator: fail\['shutter'\]=256 is out of range 0\.\.255"),
        ({"fail": {"shutter\0junk": 1}}, r"Simulator: fail's order='shutter\\x00junk' holds a NUL"),
        ({"fail": {300: 1}}, r"Simulator: fail's order=300 is out of range 0\.\.255"),
    ],
)
def test_simulator_options_out_of_range(kwargs: Dict[str, Any], message: str) -> None:
    refused(ValueError, message, lambda: xfgcu.Simulator("udp:127.0.0.1:0", **kwargs))


@pytest.mark.parametrize(
    "spec,message",
    [
        ("udp:127.0.0.1:70000", r"Simulator: spec 'udp:127\.0\.0\.1:70000': port 70000 is out of range 0\.\.65535"),
        ("udp:127.0.0.1:-1", r"Simulator: spec 'udp:127\.0\.0\.1:-1': the port '-1' is not a number 0\.\.65535"),
        ("tcp:127.0.0.1:65536", r"Simulator: spec 'tcp:127\.0\.0\.1:65536': port 65536 is out of range"),
        ("udp:127.0.0.1:0\0", r"Simulator: spec='udp:127\.0\.0\.1:0\\x00' holds a NUL"),
    ],
)
def test_simulator_port_never_wraps(spec: str, message: str) -> None:
    refused(ValueError, message, lambda: xfgcu.Simulator(spec))


def test_simulator_fail_256_is_not_ok() -> None:
    # 256 used to become state 0: the shutter answered ok
    refused(ValueError, r"Simulator: fail\['shutter'\]=256", lambda: xfgcu.Simulator(fail={"shutter": 256}))
    with xfgcu.Simulator(fail={"shutter": 255}) as sim, xfgcu.connect(sim.spec) as g:
        assert g.send("shutter").status == "failed"


def test_fault_and_disconnect_change_nothing_on_refusal(rig: Any) -> None:
    sim, g = rig
    before = sim.faults()
    refused(ValueError, r"fault: drop_next=18446744073709551617 is out of range 0\.\.65535", lambda: sim.fault(drop_next=BIG + 1))
    # all are checked before any is set: the good one before the bad one is not set either
    refused(ValueError, r"fault: silent=2 is out of range 0\.\.1", lambda: sim.fault(drop_permille=500, silent=2))
    refused(TypeError, "fault: silent must be an int, not str", lambda: sim.fault(silent="1"))
    refused(TypeError, "fault: unexpected fault 'bogus'", lambda: sim.fault(bogus=1))
    assert sim.faults() == before
    refused(ValueError, r"disconnect: ms=-1 is out of range 0\.\.3600000", lambda: sim.disconnect(-1))
    refused(ValueError, r"disconnect: ms=18446744073709551716 is out of range", lambda: sim.disconnect(BIG + 100))
    assert g.send("shutter").ok  # the link stayed up


# ---- the gimbal's setters -------------------------------------------------------------------


def test_set_gnss_week_is_not_cut(rig: Any) -> None:
    sim, g = rig
    refused(ValueError, r"set_gnss: week=4294967301 is out of range 0\.\.32767", lambda: g.set_gnss(22.5, 113.9, 50.0, week=2**32 + 5))
    refused(ValueError, r"set_gnss: satellites=256 is out of range 0\.\.255", lambda: g.set_gnss(22.5, 113.9, 50.0, satellites=256))
    refused(ValueError, r"set_gnss: latitude=91\.0 is out of range -90\.0\.\.90\.0", lambda: g.set_gnss(91.0, 0.0, 0.0))
    refused(ValueError, r"set_gnss: ms_of_week=604800000 is out of range 0\.\.604799999", lambda: g.set_gnss(0.0, 0.0, 0.0, ms_of_week=604800000))
    time.sleep(0.05)
    assert last_sent(g)["gnss_week"] == 0  # nothing reached the packets
    g.set_gnss(22.5, 113.9, 50.0, week=2345, ms_of_week=1000, satellites=12)
    time.sleep(0.05)
    sent = last_sent(g)
    assert (sent["gnss_week"], sent["gnss_ms"], sent["satellites"]) == (2345, 1000, 12)


def test_result_of_another_id_is_refused(rig: Any) -> None:
    sim, g = rig
    ident = g.submit("shutter")
    refused(ValueError, r"result: ident=\d+ is out of range 1\.\.4294967295", lambda: g.result(ident + 2**32))
    refused(ValueError, r"result: ident=0 is out of range", lambda: g.result(0))
    refused(TypeError, "result: ident must be an int, not str", lambda: g.result(str(ident)))  # type: ignore[arg-type]


def test_set_angles_nan_is_refused(rig: Any) -> None:
    sim, g = rig
    g.clear_control()
    for bad in (math.nan, math.inf, -math.inf):
        refused(ValueError, r"set_angles: roll=(nan|inf|-inf) is not a finite number", lambda: g.set_angles(bad, bad, bad))
    refused(ValueError, r"set_angles: pitch=200\.0 is out of range -180\.0\.\.180\.0", lambda: g.set_angles(0.0, 200.0, 0.0))
    assert g.health().control == "not_set"  # nothing set


def test_set_rates_beyond_the_wire_is_refused(rig: Any) -> None:
    sim, g = rig
    g.clear_control()
    refused(ValueError, r"set_rates: yaw=1000000\.0 is out of range -150\.0\.\.150\.0", lambda: g.set_rates(0, 0, 1e6))
    assert g.health().control == "not_set"


def test_a_string_gives_a_type_error_not_a_ctypes_one(rig: Any) -> None:
    sim, g = rig
    refused(TypeError, "set_angles: roll must be a number, not str", lambda: g.set_angles("a", 0, 0))
    refused(TypeError, "set_rates: pitch must be a number, not str", lambda: g.set_rates(0, "1", 0))
    refused(TypeError, "set_carrier: vel_up must be a number, not str", lambda: g.set_carrier(0, 0, 0, vel_up="2"))
    refused(TypeError, "set_gnss: latitude must be a number, not str", lambda: g.set_gnss("x", 0, 0))
    refused(TypeError, "send: name must be a str, not int", lambda: g.send(32))
    refused(TypeError, "wait_reply: timeout must be a number, not str", lambda: g.wait_reply("1"))
    refused(TypeError, "disconnect: ms must be an int, not str", lambda: sim.disconnect("10"))


# ---- commands: NUL and values -------------------------------------------------------------


def test_nul_in_a_command_name_or_value() -> None:
    # "shutter\0junk" used to be the shutter, and a value was cut at its NUL the same way
    refused(ValueError, r"encode_command: name='shutter\\x00junk' holds a NUL", lambda: xfgcu.encode_command("shutter\0junk"))
    refused(ValueError, r"night_vision: mode='auto\\x00junk' holds a NUL", lambda: xfgcu.encode_command("night_vision", mode="auto\0junk"))
    refused(ValueError, r"zoom_in: cameras='1\\x00,2' holds a NUL", lambda: xfgcu.encode_command("zoom_in", cameras="1\0,2"))


def test_command_values_checked_in_python_words(rig: Any) -> None:
    sim, g = rig
    executed = dict(sim.stats()["executed"])
    refused(xfgcu.CommandError, r"zoom_to: factor=3300\.0 is out of range 1\.0\.\.3276\.8", lambda: g.send("zoom_to", factor=3300.0))
    refused(xfgcu.CommandError, r"zoom_to: factor=nan is not a finite number", lambda: g.send("zoom_to", factor=math.nan))
    refused(TypeError, r"zoom_to: fraction must be an int, not float", lambda: g.send("zoom_to", fraction=0.5))
    refused(xfgcu.CommandError, r"lighting: level=18446744073709551617 is out of range 0\.\.255", lambda: g.send("lighting", level=BIG + 1))
    refused(TypeError, r"track: box must be a tuple of 4 ints", lambda: g.send("track", start=True, box=(1, 2, 3)))
    refused(TypeError, r"track: start is a switch: give start=True, not 1", lambda: g.send("track", start=1, box=(1, 2, 3, 4)))
    refused(xfgcu.CommandError, r"night_vision: mode='dusk' is not one of off, on, auto", lambda: g.send("night_vision", mode="dusk"))
    refused(TypeError, r"zoom_to: unexpected argument 'rat'", lambda: g.send("zoom_to", rat=5.5))
    refused(xfgcu.CommandError, r"send: 'shuter' is not a command", lambda: g.send("shuter"))
    assert sim.stats()["executed"] == executed  # nothing ran
