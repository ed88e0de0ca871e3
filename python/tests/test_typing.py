"""The package is typed (py.typed): `mypy --strict` passes on it, and catches a user's mistakes
with its types (Debian's mypy: scripts/setup.sh --dev)."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import xfgcu

SOURCE = Path(__file__).resolve().parent.parent  # python/: the package's sources
MYPY = ["/usr/bin/python3", "-m", "mypy", "--strict", "--no-error-summary"]

USER = """
import xfgcu

def pitch(g: xfgcu.Gimbal) -> float:
    t = g.telemetry()
    if t is None:
        return 0.0
    raw: int = int(t.raw.cam_pitch)
    return t.cam_pitch + raw * 0.0

def ok(r: xfgcu.Result) -> bool:
    return r.status == xfgcu.Status.OK and r.status == "ok"
"""


def mypy(*args: str, cwd: Path, env_path: str = "") -> subprocess.CompletedProcess:
    found = subprocess.run([MYPY[0], "-c", "import mypy"], capture_output=True).returncode == 0
    assert found, "these tests need Debian's mypy (apt-get install mypy, or scripts/setup.sh --dev)"
    env = dict(os.environ, MYPYPATH=env_path) if env_path else dict(os.environ)
    env.pop("PYTHONPATH", None)
    return subprocess.run([*MYPY, *args], cwd=cwd, env=env, capture_output=True, text=True, timeout=300)


def test_the_package_is_mypy_strict_clean(tmp_path: Path) -> None:
    r = mypy("--cache-dir", str(tmp_path / "cache"), "xfgcu", cwd=SOURCE)
    assert r.returncode == 0, r.stdout + r.stderr


def test_a_users_code_is_checked_against_its_types(tmp_path: Path) -> None:
    good, bad = tmp_path / "good.py", tmp_path / "bad.py"
    good.write_text(USER)
    bad.write_text(USER + "\ndef wrong(g: xfgcu.Gimbal) -> str:\n    return g.telemetry().cam_pitch\n")
    # the package as the tests import it: from the source tree, or installed (PYTHON's site-packages)
    where = Path(xfgcu.__file__).resolve().parent.parent
    installed = where.name in ("site-packages", "dist-packages")
    path_args = ["--python-executable", sys.executable] if installed else []
    r = mypy("--cache-dir", str(tmp_path / "cache"), *path_args, str(good), cwd=tmp_path,
             env_path="" if installed else str(where))  # fmt: skip
    assert r.returncode == 0, r.stdout + r.stderr
    r = mypy("--cache-dir", str(tmp_path / "cache"), *path_args, str(bad), cwd=tmp_path,
             env_path="" if installed else str(where))  # fmt: skip
    assert r.returncode == 1
    assert 'Item "None" of "Optional[Telemetry]" has no attribute "cam_pitch"' in r.stdout
    assert 'Incompatible return value type' in r.stdout and 'expected "str"' in r.stdout
