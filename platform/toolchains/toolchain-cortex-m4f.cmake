# Cortex-M4F: the Cortex-M4 with its single-precision FPU in use (hard-float ABI, fpv4-sp-d16),
# for the target tracker's float geometry and filter; images run on QEMU's mps2-an386, whose
# Cortex-M4 has the FPU (startup.c turns it on). Double precision stays in libgcc helpers, which
# the core double-free check looks for.
set(CMAKE_SYSTEM_PROCESSOR cortex-m4)
set(QT_FLOAT_ABI_FLAGS "-mfpu=fpv4-sp-d16 -mfloat-abi=hard")
set(QT_FIRMWARE_HARD_FLOAT ON)
include(${CMAKE_CURRENT_LIST_DIR}/toolchain-arm-none-eabi.cmake)
