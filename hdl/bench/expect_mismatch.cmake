# Runs the vector bench with a corrupted expected beat (hdl_fault_injection, marked WILL_FAIL).
# Exits with an error only when the bench failed and reported the mismatch at the corrupted
# beat, so the test passes for exactly that reason and fails for any other outcome (the bench
# passing, not starting, or failing elsewhere).
#   cmake -DVVP=... -DBENCH=... -DBEAT=K -DARGS=a|b|c -P expect_mismatch.cmake
string(REPLACE "|" ";" _args "${ARGS}")
execute_process(COMMAND ${VVP} -n ${BENCH} ${_args} +corrupt=${BEAT}
                RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
message("${_out}${_err}")
if(NOT _rc EQUAL 0 AND _out MATCHES "MISMATCH beat=${BEAT} ")
    message(FATAL_ERROR "bench reported the injected mismatch at beat ${BEAT} (expected)")
endif()
message("bench did not report the injected mismatch at beat ${BEAT}")
