#!/bin/sh
# Run the Python package's tests (python/tests, pytest) with Debian's Python.
#
# usage: python/run_tests.sh [BUILD_DIR]
#
# BUILD_DIR: a CMake build of the project. Its libxfgcu_py.so is tested with the package from
# this source tree (configured with -DXFGCU_BUILD_PYTHON=ON here if it was not), and its xfgcu
# program is what the tests compare with. Without BUILD_DIR, one is made in a temporary
# directory (and removed).
# Environment: PYTHON (default /usr/bin/python3); XFGCU_TEST_INSTALLED=1 tests the xfgcu package
# PYTHON imports (a pip-installed one, e.g. PYTHON=venv/bin/python) instead of this tree's.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
python=${PYTHON:-/usr/bin/python3}
case $python in */*) python=$(cd "$(dirname "$python")" && pwd)/$(basename "$python") ;; esac # tests run from python/tests
build=${1:-}
if [ -z "$build" ]; then
    build=$(mktemp -d "${TMPDIR:-/tmp}/xfgcu-python-tests.XXXXXX")
    trap 'rm -rf "$build"' EXIT
fi
mkdir -p "$build"
build=$(cd "$build" && pwd) # the tests run from python/tests: no relative path may reach them
if [ ! -f "$build/CMakeCache.txt" ] || [ ! -f "$build/python/libxfgcu_py.so" ]; then
    cmake -S "$here/.." -B "$build" -DXFGCU_BUILD_PYTHON=ON -DXFGCU_BUILD_TOOLS=ON >/dev/null
fi
cmake --build "$build" -j2 --target xfgcu xfgcu_py >/dev/null # incremental: never an old library
export XFGCU_PROGRAM="$build/tools/xfgcu"
if [ -z "${XFGCU_TEST_INSTALLED:-}" ]; then
    export XFGCU_PY_LIB="$build/python/libxfgcu_py.so"
    export PYTHONPATH="$here${PYTHONPATH:+:$PYTHONPATH}"
fi
export PYTHONDONTWRITEBYTECODE=1 # nothing written into the source tree
cd "$here/tests"
# One test at a time: several processes' UDP clients and simulators on ephemeral ports can reach
# one another's (a closed test's client, a port reused), and tests count what a simulator executed.
"$python" -m pytest -q -p no:cacheprovider . # not exec: the EXIT trap removes a temporary build
