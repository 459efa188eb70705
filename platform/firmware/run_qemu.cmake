# ctest driver for a firmware image: runs QEMU, echoes its output, and succeeds only if the
# exit status (main()'s return value, via semihosting) is 0 AND the output matches PASS_RE
# (a ctest PASS_REGULAR_EXPRESSION alone would ignore the exit status), AND, for each file in
# EXPECTED ('|'-separated paths, may be empty), the output holds the file's text byte for byte
# between a line "=== chain NAME" and a line "=== end NAME", NAME being the file's name up to
# its first dot.
#   cmake -DQEMU=... -DMACHINE=mps2-an386 -DCPU=cortex-m4 -DELF=... -DPASS_RE=...
#         [-DEXPECTED=a.chain.txt|b.chain.txt] -DTIMEOUT=<seconds> -P run_qemu.cmake
execute_process(
    COMMAND ${QEMU} -M ${MACHINE} -cpu ${CPU} -nographic
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

string(REPLACE "|" ";" expected_files "${EXPECTED}")
foreach(file IN LISTS expected_files)
    get_filename_component(name ${file} NAME_WE)
    file(READ ${file} want)
    set(begin_marker "=== chain ${name}\n")
    set(end_marker "=== end ${name}\n")
    string(FIND "${out}" "${begin_marker}" begin)
    string(FIND "${out}" "${end_marker}" end)
    if(begin EQUAL -1 OR end EQUAL -1 OR end LESS begin)
        message(FATAL_ERROR "FAIL: the firmware printed no '${name}' block")
    endif()
    string(LENGTH "${begin_marker}" marker_length)
    math(EXPR begin "${begin} + ${marker_length}")
    math(EXPR length "${end} - ${begin}")
    string(SUBSTRING "${out}" ${begin} ${length} got)
    if(NOT got STREQUAL want)
        # Report the first line that differs.
        string(REPLACE "\n" ";" got_lines "${got}")
        string(REPLACE "\n" ";" want_lines "${want}")
        list(LENGTH got_lines got_count)
        list(LENGTH want_lines want_count)
        set(line 0)
        while(line LESS got_count AND line LESS want_count)
            list(GET got_lines ${line} g)
            list(GET want_lines ${line} w)
            if(NOT g STREQUAL w)
                break()
            endif()
            math(EXPR line "${line} + 1")
        endwhile()
        set(g "(none)")
        set(w "(none)")
        if(line LESS got_count)
            list(GET got_lines ${line} g)
        endif()
        if(line LESS want_count)
            list(GET want_lines ${line} w)
        endif()
        math(EXPR line "${line} + 1")
        message(FATAL_ERROR "FAIL: ${name}: the firmware's text differs from ${file} at line ${line}\n"
                            "  firmware: ${g}\n  host:     ${w}")
    endif()
    message(STATUS "${name}: the firmware's text equals ${file} byte for byte")
endforeach()
