# Cortex-M3 (no FPU, no DSP instructions): the soft-float build whose chain image must link no
# floating-point helper; images run on QEMU's mps2-an385.
set(CMAKE_SYSTEM_PROCESSOR cortex-m3)
include(${CMAKE_CURRENT_LIST_DIR}/toolchain-arm-none-eabi.cmake)
