"""The protocol version on the Python side (issue 29): connect() finds the version a GCU answers
by itself, reports it, and follows the GCU's version for ranges and meanings; the simulator can
answer one version only and can send the execution state once."""

from __future__ import annotations

import time
from typing import List

import pytest

import xfgcu
from conftest import wait_until


@pytest.mark.parametrize("version", [1, 2])
def test_connect_unchanged_against_a_gcu_of_one_version(version: int) -> None:
    """A GCU that answers only version 1 or only version 2 (in its own version): the default
    connect() finds it, says which, and a photo is taken."""
    with xfgcu.Simulator(protocol=version, answer_only=version) as sim, xfgcu.connect(sim.spec) as g:
        assert g.protocol == version and g.gcu_protocol == version
        health = g.health()
        assert (health.version_sent, health.version_answered, health.version_gcu) == (version, version, version)
        assert g.send("shutter").ok
        t = g.telemetry()
        assert t is not None and t.version == version
        assert sim.stats()["photos"] == 1
        if version == 2:
            assert sim.stats()["ignored"] > 0  # the client's version-1 packets went unanswered, then it tried 2


def test_a_fixed_version_is_silent_against_the_other() -> None:
    with xfgcu.Simulator(protocol=2, answer_only=2) as sim:
        with pytest.raises(xfgcu.LinkError, match=r"within 500 ms, in protocol version 1 only: .*protocol=None tries both$"):
            xfgcu.connect(sim.spec, protocol=1, connect_timeout_ms=500)
        with xfgcu.connect(sim.spec, protocol=2) as g:
            assert g.protocol == 2


def test_ranges_follow_the_gcus_version() -> None:
    # pip mode 3 and palette 0..10 are V0.2's; a V0.2 GCU is met with the default settings
    with xfgcu.Simulator(protocol=2, answer_only=2) as sim, xfgcu.connect(sim.spec) as g:
        assert g.send("pip", mode=3).ok
        with pytest.raises(xfgcu.CommandError, match=r"^palette: mode=50 is out of range for protocol 2"):
            g.send("palette", mode=50)
        assert sim.stats()["executed"] == {"pip": 1}
    with xfgcu.Simulator(protocol=1) as sim, xfgcu.connect(sim.spec) as g:
        assert g.gcu_protocol == 1 and g.send("palette", mode=50).ok


def test_a_gcu_that_answers_every_version_keeps_the_first() -> None:
    with xfgcu.Simulator(protocol=2) as sim, xfgcu.connect(sim.spec) as g:
        assert g.protocol == 1  # tried first, and answered
        assert g.gcu_protocol == 2  # the GCU's own version, whose meanings the client follows


def feedback_replies(state_once: bool) -> List[int]:
    """The lengths of the replies that carried an execution state while one shutter ran, on a
    link that holds each reply 100 ms (the client repeats the command meanwhile)."""
    with xfgcu.Simulator(state_once=state_once, delay_ms=100) as sim, xfgcu.connect(sim.spec) as g:
        assert sim.configuration()["state_once"] == int(state_once)
        stream = g.telemetry_stream(timeout=2.0)
        assert g.send("shutter").ok
        lengths = []
        for t in stream:  # the replies to the repeats come after the result
            if t.order_name == "shutter" and t.length > 72:
                lengths.append(t.length)
            if t.order_name == "null" and t.time_mono > time.monotonic() - 0.05:
                break
        assert sim.stats()["photos"] == 1
    return lengths


def test_state_once() -> None:
    """state_once: only the first reply after the execution carries the state; by default the
    replies to every repeat of the order do."""
    assert len(feedback_replies(True)) == 1
    assert len(feedback_replies(False)) > 1


def test_health_reports_the_link_order() -> None:
    # a clean loopback link shows that it keeps order: the client drops its own bound
    with xfgcu.Simulator() as sim, xfgcu.connect(sim.spec) as g:
        assert wait_until(lambda: g.health().in_order)
        health = g.health()
        assert health.reorder_ms == 0 and health.out_of_turn == 0
    # a bound given by the user stands, whatever the link shows (reorder_fixed)
    with xfgcu.Simulator() as sim, xfgcu.connect(sim.spec, reorder_ms=80) as g:
        assert wait_until(lambda: g.health().in_order)
        assert g.health().reorder_ms == 80
    # a link that duplicates: replies out of turn are counted, and the client keeps a bound
    with xfgcu.Simulator(dup_permille=300) as sim, xfgcu.connect(sim.spec) as g:
        assert wait_until(lambda: g.health().out_of_turn > 0)
        health = g.health()
        assert not health.in_order and health.reorder_ms > 0


def test_reordering_link_default_settings() -> None:
    """Packets overtake one another and 30 % arrive twice, and the user set no bound: the client
    judges the link itself, so every shutter is ok on its own reply and the GCU takes each once."""
    with xfgcu.Simulator(jitter_ms=60, dup_permille=300) as sim:
        with xfgcu.connect(sim.spec) as gimbal:
            results = [gimbal.send("shutter") for _ in range(10)]
        assert [r.status for r in results] == ["ok"] * 10
        assert sim.stats()["photos"] == 10


def test_simulator_notes_its_strict_readings() -> None:
    # record with a parameter other than 0x01: V2.0.6 leaves it open; the simulator fails it
    packet = bytearray(xfgcu.encode({"direction": "host", "order": "record", "params": "00"}))
    with xfgcu.Simulator() as sim, xfgcu.connect(sim.spec) as g:
        del g  # only to have a link up; the packet goes through a raw socket below
        import socket

        host, port = sim.spec.split(":")[1], int(sim.spec.split(":")[2].split(",")[0])
        with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
            s.sendto(bytes(packet), (host, port))
            assert wait_until(lambda: sim.stats()["strict"] > 0)
        notes = sim.notes()
    assert len(notes) == 1 and notes[0].startswith("record (0x21): ")
