"""The client and the simulator over UDP, TCP and a pty."""

from __future__ import annotations

import json
import os
import time

import pytest

import xfgcu
from conftest import run, wait_until


def test_workers_share_no_network() -> None:
    """Run side by side (run_tests.sh), each pytest worker has a network of its own: a client
    left talking by one worker's test can never reach the simulator of another's."""
    if "PYTEST_XDIST_WORKER" not in os.environ:
        pytest.skip("one test at a time: no workers to keep apart")
    here = os.readlink("/proc/self/ns/net")
    assert here != os.environ["XFGCU_TEST_NETWORK"], "a worker shares its network (tests/own_network.sh)"


def test_photo_and_results(sim: xfgcu.Simulator) -> None:
    with xfgcu.connect(sim.spec) as g:
        r = g.send("shutter")
        assert r.status == "ok" and r.ok and r.name == "shutter" and r.packets >= 1
        r = g.send("zoom-to", rate=5.5)
        assert r.status == "ok"
        assert wait_until(lambda: g.telemetry().zoom_cam1 == 5.5)  # type: ignore[union-attr]
        health = g.health()
        assert health.link == "up" and health.replies > 0 and health.crc_errors == 0
    stats = sim.stats()
    assert stats["photos"] == 1 and stats["executed"]["zoom_to"] == 1


def test_angles_in_euler(sim: xfgcu.Simulator) -> None:
    with xfgcu.connect(sim.spec) as g:
        assert g.send("euler").status == "ok"
        assert wait_until(lambda: g.set_angles(0.0, -30.0, 45.0) == "sent")
        assert wait_until(
            lambda: abs(g.telemetry().cam_pitch + 30.0) < 0.5  # type: ignore[union-attr]
            and abs(g.telemetry().cam_yaw - 45.0) < 0.5  # type: ignore[union-attr]
        )
        g.clear_control()


def test_rates_carrier_gnss(udp_sim: xfgcu.Simulator) -> None:
    with xfgcu.connect(udp_sim.spec, rate_hz=50) as g:
        assert g.send("head-lock").status == "ok"
        assert wait_until(lambda: g.set_rates(0.0, 0.0, 20.0) == "sent")
        yaw0 = g.telemetry().cam_yaw  # type: ignore[union-attr]
        assert wait_until(lambda: g.set_rates(0.0, 0.0, 20.0) == "sent" and g.telemetry().cam_yaw != yaw0)  # type: ignore[union-attr]
        g.set_rates(0.0, 0.0, 0.0)
        g.set_carrier(1.0, 2.0, 90.0, vel_north=3.0)
        g.set_gnss(22.5, 113.9, 50.0, satellites=12)
        assert wait_until(lambda: udp_sim.stats()["ins_valid_packets"] > 0)


def test_failed_with_cameras() -> None:
    with xfgcu.Simulator("udp:127.0.0.1:0", fail={"zoom_in": 0x02}) as s, xfgcu.connect(s.spec) as g:
        r = g.send("zoom-in")
        assert r.status == "failed" and r.failed_cameras == 0x02


def test_timeout_and_link_lost(udp_sim: xfgcu.Simulator) -> None:
    with xfgcu.connect(udp_sim.spec, command_timeout_ms=300, stale_ms=100, down_ms=2000) as g:
        udp_sim.fault(silent=1)
        assert g.send("shutter").status == "timeout"
        udp_sim.fault(silent=0)
        assert wait_until(lambda: g.health().link == "up")
    with xfgcu.connect(udp_sim.spec, command_timeout_ms=5000, stale_ms=100, down_ms=300) as g:
        udp_sim.fault(silent=1)
        assert g.send("shutter").status == "link_lost"
        assert g.health().link == "down"
        udp_sim.fault(silent=0)


def test_unsupported_model_and_force() -> None:
    # Z-6A (code 0) has no palette by V2.0.6's list: refused, unless forced
    with xfgcu.Simulator("udp:127.0.0.1:0", model="Z-6A") as s, xfgcu.connect(s.spec) as g:
        with pytest.raises(xfgcu.UnsupportedCommandError, match="Z-6A .code 0. does not support it"):
            g.send("palette", mode=1)
        assert s.stats()["executed"] == {}
        assert g.send("palette", mode=1, force=True).status == "failed"  # the simulated Z-6A refuses it too


def test_bad_arguments_raise(udp_sim: xfgcu.Simulator) -> None:
    with xfgcu.connect(udp_sim.spec) as g:
        with pytest.raises(xfgcu.CommandError, match=r"^lighting: level=999 is out of range 0\.\.255$"):
            g.send("lighting", level=999)
        with pytest.raises(TypeError):
            xfgcu.connect(udp_sim.spec, no_such_option=1)


def test_no_gcu_is_a_link_error() -> None:
    with pytest.raises(xfgcu.LinkError, match=r"no reply .* within 300 ms, in protocol version 1 or 2: check the link"):
        xfgcu.connect("udp:127.0.0.1:9,local=0", connect_timeout_ms=300)
    with pytest.raises(xfgcu.LinkError):
        xfgcu.connect("bogus:thing")


def test_telemetry_has_the_keys_of_monitor_json(program: str, udp_sim: xfgcu.Simulator) -> None:
    port = udp_sim.spec.split(":")[2].split(",")[0]
    r = run(program, "--udp", "127.0.0.1", "--gcu-port", port, "--local-port", "0", "monitor", "--json", "--count", "1")
    assert r.returncode == 0, r.stderr
    monitor = json.loads(r.stdout.splitlines()[0])
    with xfgcu.connect(udp_sim.spec) as g:
        telemetry = g.telemetry()
    assert telemetry is not None
    t = telemetry.as_dict()
    assert list(t) == list(monitor)  # the times first, as monitor --json has them
    assert t["time_utc"].endswith("Z") and abs(t["time_mono"] - time.monotonic()) < 5.0
    del t["time_mono"], t["time_utc"]  # what decode and encode know
    assert xfgcu.decode(xfgcu.encode(t)) == t


def test_telemetry_callback(udp_sim: xfgcu.Simulator) -> None:
    seen = []
    with xfgcu.connect(udp_sim.spec, rate_hz=50) as g:
        remove = g.on_telemetry(seen.append)
        assert wait_until(lambda: len(seen) >= 10)
        remove()
    assert all(isinstance(t, xfgcu.Telemetry) and t.direction == "gcu" for t in seen)


@pytest.mark.parametrize("protocol", [1, 2])
def test_one_value_everywhere(program: str, protocol: int) -> None:
    """A GCU packet reads the same, name, unit and value, in `monitor --json`, `decode --json` of its
    bytes, Python's decode() and Python's telemetry(), in both protocol versions; and as wire
    integers with --raw and raw=True (issue 28)."""
    with xfgcu.Simulator("udp:127.0.0.1:0", protocol=protocol) as sim:
        port = sim.spec.split(":")[2].split(",")[0]
        link = ["--link", f"udp:127.0.0.1:{port},local=0", "--protocol", str(protocol)]
        r = run(program, *link, "point", "--pitch", "-30", "--yaw", "45")
        assert r.returncode == 0, r.stderr
        r = run(program, *link, "monitor", "--json", "--count", "1")
        assert r.returncode == 0, r.stderr
        monitor = json.loads(r.stdout.splitlines()[0])
        with xfgcu.connect(sim.spec, protocol=protocol) as g:
            t = g.telemetry()
    assert t is not None
    del monitor["time_mono"], monitor["time_utc"]
    packet = xfgcu.encode(monitor)  # the bytes monitor printed
    decoded = json.loads(run(program, "decode", "--json", packet.hex()).stdout)
    assert decoded == monitor == xfgcu.decode(packet)
    assert monitor["version"] == protocol and monitor["cam_pitch"] == -30.0 and monitor["cam_yaw"] == 45.0
    assert monitor["hw_version"] == 3.1 and monitor["zoom_cam1"] == 1.0
    raw = json.loads(run(program, "--raw", "decode", "--json", packet.hex()).stdout)
    assert raw == xfgcu.decode(packet, raw=True)
    assert raw["cam_pitch"] == -3000 and raw["hw_version"] == 31 and raw["zoom_cam1"] == 10
    assert xfgcu.encode(raw, raw=True) == packet
    # telemetry() of another client: the same names and values, and the raw view
    assert list(t.as_dict())[2:] == list(monitor)
    assert t.cam_pitch == monitor["cam_pitch"] and t.hw_version == 3.1 and t.raw.hw_version == 31
    assert t.raw.cam_pitch == -3000 and list(t.raw.as_dict())[2:] == list(raw)


def test_protocol_2(program: str) -> None:
    with xfgcu.Simulator("tcp:127.0.0.1:0", protocol=2) as s, xfgcu.connect(s.spec, protocol=2) as g:
        assert g.send("osd", hide=True).status == "ok"
        t = g.telemetry()
        assert t is not None and t.version == 2 and t.camera_status is not None


def test_program_simulator_interop(program: str) -> None:
    import subprocess

    proc = subprocess.Popen([program, "sim", "--udp", "0"], stdout=subprocess.PIPE, text=True)
    try:
        line = proc.stdout.readline()  # type: ignore[union-attr]
        port = line.strip().rsplit(":", 1)[1]
        with xfgcu.connect(f"udp:127.0.0.1:{port},local=0") as g:
            assert g.send("shutter").status == "ok"
    finally:
        proc.terminate()
        proc.wait(10)


def test_calibration_operating_then_ok() -> None:
    with xfgcu.Simulator("udp:127.0.0.1:0", calibration_ms=300) as s, xfgcu.connect(s.spec) as g:
        r = g.send("calibration")
        assert r.status == "ok" and r.elapsed_ms >= 250


def test_pty_with_a_stable_link(tmp_path) -> None:  # type: ignore[no-untyped-def]
    link = str(tmp_path / "gcu")
    with xfgcu.Simulator("pty:" + link) as s:
        assert s.spec == "serial:" + link
        with xfgcu.connect(s.spec) as g:
            assert g.send("shutter").ok
            assert g.set_rates(0.0, 0.0, 0.0) in ("sent", "wrong_kind")
            assert g.health().control in ("sent", "wrong_kind")


def test_simulator_spec_errors() -> None:
    with pytest.raises(ValueError):
        xfgcu.Simulator("carrier-pigeon")
    with pytest.raises(TypeError, match="unexpected option 'no_such_setting'"):
        xfgcu.Simulator("udp:127.0.0.1:0", no_such_setting=1)
    with pytest.raises(ValueError):
        xfgcu.Simulator("udp:127.0.0.1:0", model="no such model")


def test_reordering_link_no_false_ok() -> None:
    # Packets overtake one another (0..60 ms each way) and 30 % arrive twice: with reorder_ms
    # bounding that, every shutter is ok on its own reply and the GCU takes each once.
    with xfgcu.Simulator("udp:127.0.0.1:0", jitter_ms=60, dup_permille=300) as sim:
        with xfgcu.connect(sim.spec, reorder_ms=100) as gimbal:
            results = [gimbal.send("shutter") for _ in range(10)]
        assert [r.status for r in results] == ["ok"] * 10
        assert sim.stats()["photos"] == 10


def test_close_settles() -> None:
    # Replies 300 ms late: a command that timed out after 200 ms still has its "ok" on the way;
    # close() waits for it (and a null's reply after it), so that the next client cannot take it.
    with xfgcu.Simulator("udp:127.0.0.1:0", delay_ms=300) as sim:
        gimbal = xfgcu.connect(sim.spec, command_timeout_ms=200)
        assert gimbal.send("shutter").status == "timeout"
        t0 = time.monotonic()
        gimbal.close()
        assert time.monotonic() - t0 >= 0.25
        with xfgcu.connect(sim.spec, command_timeout_ms=200) as second:
            assert second.send("shutter").status == "timeout"  # never the first one's late ok


def test_review_fixes() -> None:
    # a configuration cut to its C type, or one the library would refuse, is a ValueError
    with pytest.raises(ValueError):
        xfgcu.connect("udp:127.0.0.1:9", rate_hz=65586)
    with pytest.raises(ValueError, match="stale_ms"):
        xfgcu.connect("udp:127.0.0.1:9", rate_hz=1)
    with pytest.raises(ValueError, match=r"^encode_command: protocol=257 is out of range 1\.\.2$"):
        xfgcu.encode_command("shutter", protocol=257)
    sim = xfgcu.Simulator("udp:127.0.0.1:0")
    gimbal = xfgcu.connect(sim.spec)
    # from a telemetry callback, send() would wait on its own thread
    errors: list = []

    def callback(t: dict) -> None:
        for call in (lambda: gimbal.send("shutter"), gimbal.close):
            try:
                call()
            except RuntimeError as e:
                errors.append(e)

    remove = gimbal.on_telemetry(callback)
    assert wait_until(lambda: len(errors) > 1)
    remove()
    gimbal.health()  # close() from the callback refused, and left the gimbal open
    # two threads closing at once: one closes, the other returns
    import threading

    closers = [threading.Thread(target=gimbal.close) for _ in range(2)]
    for c in closers:
        c.start()
    for c in closers:
        c.join()
    with pytest.raises(xfgcu.LinkError):
        gimbal.health()
    sim.close()
    sim.close()
    with pytest.raises(xfgcu.LinkError):
        sim.stats()
    with pytest.raises(xfgcu.LinkError):
        sim.fault(drop_next=1)
