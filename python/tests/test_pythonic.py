"""The package as a Python user meets it: typed telemetry with the names, values and units of
`xfgcu monitor --json` and a raw view, iterators, enums that are their words, errors that raise
where asked, and one error for every call after close()."""

from __future__ import annotations

import asyncio
import dataclasses
import inspect
import json
import time
import warnings
from typing import Any, Callable, Dict, List

import pytest

import xfgcu
import xfgcu.aio
from xfgcu import _native
from conftest import run, wait_until


def monitor_line(program: str, sim: xfgcu.Simulator, *extra: str) -> Dict[str, Any]:
    port = sim.spec.split(":")[2].split(",")[0]
    r = run(program, *extra, "--link", f"udp:127.0.0.1:{port},local=0", "monitor", "--json", "--count", "1")
    assert r.returncode == 0, r.stderr
    line: Dict[str, Any] = json.loads(r.stdout.splitlines()[0])
    return line


def attributes(t: xfgcu.Telemetry, keys: List[str]) -> Dict[str, Any]:
    """The attributes of ``t`` named by ``keys`` (or its ``extra``), as JSON gives them."""
    out = {}
    for key in keys:
        value = getattr(t, key) if hasattr(t, key) and key != "extra" else t.extra[key]
        out[key] = list(value) if isinstance(value, tuple) else value
    return out


@pytest.mark.parametrize("protocol", [1, 2])
def test_telemetry_reads_as_monitor_json(program: str, protocol: int) -> None:
    """Every key of `monitor --json` is an attribute of the same name and value (engineering
    units), and of `monitor --raw --json` the same in the raw view; nothing else is."""
    with xfgcu.Simulator(protocol=protocol, fw_version=51) as sim:
        with xfgcu.connect(sim.spec) as g:
            assert g.send("zoom_to", factor=5.5).ok and g.send("euler").ok
            assert wait_until(lambda: g.set_angles(0.0, -30.0, 45.0) == "sent" and abs(g.telemetry().cam_yaw - 45.0) < 0.01)  # type: ignore[union-attr]
            assert wait_until(lambda: g.telemetry().zoom_cam1 == 5.5)  # type: ignore[union-attr]
            g.clear_control()
            time.sleep(0.2)  # the gimbal at rest: the next client reads the same values
            t = g.telemetry()
            eng = monitor_line(program, sim)
            raw = monitor_line(program, sim, "--raw")
    assert t is not None
    for view, line in ((t, eng), (t.raw, raw)):
        keys = [k for k in line if k not in ("time_mono", "time_utc")]
        assert attributes(view, keys) == {k: line[k] for k in keys}
        assert list(view.as_dict()) == list(line)  # the same keys, in the same order
    assert (t.cam_pitch, t.raw.cam_pitch, t.fw_version, t.raw.fw_version) == (-30.0, -3000, 5.1, 51)
    assert (t.zoom_cam1, t.raw.zoom_cam1, t.version) == (5.5, 55, protocol)


def test_units_come_from_the_field_table() -> None:
    rows = {f.name: f for f in _native.fields(2)}  # the GCU's frames, include/xfgcu/xf_fields.h
    assert xfgcu.Telemetry.unit("cam_pitch") == rows["cam_pitch"].unit == "deg"
    assert xfgcu.Telemetry.unit("rate_z") == "deg/s" and xfgcu.Telemetry.unit("zoom_cam1") == "x"
    assert xfgcu.Telemetry.unit("target_distance") == "m" and xfgcu.Telemetry.unit("gimbal_code") == ""
    names = {f.name for f in dataclasses.fields(xfgcu.Telemetry)}
    for row in rows.values():  # every field of the table is an attribute, documented with its unit
        if row.kind != 5:  # reserved blocks: hex, under reserved_main / reserved_sub
            assert row.name in names
            assert f"    {row.name}" + (f" ({row.unit})" if row.unit else "") in (xfgcu.Telemetry.__doc__ or "")


def test_sync_telemetry_stream_and_its_timeout(udp_sim: xfgcu.Simulator) -> None:
    with xfgcu.connect(udp_sim.spec) as g:
        got = []
        for t in g.telemetry_stream(timeout=2.0):
            got.append(t)
            if len(got) == 5:
                break
        assert all(isinstance(t, xfgcu.Telemetry) for t in got)
        assert [t.time_mono for t in got] == sorted(t.time_mono for t in got)
        udp_sim.fault(silent=1)
        t0 = time.monotonic()
        with pytest.raises(xfgcu.TelemetryTimeout, match="no telemetry within 0.3 s"):
            for _ in g.telemetry_stream(timeout=0.3):
                pass
        assert time.monotonic() - t0 >= 0.25
        udp_sim.fault(silent=0)
        stream = g.telemetry_stream()
    assert list(stream) == [] or all(isinstance(t, xfgcu.Telemetry) for t in stream)  # ends with close()


def test_statuses_are_enums_and_their_words(udp_sim: xfgcu.Simulator) -> None:
    with xfgcu.connect(udp_sim.spec) as g:
        r = g.send("shutter")
        assert r.status is xfgcu.Status.OK and r.status == "ok" and f"{r.status}" == "ok" and str(r.status) == "ok"
        assert json.dumps({"status": r.status}) == '{"status": "ok"}'
        control = g.set_rates(0, 0, 0)
        assert isinstance(control, xfgcu.ControlStatus) and control in ("sent", "wrong_kind")
        assert g.health().link is xfgcu.LinkState.UP


def test_command_failed_raises_when_asked() -> None:
    with xfgcu.Simulator(fail={"zoom_in": 0x02}) as sim:
        with xfgcu.connect(sim.spec) as g:
            assert g.send("zoom_in").status == "failed"  # by default, a result
            with pytest.raises(xfgcu.CommandFailed, match=r"^zoom_in: failed \(cameras 0x02\)$") as info:
                g.send("zoom_in", check=True)
            assert info.value.result.failed_cameras == 0x02 and info.value.result.status is xfgcu.Status.FAILED
        with xfgcu.connect(sim.spec, raise_on_failure=True) as g:
            with pytest.raises(xfgcu.CommandFailed):
                g.send("zoom_in")
            assert g.send("zoom_in", check=False).status == "failed"
            assert g.send("shutter").ok

        async def main() -> None:
            async with xfgcu.aio.connect(sim.spec, raise_on_failure=True) as ag:
                with pytest.raises(xfgcu.CommandFailed):
                    await ag.send("zoom_in")

        asyncio.run(main())


def test_clamped_rates_are_reported(udp_sim: xfgcu.Simulator) -> None:
    with xfgcu.connect(udp_sim.spec) as g:
        assert g.send("zoom_to", factor=10.0).ok and g.send("head_lock").ok
        assert wait_until(lambda: g.telemetry().zoom_cam1 == 10.0)  # type: ignore[union-attr]
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            g.set_rates(0.0, 0.0, 10.0)  # within 15 deg/s, what the wire carries at 10x
            assert not caught
            g.set_rates(0.0, 0.0, 100.0)
        assert [w.category for w in caught] == [xfgcu.ClampedWarning]
        assert "15.00 deg/s" in str(caught[0].message)


PUBLIC_GIMBAL: Dict[str, Callable[[Any], Any]] = {
    "send": lambda g: g.send("shutter"),
    "submit": lambda g: g.submit("shutter"),
    "result": lambda g: g.result(1),
    "wait_reply": lambda g: g.wait_reply(0.1),
    "cancel_all": lambda g: g.cancel_all(),
    "set_rates": lambda g: g.set_rates(0, 0, 0),
    "set_angles": lambda g: g.set_angles(0, 0, 0),
    "set_main_camera": lambda g: g.set_main_camera(1),
    "clear_control": lambda g: g.clear_control(),
    "set_carrier": lambda g: g.set_carrier(0, 0, 0),
    "set_gnss": lambda g: g.set_gnss(0, 0, 0),
    "telemetry": lambda g: g.telemetry(),
    "on_telemetry": lambda g: g.on_telemetry(print),
    "telemetry_stream": lambda g: g.telemetry_stream(),
    "health": lambda g: g.health(),
    "protocol": lambda g: g.protocol,
    "gcu_protocol": lambda g: g.gcu_protocol,
}


def public(cls: type) -> List[str]:
    return sorted(n for n, _ in inspect.getmembers(cls) if not n.startswith("_") and n not in ("close",))


def test_every_call_after_close_raises_closed_error(udp_sim: xfgcu.Simulator) -> None:
    assert public(xfgcu.Gimbal) == sorted(PUBLIC_GIMBAL)  # a new method gets a row here
    g = xfgcu.connect(udp_sim.spec)
    g.close()
    g.close()  # again: nothing
    for call in PUBLIC_GIMBAL.values():
        with pytest.raises(xfgcu.ClosedError, match="^the gimbal is closed$"):
            call(g)
    with pytest.raises(xfgcu.ClosedError):  # even with a bad argument: the same error first
        g.set_angles(float("nan"), 0, 0)

    async def main() -> None:
        ag = await xfgcu.aio.connect(udp_sim.spec)
        await ag.close()
        for name in public(xfgcu.aio.AsyncGimbal):
            if name in ("gimbal", "description"):
                continue
            call = PUBLIC_GIMBAL[name]
            with pytest.raises(xfgcu.ClosedError):
                value = call(ag)
                if inspect.isawaitable(value):
                    await value

    asyncio.run(main())
    sim = xfgcu.Simulator()
    sim.close()
    for call in (lambda: sim.stats(), lambda: sim.notes(), lambda: sim.fault(silent=1), lambda: sim.faults(),
                 lambda: sim.configuration(), lambda: sim.disconnect(10)):  # fmt: skip
        with pytest.raises(xfgcu.ClosedError, match="^the simulator is closed$"):
            call()
    assert public(xfgcu.Simulator) == ["configuration", "disconnect", "fault", "faults", "notes", "stats"]


def test_errors_speak_python() -> None:
    """No option spelling, no program hint: the function, the parameter and the range."""
    messages = []
    for call in (
        lambda: xfgcu.encode_command("zoom_to", factor=300000.0),
        lambda: xfgcu.encode_command("zoom_to"),
        lambda: xfgcu.encode_command("zoom_to", rat=5.5),
        lambda: xfgcu.encode_command("shuter"),
        lambda: xfgcu.encode_command("track", start=True),
        lambda: xfgcu.encode_command("zoom_in", cameras="9"),
        lambda: xfgcu.encode_command("palette", protocol=2, mode=50),
        lambda: xfgcu.encode_command("track"),
        lambda: xfgcu.encode_command("temp_alarm", on=True, high=5.0, low=10.0),
        lambda: xfgcu.encode_command("gaze_geo", lat=1),
    ):
        with pytest.raises((TypeError, ValueError)) as info:
            call()
        messages.append(str(info.value))
    assert messages[0] == "zoom_to: factor=300000.0 is out of range 1.0..3276.8"
    assert messages[7] == "track: give start=True box=X0,Y0,X1,Y1 or stop=True"
    for m in messages:
        assert "--" not in m and "xfgcu " not in m and "help" not in m, m
