# Toolchain file for bare-metal Arm Cortex-M with Debian's gcc-arm-none-eabi.
#   cmake -S . -B build/m4 -DCMAKE_TOOLCHAIN_FILE=cmake/arm-none-eabi.cmake [-DXFGCU_ARM_CPU=cortex-m0plus]
# Default CPU: Cortex-M4F (hard float). Only the header-only codec target is meaningful here:
# configure with -DXFGCU_BUILD_TESTS=OFF -DXFGCU_BUILD_TOOLS=OFF -DXFGCU_BUILD_BENCH=OFF.
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)
set(CMAKE_C_COMPILER arm-none-eabi-gcc)
set(CMAKE_ASM_COMPILER arm-none-eabi-gcc)
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY) # no semihosting or startup code to link probes

set(XFGCU_ARM_CPU "cortex-m4" CACHE STRING "Arm CPU for -mcpu")
if(XFGCU_ARM_CPU STREQUAL "cortex-m4")
  set(_xf_fpu "-mfloat-abi=hard -mfpu=fpv4-sp-d16")
else()
  set(_xf_fpu "-mfloat-abi=soft")
endif()
set(CMAKE_C_FLAGS_INIT "-mcpu=${XFGCU_ARM_CPU} -mthumb ${_xf_fpu} -ffunction-sections -fdata-sections")
set(CMAKE_EXE_LINKER_FLAGS_INIT "-Wl,--gc-sections -specs=nano.specs")

set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
