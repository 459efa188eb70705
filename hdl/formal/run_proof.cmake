# Bounded proof of the gradient block's stream rules (hdl/formal/stream_props.v) with yosys's
# SAT solver: every assertion holds in every state reachable within DEPTH clocks from reset,
# MAX_WIDTH 2 (rows short enough that the depth covers frames of several rows and their
# output). Used by the ctests hdl_formal_stream and hdl_formal_mutant.
#
#   cmake -DYOSYS=... -DRTL=hdl/rtl -DPROPS=hdl/formal/stream_props.v -DWORK=dir [-DDEPTH=20]
#         [-DMUTANT="from|to"] -P run_proof.cmake
#
# MUTANT (hdl_formal_mutant, marked WILL_FAIL): the proof runs on a copy of gradient.v with the
# text `from` replaced by `to` (it must occur), and the script exits with an error only when
# yosys finds a counterexample; any other outcome exits 0, so the test passes for exactly that
# reason.
foreach(_v YOSYS RTL PROPS WORK)
    if(NOT DEFINED ${_v})
        message(FATAL_ERROR "run_proof.cmake: -D${_v}=... is required")
    endif()
endforeach()
if(NOT DEFINED DEPTH)
    set(DEPTH 20)
endif()
file(MAKE_DIRECTORY ${WORK})
set(_gradient ${RTL}/gradient.v)
if(DEFINED MUTANT)
    string(FIND "${MUTANT}" "|" _bar)
    string(SUBSTRING "${MUTANT}" 0 ${_bar} _from)
    math(EXPR _bar "${_bar} + 1")
    string(SUBSTRING "${MUTANT}" ${_bar} -1 _to)
    file(READ ${RTL}/gradient.v _text)
    string(FIND "${_text}" "${_from}" _at)
    if(_at LESS 0)
        message("mutant text not found in gradient.v: ${_from}")
        return()
    endif()
    string(REPLACE "${_from}" "${_to}" _text "${_text}")
    set(_gradient ${WORK}/gradient_mutant.v)
    file(WRITE ${_gradient} "${_text}")
endif()

execute_process(
    COMMAND ${YOSYS} -q -l ${WORK}/proof.log -p
        "read_verilog -I${RTL} -formal ${PROPS} ${_gradient} ${RTL}/axis_slice.v ${RTL}/gradient_direction.v ${RTL}/gradient_dir_fold.v ${RTL}/gradient_dir_s51.v ${RTL}/gradient_dir_bin.v; chparam -set MAX_WIDTH 2 stream_props; prep -top stream_props; flatten; memory_map; opt -fast; sat -seq ${DEPTH} -prove-asserts -set-assumes -set-init-zero -verify"
    RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
file(READ ${WORK}/proof.log _log)
if(DEFINED MUTANT)
    if(NOT _rc EQUAL 0 AND _log MATCHES "proof did fail")
        message(FATAL_ERROR "the proof fails on the mutant (expected): ${_from} -> ${_to}")
    endif()
    message("the proof did not fail on the mutant (exit ${_rc})")
    return()
endif()
if(NOT _rc EQUAL 0)
    message(FATAL_ERROR "proof failed (yosys exit ${_rc}), see ${WORK}/proof.log\n${_err}")
endif()
message("stream rules hold for ${DEPTH} clocks from reset (MAX_WIDTH 2)")
