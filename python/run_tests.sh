#!/bin/sh
# Run the Python package's tests (python/tests, pytest) with Debian's Python.
#
# usage: python/run_tests.sh [BUILD_DIR]
#
# BUILD_DIR: a CMake build of the project. Its libxfgcu_py.so is tested with the package from
# this source tree (configured with -DXFGCU_BUILD_PYTHON=ON here if it was not), and its xfgcu
# program is what the tests compare with. Without BUILD_DIR, one is made in a temporary
# directory (and removed).
# Environment: PYTHON (default /usr/bin/python3); XFGCU_TEST_WORKERS (default 4); XFGCU_TEST_INSTALLED=1 tests the xfgcu package
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
# Four workers (pytest-xdist), each in a network namespace of its own (own_network.sh): most tests
# wait on a simulator, and tests count what their simulator executed, which a client of another
# worker must never reach. Where namespaces or xdist are not to be had: one test at a time.
# XFGCU_TEST_WORKERS=1 asks for one at a time.
workers=${XFGCU_TEST_WORKERS:-4}
case $workers in
    '' | *[!0-9]*) echo "run_tests.sh: XFGCU_TEST_WORKERS='$workers' is not a number of workers" >&2; exit 2 ;;
esac
set -- -q -p no:cacheprovider
why=
if [ "$workers" -le 1 ]; then
    :
elif ! "$python" -c 'import xdist' 2>/dev/null; then
    why="$python has no pytest-xdist"
elif ! why=$(./own_network.sh "$python" -c '' 2>&1); then
    why="no network namespace of its own here ($(printf '%s' "$why" | head -1))"
else
    why=
    set -- "$@" -p xdist --dist load --tx "$workers*popen//python='$here/tests/own_network.sh' '$python'"
fi
[ -z "$why" ] || echo "run_tests.sh: one test at a time: $why"
"$python" -m pytest "$@" . # not exec: the EXIT trap removes a temporary build
