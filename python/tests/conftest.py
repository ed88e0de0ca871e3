"""Fixtures: the xfgcu program (to compare with), simulators on each link kind."""

from __future__ import annotations

import os
import shutil
import subprocess
import tempfile
import time
from typing import Callable, Iterator, List

import pytest
from hypothesis import HealthCheck, settings
from hypothesis.configuration import set_hypothesis_home_dir

import xfgcu

# Nothing written into the source tree: no example database, and hypothesis's own cache (the
# characters of text strategies) in the temporary directory. A fixed budget so the suite stays fast.
set_hypothesis_home_dir(os.environ.get("HYPOTHESIS_STORAGE_DIRECTORY") or os.path.join(tempfile.gettempdir(), "xfgcu-hypothesis"))
settings.register_profile(
    "xfgcu", database=None, max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow]
)
settings.load_profile("xfgcu")


def pytest_configure(config: pytest.Config) -> None:
    # pytest itself, or xdist's controller: the workers see it (test_workers_share_no_network)
    if "PYTEST_XDIST_WORKER" not in os.environ and os.path.exists("/proc/self/ns/net"):
        os.environ["XFGCU_TEST_NETWORK"] = os.readlink("/proc/self/ns/net")


def pytest_report_header() -> str:
    return f"xfgcu {xfgcu.__version__} from {os.path.dirname(xfgcu.__file__)}"


LINKS = ["udp:127.0.0.1:0", "tcp:127.0.0.1:0", "pty"]


def wait_until(predicate: Callable[[], bool], timeout: float = 5.0) -> bool:
    """Whether ``predicate`` holds within ``timeout`` seconds (a bound that holds on a loaded
    machine: the tests wait for an event, never assert how soon it comes)."""
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        if predicate():
            return True
        time.sleep(0.02)
    return predicate()


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
