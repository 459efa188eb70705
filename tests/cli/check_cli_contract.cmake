# The command line's promises, run on the binary (through EMULATOR when cross-compiled): every
# failed write ends the run non-zero with one line on stderr; headers and frames are read within
# bounds; the exit codes (0 done, 1 bad input or I/O, 2 bad command line); --version; a numbered
# sequence that stops at a gap says so. -DQUADTRACK=... -DEMULATOR=... -DDIR=... (scratch)
# -DADDRESS_LIMIT=ON|OFF (whether an address-space limit can be put on the binary).
file(REMOVE_RECURSE ${DIR})
file(MAKE_DIRECTORY ${DIR})
set(q ${EMULATOR} ${QUADTRACK})

# Runs the quadtrack arguments ARGN (stdout to OUT_FILE when given) and checks the exit code and
# that stderr matches ERR_REGEX.
function(expect what code err_regex)
    cmake_parse_arguments(E "" "OUT_FILE" "ARGS" ${ARGN})
    if(E_OUT_FILE)
        execute_process(COMMAND ${q} ${E_ARGS} RESULT_VARIABLE rc OUTPUT_FILE ${E_OUT_FILE}
            ERROR_VARIABLE err)
    else()
        execute_process(COMMAND ${q} ${E_ARGS} RESULT_VARIABLE rc OUTPUT_VARIABLE out
            ERROR_VARIABLE err)
    endif()
    if(NOT rc EQUAL code OR NOT err MATCHES "${err_regex}")
        message(FATAL_ERROR "${what}: exit ${rc} (want ${code}), stderr '${err}' (want '${err_regex}')")
    endif()
    message("ok: ${what}")
endfunction()

# A 64 x 48 grey frame (every sample 'A', 65).
string(REPEAT "A" 3072 samples)
file(WRITE ${DIR}/frame.pgm "P5\n64 48\n255\n${samples}")

# Writes that fail: a full device and a closed standard output.
expect("--help to /dev/full" 1 "^quadtrack: cannot write the results: " OUT_FILE /dev/full ARGS --help)
expect("detect --help to /dev/full" 1 "^quadtrack detect: cannot write" OUT_FILE /dev/full
    ARGS detect --help)
expect("detect to /dev/full" 1 "^quadtrack detect: cannot write the results: " OUT_FILE /dev/full
    ARGS detect ${DIR}/frame.pgm)
expect("track to /dev/full" 1 "^quadtrack track: cannot write the results: " OUT_FILE /dev/full
    ARGS track ${DIR}/frame.pgm)
execute_process(COMMAND sh -c "\"$0\" \"$@\" >&-" ${q} detect ${DIR}/frame.pgm
    RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 1 OR NOT err MATCHES "cannot write the results")
    message(FATAL_ERROR "detect with stdout closed: exit ${rc}, stderr '${err}'")
endif()

# Exit codes and flags.
expect("--version" 0 "^$" ARGS --version)
execute_process(COMMAND ${q} --version OUTPUT_VARIABLE version)
if(NOT version MATCHES "^quadtrack [0-9]+[.][0-9]+[.][0-9]+\n$")
    message(FATAL_ERROR "--version printed '${version}'")
endif()
expect("demo --help" 0 "^$" ARGS demo --help)
expect("an unknown -x" 2 "unknown option '-x'" ARGS detect -x ${DIR}/frame.pgm)
expect("a file named after --" 1 "^quadtrack detect: --help: cannot open" ARGS detect -- --help)
expect("a bad frame pattern" 2 "bad frame pattern" ARGS track ${DIR}/f%q.pgm)
expect("an ROI outside frame 0" 2 "not wholly inside" ARGS target ${DIR}/frame.pgm --roi -5,-5,20,20)
expect("an ROI too wide" 2 "" ARGS target ${DIR}/frame.pgm --roi 10,10,385,100)
expect("a non-ASCII byte in a message" 2 "unknown option '--caf\\\\xc3\\\\xa9'" ARGS detect --café)

# A numbered sequence with file 2 missing: two frames, exit 0, a warning naming the gap.
foreach(k 0 1 3)
    file(COPY_FILE ${DIR}/frame.pgm ${DIR}/f${k}.pgm)
endforeach()
expect("a sequence with a gap" 0 "warning: .*f2[.]pgm is missing but .*f3[.]pgm exists" ARGS
    track ${DIR}/f%d.pgm)

# Bounded reads: a header that never ends, and a 16384 x 16384 frame of 3 bytes, which must be
# refused as truncated without reserving its 256 MiB (under a 200 MB address-space limit, where
# ADDRESS_LIMIT says one can be set).
execute_process(COMMAND sh -c "(printf 'P5\\n#'; cat /dev/zero) | timeout 60 \"$0\" \"$@\" detect -"
    ${q} RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 1 OR NOT err MATCHES "PGM header longer than 65536 bytes")
    message(FATAL_ERROR "an endless PGM comment: exit ${rc}, stderr '${err}'")
endif()
file(WRITE ${DIR}/huge.pgm "P5\n16384 16384\n255\nabc")
file(WRITE ${DIR}/huge.y4m "YUV4MPEG2 W16384 H16384 Cmono\nFRAME\nabc")
if(ADDRESS_LIMIT)
    foreach(file huge.pgm huge.y4m)
        execute_process(COMMAND sh -c "ulimit -v 200000 && \"$0\" detect \"$1\"" ${QUADTRACK}
            ${DIR}/${file} RESULT_VARIABLE rc ERROR_VARIABLE err)
        if(NOT rc EQUAL 1 OR NOT err MATCHES "truncated (pixel|frame) data")
            message(FATAL_ERROR "${file} under 200 MB: exit ${rc}, stderr '${err}'")
        endif()
    endforeach()
endif()

# --draw: a PNG from detect; track draws frames 0, N, 2N, ... by its pattern, refuses a pattern
# without a number (2) and reports a picture it cannot write (1).
file(REMOVE ${DIR}/drawn.png)
expect("detect --draw" 0 "^$" ARGS detect ${DIR}/frame.pgm --draw ${DIR}/drawn.png)
file(READ ${DIR}/drawn.png magic LIMIT 8 HEX)
if(NOT magic STREQUAL "89504e470d0a1a0a")
    message(FATAL_ERROR "detect --draw wrote no PNG (${magic})")
endif()
expect("track --draw --draw-every 2" 0 "" ARGS track ${DIR}/f%d.pgm --draw ${DIR}/drawn_%02d.png
    --draw-every 2)
if(NOT EXISTS ${DIR}/drawn_00.png OR EXISTS ${DIR}/drawn_01.png)
    message(FATAL_ERROR "track --draw-every 2 did not draw frame 0 alone of frames 0-1")
endif()
expect("track --draw without a number" 2 "needs one %d" ARGS track ${DIR}/frame.pgm --draw x.png)
expect("detect --draw into no directory" 1 "^quadtrack detect: --draw: " ARGS
    detect ${DIR}/frame.pgm --draw ${DIR}/no/such/dir/x.png)

# track --lines no: each frame's line without the detected lines (with them by default).
execute_process(COMMAND ${q} track ${DIR}/f%d.pgm --lines no OUTPUT_VARIABLE out RESULT_VARIABLE rc
    ERROR_QUIET)
execute_process(COMMAND ${q} track ${DIR}/f%d.pgm OUTPUT_VARIABLE with RESULT_VARIABLE rc_with
    ERROR_QUIET)
if(NOT rc EQUAL 0 OR out MATCHES "\"lines\":" OR NOT out MATCHES "\"frame\":1," OR
   NOT with MATCHES "\"lines\":")
    message(FATAL_ERROR "track --lines no: exit ${rc}, '${out}'; by default: '${with}'")
endif()

# target --draw: a PNG per frame by its pattern; a pattern without a number is a command-line error.
file(REMOVE ${DIR}/target_00.png)
expect("target --draw" 0 "" ARGS target ${DIR}/f%d.pgm --roi 20,15,16,12 --draw ${DIR}/target_%02d.png)
if(NOT EXISTS ${DIR}/target_00.png OR NOT EXISTS ${DIR}/target_01.png)
    message(FATAL_ERROR "target --draw did not draw frames 0 and 1")
endif()
expect("target --draw without a number" 2 "needs one %d" ARGS target ${DIR}/f%d.pgm
    --roi 20,15,16,12 --draw x.png)
