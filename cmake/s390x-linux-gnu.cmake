# Toolchain file for a big-endian Linux target: IBM Z (s390x) with Debian's cross compiler,
# its multiarch libraries (libcmocka-dev:s390x, libserialport-dev:s390x) and qemu-user, so
# that ctest runs the tests under emulation. scripts/bigendian.sh installs and runs it.
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR s390x)
set(CMAKE_C_COMPILER s390x-linux-gnu-gcc)
# No -L: the multiarch libc6:s390x (with its /lib/ld64.so.1) must be the one used; mixing it
# with the cross package's loader under /usr/s390x-linux-gnu makes every program abort.
set(CMAKE_CROSSCOMPILING_EMULATOR qemu-s390x)
set(ENV{PKG_CONFIG_LIBDIR} /usr/lib/s390x-linux-gnu/pkgconfig:/usr/share/pkgconfig)
set(CMAKE_FIND_ROOT_PATH /usr/s390x-linux-gnu)
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY BOTH)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE BOTH)
