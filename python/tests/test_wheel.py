"""The wheel the build makes installs into a plain venv (no system site packages, no build step,
no network) and runs: built once with Debian's python3 (python3-setuptools, python3-wheel), as
python/README.md shows."""

from __future__ import annotations

import glob
import os
import shutil
import subprocess
from pathlib import Path

PROJECT = Path(__file__).resolve().parent.parent.parent  # the clone: python/.. holds CMakeLists.txt
SYSTEM_PYTHON = "/usr/bin/python3"

PHOTO = """
import os, sys, xfgcu
assert "XFGCU_PY_LIB" not in os.environ
assert xfgcu.__file__.startswith(sys.prefix), xfgcu.__file__
with xfgcu.Simulator() as sim, xfgcu.connect(sim.spec) as gimbal:
    result = gimbal.send("shutter")
    print(result.status, sim.stats()["photos"], gimbal.protocol)
"""


def run(*cmd: str, cwd: Path) -> str:
    env = {k: v for k, v in os.environ.items() if k not in ("XFGCU_PY_LIB", "PYTHONPATH", "VIRTUAL_ENV")}
    env["XFGCU_BUILD_JOBS"] = "2"
    r = subprocess.run(cmd, cwd=cwd, env=env, capture_output=True, text=True, timeout=900)
    assert r.returncode == 0, f"{' '.join(cmd)}:\n{r.stdout[-3000:]}\n{r.stderr[-3000:]}"
    return r.stdout


def test_wheel_into_a_plain_venv(tmp_path: Path) -> None:
    source = tmp_path / "xfgcu"  # a copy: the build writes python/build and the egg-info in place
    shutil.copytree(
        PROJECT, source,
        ignore=shutil.ignore_patterns(".git", "build", "dist", "*.egg-info", "__pycache__", "venv*"),
    )  # fmt: skip
    run(SYSTEM_PYTHON, "-m", "pip", "wheel", "--no-build-isolation", "--no-deps", "--no-index", "-w", "dist",
        str(source / "python"), cwd=tmp_path)  # fmt: skip
    wheels = glob.glob(str(tmp_path / "dist" / "xfgcu-*.whl"))
    assert len(wheels) == 1 and wheels[0].endswith("-py3-none-linux_x86_64.whl"), wheels
    run(SYSTEM_PYTHON, "-m", "venv", "plain", cwd=tmp_path)
    config = (tmp_path / "plain" / "pyvenv.cfg").read_text()
    assert "include-system-site-packages = false" in config
    run(str(tmp_path / "plain" / "bin" / "pip"), "install", "--no-index", wheels[0], cwd=tmp_path)
    shutil.rmtree(source)  # nothing of the clone is needed any more
    out = run(str(tmp_path / "plain" / "bin" / "python"), "-c", PHOTO, cwd=tmp_path)
    assert out.split() == ["ok", "1", "1"]
