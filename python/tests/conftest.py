"""Fixtures: the xfgcu program (to compare with), simulators on each link kind."""

from __future__ import annotations

import os
import shutil
import subprocess
from typing import Iterator, List

import pytest
from hypothesis import HealthCheck, settings

import xfgcu

# No example database in the source tree; a fixed budget so the suite stays fast.
settings.register_profile(
    "xfgcu", database=None, max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow]
)
settings.load_profile("xfgcu")

def pytest_report_header() -> str:
    return f"xfgcu {xfgcu.__version__} from {os.path.dirname(xfgcu.__file__)}"


LINKS = ["udp:127.0.0.1:0", "tcp:127.0.0.1:0", "pty"]


@pytest.fixture(scope="session")
def program() -> str:
    """The xfgcu program: $XFGCU_PROGRAM, else `xfgcu` on PATH. Missing: the test fails."""
    path = os.environ.get("XFGCU_PROGRAM") or shutil.which("xfgcu")
    assert path and os.access(path, os.X_OK), "set XFGCU_PROGRAM to the xfgcu program (run python/run_tests.sh)"
    return path


def run(program: str, *args: str, input: str = "") -> subprocess.CompletedProcess:
    return subprocess.run([program, *args], input=input, capture_output=True, text=True, timeout=30)


def program_encode(program: str, *args: str) -> bytes:
    r = run(program, "encode", *args)
    assert r.returncode == 0, r.stderr
    return bytes.fromhex(r.stdout.strip())


def program_decode(program: str, packets: List[bytes]) -> List[dict]:
    import json

    r = run(program, "decode", "--json", *[p.hex() for p in packets])
    assert r.returncode == 0, r.stderr
    return [json.loads(line) for line in r.stdout.splitlines()]


@pytest.fixture(params=LINKS, ids=["udp", "tcp", "pty"])
def sim(request: pytest.FixtureRequest) -> Iterator[xfgcu.Simulator]:
    with xfgcu.Simulator(request.param) as s:
        yield s


@pytest.fixture
def udp_sim() -> Iterator[xfgcu.Simulator]:
    with xfgcu.Simulator("udp:127.0.0.1:0") as s:
        yield s
