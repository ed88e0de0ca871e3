# Toolchain file for bare-metal RISC-V with Debian's gcc-riscv64-unknown-elf, which has no C
# library: the codec and client are built with XF_NO_LIBC (their own byte loops), the simulator
# (it needs libm) is left out.
#   cmake --preset riscv      or      cmake -S . -B build/rv -DCMAKE_TOOLCHAIN_FILE=cmake/riscv64-unknown-elf.cmake
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR riscv)
set(CMAKE_C_COMPILER riscv64-unknown-elf-gcc)
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)

set(XFGCU_RISCV_ARCH "rv32imac" CACHE STRING "-march for the RISC-V target")
set(XFGCU_RISCV_ABI "ilp32" CACHE STRING "-mabi for the RISC-V target")
set(CMAKE_C_FLAGS_INIT "-march=${XFGCU_RISCV_ARCH} -mabi=${XFGCU_RISCV_ABI} -ffreestanding -ffunction-sections -fdata-sections")
set(XFGCU_NO_LIBC ON CACHE BOOL "no C library on this toolchain")

set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
