# Registers the ctest that installs quadtrack_core and builds this directory's consumer
# against the installed package (run_consumer_test.cmake), with this build's toolchain:
#   package_consumer     host presets: built and run;
#                        aarch64-linux: built with its toolchain file, run under its
#                        CMAKE_CROSSCOMPILING_EMULATOR (qemu-aarch64);
#   package_consumer_cortex-m4 (or -m3), bare metal (CMAKE_SYSTEM_NAME Generic): built and linked with
#                        newlib-nano, not run (no board start-up code in a generic consumer).
# Included by tests/CMakeLists.txt and by the Generic branch of the top-level CMakeLists.txt.
if(CMAKE_SYSTEM_NAME STREQUAL "Generic")
    set(qt_pkg_test package_consumer_${CMAKE_SYSTEM_PROCESSOR})
    set(qt_pkg_run OFF)
else()
    set(qt_pkg_test package_consumer)
    set(qt_pkg_run ON)
endif()
if(CMAKE_CROSSCOMPILING AND qt_pkg_run AND NOT CMAKE_CROSSCOMPILING_EMULATOR)
    message(STATUS "${qt_pkg_test}: cross build without CMAKE_CROSSCOMPILING_EMULATOR, consumer built only")
    set(qt_pkg_run OFF)
endif()

# Host builds pass their compiler and flags (host-sanitize's -fsanitize must reach the
# consumer's link); cross builds pass only their toolchain file, as a firmware project would.
set(qt_pkg_host_args "")
if(NOT CMAKE_TOOLCHAIN_FILE)
    set(qt_pkg_host_args -DCXX_COMPILER=${CMAKE_CXX_COMPILER} "-DCXX_FLAGS=${CMAKE_CXX_FLAGS}"
        "-DLINKER_FLAGS=${CMAKE_EXE_LINKER_FLAGS}")
endif()
add_test(NAME ${qt_pkg_test} COMMAND ${CMAKE_COMMAND}
    -DBUILD_DIR=${CMAKE_BINARY_DIR}
    -DWORK_DIR=${CMAKE_BINARY_DIR}/${qt_pkg_test}
    -DCORE_DIR=${PROJECT_SOURCE_DIR}/core
    -DCONFIG=$<CONFIG>
    "-DGENERATOR=${CMAKE_GENERATOR}"
    "-DTOOLCHAIN_FILE=${CMAKE_TOOLCHAIN_FILE}"
    ${qt_pkg_host_args}
    -DRUN=${qt_pkg_run}
    "-DEMULATOR=${CMAKE_CROSSCOMPILING_EMULATOR}"
    -P ${CMAKE_CURRENT_LIST_DIR}/run_consumer_test.cmake)
# seconds: two configure+build runs of a one-file project and an emulated run
set_tests_properties(${qt_pkg_test} PROPERTIES TIMEOUT 300)
