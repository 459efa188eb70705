# The ctests package_consumer and package_consumer_cortex-m4/-m3 (registered by package_test.cmake):
# installs the core component of BUILD_DIR into a fresh prefix, checks what was installed,
# configures and builds this directory's consumer against it with CMAKE_PREFIX_PATH only, and
# when RUN is true runs the consumer (through EMULATOR when cross-compiled), which must exit 0.
#
#   cmake -DBUILD_DIR=... -DWORK_DIR=... -DCORE_DIR=... [-DCONFIG=Release] [-DGENERATOR=...]
#         [-DTOOLCHAIN_FILE=...] [-DCXX_COMPILER=...] [-DCXX_FLAGS=...] [-DLINKER_FLAGS=...]
#         [-DRUN=ON] [-DEMULATOR=...] -P run_consumer_test.cmake
cmake_minimum_required(VERSION 3.22)

foreach(var BUILD_DIR WORK_DIR CORE_DIR)
    if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
        message(FATAL_ERROR "${var} is not set")
    endif()
endforeach()
set(consumer_src ${CMAKE_CURRENT_LIST_DIR})
set(prefix ${WORK_DIR}/prefix)
set(consumer_build ${WORK_DIR}/build)

# Runs a command; stops the test with its output when it fails.
function(run_step what)
    execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(NOT rc EQUAL 0)
        message(FATAL_ERROR "FAIL: ${what} (exit ${rc})\n${out}\n${err}")
    endif()
    message("${what}: ok")
endfunction()

# A fresh start on every run: nothing left from an earlier install or consumer build.
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

# (a) Install only the core library's component (a firmware target need not have built).
set(config_args "")
if(NOT "${CONFIG}" STREQUAL "")
    set(config_args --config ${CONFIG})
endif()
run_step("install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix}
    --component quadtrack_core ${config_args})

# Every public header of core/ was installed (the consumer below includes only some).
file(GLOB core_headers RELATIVE ${CORE_DIR} ${CORE_DIR}/*.h)
set(missing "")
foreach(header IN LISTS core_headers)
    if(NOT EXISTS ${prefix}/include/quadtrack/${header})
        list(APPEND missing ${header})
    endif()
endforeach()
if(missing)
    message(FATAL_ERROR "FAIL: headers of core/ not installed: ${missing}")
endif()
# The package describes the installed tree only: no path into the source or build tree, and
# none of the library's private compile options.
file(GLOB package_files ${prefix}/lib*/cmake/quadtrack/*.cmake ${prefix}/lib/*/cmake/quadtrack/*.cmake)
if(NOT package_files)
    message(FATAL_ERROR "FAIL: no package files under ${prefix}/lib*/cmake/quadtrack")
endif()
foreach(file IN LISTS package_files)
    file(READ ${file} text)
    foreach(leak ${CORE_DIR} ${BUILD_DIR}/core -Werror -fno-exceptions)
        string(FIND "${text}" "${leak}" at)
        if(NOT at EQUAL -1)
            message(FATAL_ERROR "FAIL: ${file} mentions '${leak}'")
        endif()
    endforeach()
endforeach()

# (b) Configure and build the consumer as an outside project: it finds the package through
# CMAKE_PREFIX_PATH alone, with the build's own toolchain (file) and flags.
set(configure_args -S ${consumer_src} -B ${consumer_build} -DCMAKE_PREFIX_PATH=${prefix}
    -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF "-DCMAKE_BUILD_TYPE=${CONFIG}")
if(NOT "${GENERATOR}" STREQUAL "")
    list(APPEND configure_args -G ${GENERATOR})
endif()
if(NOT "${TOOLCHAIN_FILE}" STREQUAL "")
    list(APPEND configure_args -DCMAKE_TOOLCHAIN_FILE=${TOOLCHAIN_FILE})
elseif(NOT "${CXX_COMPILER}" STREQUAL "")
    list(APPEND configure_args -DCMAKE_CXX_COMPILER=${CXX_COMPILER})
endif()
# The library's instrumentation (the host-sanitize preset's -fsanitize) must reach the link.
if(NOT "${CXX_FLAGS}" STREQUAL "")
    list(APPEND configure_args "-DCMAKE_CXX_FLAGS=${CXX_FLAGS}")
endif()
if(NOT "${LINKER_FLAGS}" STREQUAL "")
    list(APPEND configure_args "-DCMAKE_EXE_LINKER_FLAGS=${LINKER_FLAGS}")
endif()
run_step("configure consumer" ${CMAKE_COMMAND} ${configure_args})

# The package found is the one just installed, not another quadtrack on the machine.
file(STRINGS ${consumer_build}/CMakeCache.txt found_dir REGEX "^quadtrack_DIR:")
string(REGEX REPLACE "^[^=]*=" "" found_dir "${found_dir}")
file(REAL_PATH "${found_dir}" found_dir)
file(REAL_PATH "${prefix}" real_prefix)
string(FIND "${found_dir}" "${real_prefix}/" at)
if(NOT at EQUAL 0)
    message(FATAL_ERROR "FAIL: the consumer found quadtrack in '${found_dir}', not under ${prefix}")
endif()

run_step("build consumer" ${CMAKE_COMMAND} --build ${consumer_build} ${config_args})

# (c) Run it: exit 0 means exactly one quadrangle in the generated frame.
if(RUN)
    set(exe ${consumer_build}/quadtrack_consumer)
    if(NOT EXISTS ${exe} AND NOT "${CONFIG}" STREQUAL "")
        set(exe ${consumer_build}/${CONFIG}/quadtrack_consumer)
    endif()
    execute_process(COMMAND ${EMULATOR} ${exe} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
    message("${out}${err}")
    if(NOT rc EQUAL 0)
        message(FATAL_ERROR "FAIL: quadtrack_consumer exited with ${rc} (0: one quadrangle, "
                            "1: another count, 2: a stage error)")
    endif()
else()
    message("run: skipped (bare-metal image, built only)")
endif()
