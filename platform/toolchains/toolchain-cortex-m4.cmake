# Cortex-M4 (its FPU is left unused: the quadrangle chain has no float); images run on QEMU's
# mps2-an386.
set(CMAKE_SYSTEM_PROCESSOR cortex-m4)
include(${CMAKE_CURRENT_LIST_DIR}/toolchain-arm-none-eabi.cmake)
