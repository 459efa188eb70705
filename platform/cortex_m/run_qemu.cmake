# ctest driver for a firmware image: runs QEMU, echoes its output, and succeeds only if the
# exit status (main()'s return value, via semihosting) is 0 AND the output matches PASS_RE.
# (A ctest PASS_REGULAR_EXPRESSION alone would ignore the exit status.)
#   cmake -DQEMU=... -DELF=... -DPASS_RE=... -DTIMEOUT=<seconds> -P run_qemu.cmake
execute_process(
    COMMAND ${QEMU} -M mps2-an386 -cpu cortex-m4 -nographic
            -semihosting-config enable=on,target=native
            -icount shift=0  # 1 instruction = 1 ns virtual: deterministic SysTick counts
            -kernel ${ELF}
    RESULT_VARIABLE status
    OUTPUT_VARIABLE out ERROR_VARIABLE out
    ECHO_OUTPUT_VARIABLE ECHO_ERROR_VARIABLE
    TIMEOUT ${TIMEOUT})
if(NOT status STREQUAL "0")
    message(FATAL_ERROR "FAIL: ${ELF} exit status ${status}")
endif()
if(NOT out MATCHES "${PASS_RE}")
    message(FATAL_ERROR "FAIL: output of ${ELF} does not match '${PASS_RE}'")
endif()
