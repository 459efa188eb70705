# Runs a vector bench with a corrupted expected beat (hdl_fault_gradient, hdl_fault_edges, marked
# WILL_FAIL). Exits with an error only when the bench failed and reported the mismatch at the
# corrupted beat, so the test passes for exactly that reason and fails for any other outcome (the
# bench passing, not starting, or failing elsewhere).
#   cmake -DVVP=... -DBENCH=... -DBEAT=K -DKIND=gradient|edge -DARGS=a|b|c -P expect_mismatch.cmake
string(REPLACE "|" ";" _args "${ARGS}")
if(KIND STREQUAL "edge")
    set(_plusarg +corrupt_edge=${BEAT})
    set(_report "MISMATCH edge=${BEAT} ")
else()
    set(_plusarg +corrupt=${BEAT})
    set(_report "MISMATCH beat=${BEAT} ")
endif()
execute_process(COMMAND ${VVP} -n ${BENCH} ${_args} ${_plusarg}
                RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
message("${_out}${_err}")
if(NOT _rc EQUAL 0 AND _out MATCHES "${_report}")
    message(FATAL_ERROR "bench reported the injected mismatch at ${KIND} beat ${BEAT} (expected)")
endif()
message("bench did not report the injected mismatch at ${KIND} beat ${BEAT}")
