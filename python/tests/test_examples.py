"""The examples run against a simulator."""

from __future__ import annotations

import os
import subprocess
import sys

import xfgcu

EXAMPLES = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "examples")


def run_example(name: str, *args: str) -> subprocess.CompletedProcess:
    return subprocess.run(
        [sys.executable, os.path.join(EXAMPLES, name), *args], capture_output=True, text=True, timeout=60
    )


def test_point_and_photo(sim: xfgcu.Simulator) -> None:
    r = run_example("point_and_photo.py", sim.spec, "--pitch", "-45", "--yaw", "90")
    assert r.returncode == 0, r.stderr
    assert "pointing at pitch -45.00 yaw 90.00 deg" in r.stdout
    assert "photo: ok" in r.stdout
    stats = sim.stats()
    assert stats["photos"] == 1 and abs(stats["pitch"] + 45.0) < 0.5


def test_point_and_photo_own_simulator() -> None:
    r = run_example("point_and_photo.py")
    assert r.returncode == 0, r.stderr
    assert "simulator: 1 photo(s) taken" in r.stdout


def test_telemetry_async(udp_sim: xfgcu.Simulator) -> None:
    r = run_example("telemetry_async.py", udp_sim.spec, "--count", "60")
    assert r.returncode == 0, r.stderr
    lines = [line for line in r.stdout.splitlines() if line[:4].strip().isdigit()]
    assert len(lines) == 60
    assert "zoom-to: ok" in r.stdout and "link up" in r.stdout
    assert udp_sim.stats()["executed"]["zoom_to"] == 1
