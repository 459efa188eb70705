# Soak of the FPGA front end (docs/gradient.md, "Soak"): generates a soak stream with
# qt_vectors --soak and runs the front end's vector bench (tb_front_w640.vvp: edge beats and the
# gradient link between the blocks both checked) on it with random stalls on both sides and the
# stream's resets. Used by the ctest tests hdl_soak and hdl_soak_fault and by bench.sh hdl-soak.
#
#   cmake -DQT_VECTORS=... -DVVP=... -DBENCH=tb_front_w640.vvp -DPREFIX=DIR/name
#         [-DSEED=1] [-DPIXELS=1050000] [-DSTALL=30] [-DMAX_WIDTH=640] [-DFAULT=1]
#         -P run_soak.cmake
#
# Prints the generator's counts, the bench's last lines and one summary line
#   soak seed=S pixels=P frames=F resets=R faults=N errors=E out_beats=O checked=C cut=X
#        mismatches=0 seconds=T
# and exits non-zero unless the bench passed. The vector files stay under PREFIX only when the
# run did not end as intended.
#
# FAULT=1 (hdl_soak_fault, marked WILL_FAIL): flips bit 0 of the expected first beat of the
# first segment after a reset that is long enough for the block to emit that beat whatever the
# stalls, and exits with an error only when the bench reported the mismatch at that beat as the
# first beat after a reset; any other outcome (the bench passing, failing elsewhere, no such
# segment, the generator failing) exits 0, so the test passes for exactly that reason.
foreach(_v QT_VECTORS VVP BENCH PREFIX)
    if(NOT DEFINED ${_v})
        message(FATAL_ERROR "run_soak.cmake: -D${_v}=... is required")
    endif()
endforeach()
if(NOT DEFINED SEED)
    set(SEED 1)
endif()
if(NOT DEFINED PIXELS)
    set(PIXELS 1050000)
endif()
if(NOT DEFINED STALL)
    set(STALL 30)
endif()
if(NOT DEFINED MAX_WIDTH)
    set(MAX_WIDTH 640)
endif()
set(_depth 2097152)     # tb_front DEPTH: beats per vector file
set(_rdepth 65536)      # tb_front RDEPTH: reset points

# In fault mode every failure other than the intended one must let the script succeed.
macro(soak_fail _msg)
    if(FAULT)
        message("${_msg}")
        message("hdl_soak_fault: the bench did not report the injected mismatch")
        return()
    endif()
    message(FATAL_ERROR "${_msg}")
endmacro()

get_filename_component(_dir ${PREFIX} DIRECTORY)
file(MAKE_DIRECTORY ${_dir})

# ---- the stream
execute_process(COMMAND ${QT_VECTORS} --soak ${SEED} ${PIXELS} ${PREFIX}
                RESULT_VARIABLE _rc OUTPUT_VARIABLE _gen ERROR_VARIABLE _gen_err
                OUTPUT_STRIP_TRAILING_WHITESPACE)
if(NOT _rc EQUAL 0)
    soak_fail("qt_vectors --soak failed (${_rc}): ${_gen}${_gen_err}")
endif()
message("${_gen}")
foreach(_k max_width threshold in_beats out_beats edge_beats errors resets pixels frames faults)
    if(NOT _gen MATCHES " ${_k}=([0-9]+)")
        soak_fail("cannot read ${_k} from qt_vectors --soak: ${_gen}")
    endif()
    set(_${_k} ${CMAKE_MATCH_1})
endforeach()
if(NOT _max_width EQUAL MAX_WIDTH)
    soak_fail("stream assumes MAX_WIDTH ${_max_width}, bench built for ${MAX_WIDTH}")
endif()
if(_in_beats GREATER _depth OR _out_beats GREATER _depth OR _edge_beats GREATER _depth OR
   _resets GREATER _rdepth)
    soak_fail("stream too long for the bench (${_depth} beats, ${_rdepth} resets per run): "
              "use fewer pixels per seed")
endif()

set(_args +in=${PREFIX}.in.hex +out=${PREFIX}.out.hex +nin=${_in_beats} +nout=${_out_beats}
          +edges=${PREFIX}.edges.hex +nedges=${_edge_beats} +threshold=${_threshold}
          +errors=${_errors} +resets=${PREFIX}.resets.hex +nresets=${_resets}
          +seed=${SEED} +stall=${STALL} +vary_threshold=1 +scramble_threshold=1)

# ---- fault mode: the beat to corrupt
if(FAULT)
    file(STRINGS ${PREFIX}.resets.hex _lines)
    list(LENGTH _lines _n)
    set(_beat -1)
    set(_i 0)
    while(_i LESS _n AND _beat LESS 0)
        list(GET _lines ${_i} _line)
        string(SUBSTRING "${_line}" 8 8 _h)
        math(EXPR _start "0x${_h}")
        math(EXPR _i "${_i} + 1")
        set(_end ${_out_beats})
        if(_i LESS _n)
            list(GET _lines ${_i} _line)
            string(SUBSTRING "${_line}" 8 8 _h)
            math(EXPR _end "0x${_h}")
        endif()
        # The block holds at most a flushed row and its pipeline behind the model.
        math(EXPR _len "${_end} - ${_start}")
        math(EXPR _need "2 * ${MAX_WIDTH} + 16")
        if(NOT _len LESS _need)
            set(_beat ${_start})
            math(EXPR _reset "${_i} - 1")
        endif()
    endwhile()
    if(_beat LESS 0)
        soak_fail("no reset followed by a segment of ${_need} beats or more")
    endif()
    message("corrupting expected beat ${_beat}, the first after reset ${_reset}")
    list(APPEND _args +corrupt=${_beat})
endif()

# ---- the bench
string(TIMESTAMP _t0 "%s")
execute_process(COMMAND ${VVP} -n ${BENCH} ${_args}
                RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
string(TIMESTAMP _t1 "%s")
math(EXPR _secs "${_t1} - ${_t0}")
string(REGEX MATCHALL "[^\n]+" _out_lines "${_out}${_err}")
list(LENGTH _out_lines _nl)
if(_nl GREATER 6)
    math(EXPR _from "${_nl} - 6")
    list(SUBLIST _out_lines ${_from} 6 _out_lines)
endif()
string(REPLACE ";" "\n" _tail "${_out_lines}")
message("${_tail}")

if(FAULT)
    if(NOT _rc EQUAL 0 AND _out MATCHES "MISMATCH beat=${_beat} [^\n]*\n  the first beat after reset ${_reset}\n")
        file(REMOVE ${PREFIX}.in.hex ${PREFIX}.out.hex ${PREFIX}.edges.hex ${PREFIX}.resets.hex)
        message(FATAL_ERROR "bench reported the injected mismatch at beat ${_beat}, the first "
                            "after reset ${_reset} (expected)")
    endif()
    soak_fail("bench exit ${_rc}")
endif()

if(NOT _rc EQUAL 0 OR NOT _out MATCHES "PASS ([0-9]+) beats, ([0-9]+) edge beats, ([0-9]+) resets, ([0-9]+) errors, ([0-9]+) cut")
    message("soak seed=${SEED} pixels=${_pixels} frames=${_frames} resets=${_resets} faults=${_faults} "
            "errors=${_errors} out_beats=${_out_beats} mismatches=FAIL seconds=${_secs}")
    message(FATAL_ERROR "soak failed (bench exit ${_rc}); vector files kept: ${PREFIX}.*.hex")
endif()
set(_checked ${CMAKE_MATCH_1})
set(_echecked ${CMAKE_MATCH_2})
set(_cut ${CMAKE_MATCH_5})
math(EXPR _sum "${_checked} + ${_echecked} + ${_cut}")
math(EXPR _expect "${_out_beats} + ${_edge_beats}")
if(NOT _sum EQUAL _expect OR NOT CMAKE_MATCH_3 EQUAL _resets OR NOT CMAKE_MATCH_4 EQUAL _errors)
    message(FATAL_ERROR "bench counts disagree with the stream: ${_checked} gradient + ${_echecked} "
                        "edge beats checked + ${_cut} cut != ${_expect}, or resets/errors differ")
endif()
message("soak seed=${SEED} pixels=${_pixels} frames=${_frames} resets=${_resets} faults=${_faults} "
        "errors=${_errors} out_beats=${_out_beats} edge_beats=${_edge_beats} checked=${_checked} "
        "edge_checked=${_echecked} cut=${_cut} mismatches=0 "
        "seconds=${_secs}")
file(REMOVE ${PREFIX}.in.hex ${PREFIX}.out.hex ${PREFIX}.edges.hex ${PREFIX}.resets.hex)
