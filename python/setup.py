"""Builds the native library (libxfgcu_py.so, python/CMakeLists.txt) with CMake from the
project's sources one directory up, and ships it inside the package. The metadata is in
pyproject.toml.

Environment: XFGCU_CMAKE (the cmake program, default "cmake"), XFGCU_BUILD_JOBS (default 2).
"""

import os
import shutil
import subprocess

from setuptools import setup
from setuptools.command.build_py import build_py
from setuptools.dist import Distribution

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.dirname(HERE)  # the project: python/.. holds CMakeLists.txt


class BuildWithNative(build_py):
    """build_py, then the native library into the built package."""

    def run(self) -> None:
        super().run()
        build = os.path.join(os.path.abspath(self.build_lib), "..", "xfgcu-native")
        cmake = os.environ.get("XFGCU_CMAKE", "cmake")
        options = [
            "-DCMAKE_BUILD_TYPE=Release",
            "-DXFGCU_BUILD_PYTHON=ON",
            "-DXFGCU_BUILD_TESTS=OFF",
            "-DXFGCU_BUILD_TOOLS=OFF",
            "-DXFGCU_BUILD_BENCH=OFF",
            "-DXFGCU_BUILD_EXAMPLES=OFF",
            "-DXFGCU_INSTALL=OFF",
        ]
        subprocess.check_call([cmake, "-S", SOURCE, "-B", build] + options)
        jobs = os.environ.get("XFGCU_BUILD_JOBS", "2")
        subprocess.check_call([cmake, "--build", build, "--target", "xfgcu_py", "-j", jobs])
        target = os.path.join(self.build_lib, "xfgcu")
        os.makedirs(target, exist_ok=True)
        shutil.copy2(os.path.join(build, "python", "libxfgcu_py.so"), os.path.join(target, "libxfgcu_py.so"))


class BinaryDistribution(Distribution):
    """The package holds a shared library: a platform wheel, installed in platlib."""

    def has_ext_modules(self) -> bool:
        return True


COMMANDS = {"build_py": BuildWithNative}
try:  # wheel's command, where the wheel package is there (Debian's python3-wheel)
    from wheel.bdist_wheel import bdist_wheel

    class PlatformWheel(bdist_wheel):
        """The native library is loaded by ctypes, not built against CPython: one wheel for any
        Python 3 on this platform (py3-none-linux_x86_64)."""

        def get_tag(self) -> tuple:
            plat = super().get_tag()[2]
            return "py3", "none", plat

    COMMANDS["bdist_wheel"] = PlatformWheel
except ImportError:
    pass

setup(cmdclass=COMMANDS, distclass=BinaryDistribution)
