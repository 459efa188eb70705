# Bare-metal Cortex-M with Debian's gcc-arm-none-eabi and newlib: included by
# toolchain-cortex-m3.cmake, toolchain-cortex-m4.cmake and toolchain-cortex-m4f.cmake after they
# set CMAKE_SYSTEM_PROCESSOR (the -mcpu value) and, for the FPU, QT_FLOAT_ABI_FLAGS (default:
# the soft-float ABI, every float operation a libgcc helper).
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_C_COMPILER arm-none-eabi-gcc)
set(CMAKE_CXX_COMPILER arm-none-eabi-g++)
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
if(NOT QT_FLOAT_ABI_FLAGS)
    set(QT_FLOAT_ABI_FLAGS "-mfloat-abi=soft")
endif()
set(QT_CPU_FLAGS "-mcpu=${CMAKE_SYSTEM_PROCESSOR} -mthumb ${QT_FLOAT_ABI_FLAGS}")
set(CMAKE_C_FLAGS_INIT "${QT_CPU_FLAGS} -ffunction-sections -fdata-sections")
set(CMAKE_CXX_FLAGS_INIT "${QT_CPU_FLAGS} -Wno-psabi -ffunction-sections -fdata-sections -fno-exceptions -fno-rtti -fno-threadsafe-statics")
set(CMAKE_EXE_LINKER_FLAGS_INIT "-Wl,--gc-sections")
