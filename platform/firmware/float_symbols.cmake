# The float-free check: lists the floating-point helper routines of libgcc linked into an
# image, by their names in its symbol table (arm-none-eabi-nm):
#   __aeabi_f* __aeabi_d*             EABI single/double arithmetic, comparisons, conversions
#   __aeabi_cf* __aeabi_cd*           EABI flag-setting comparisons
#   __aeabi_[u]{i,l}2{f,d}            integer to float conversions
#   __<op>{s,d}f<n>, __float*{s,d}f, __fix*{s,d}f*, __extendsfdf2, __truncdfsf2 ...
#                                     the same routines under their GCC names (__addsf3,
#                                     __floatsidf, __fixdfsi, __eqsf2, ...)
# EXPECT=none: fails if any is linked (the chain). EXPECT=some: fails if none is (the canary,
# which proves the check can see them). KIND=double narrows the list to the double-precision
# helpers (the target tracker may use float, never double). ELF may also be a static library
# or an object: its undefined references count too.
#   cmake -DNM=arm-none-eabi-nm -DELF=image.elf|lib.a -DEXPECT=none|some [-DKIND=double] -P float_symbols.cmake
if(NOT NM)
    message(FATAL_ERROR "FAIL: arm-none-eabi-nm not found")
endif()
execute_process(COMMAND ${NM} ${ELF} RESULT_VARIABLE status OUTPUT_VARIABLE symbols)
if(NOT status STREQUAL "0")
    message(FATAL_ERROR "FAIL: ${NM} ${ELF} exit status ${status}")
endif()
set(found "")
string(REPLACE "\n" ";" lines "${symbols}")
foreach(line IN LISTS lines)
    if(line MATCHES " ([A-Za-z_0-9]+)$")
        set(symbol ${CMAKE_MATCH_1})
        if(KIND STREQUAL "double")
            if(symbol MATCHES "^__aeabi_(c?d|u?[il]2d|f2d)" OR symbol MATCHES "^__[a-z]*df[0-9]?$"
               OR symbol MATCHES "^__[a-z]*df[sdt]?[if][0-9]?$" OR symbol MATCHES "^__(extendsfdf2|truncdfsf2)$")
                list(APPEND found ${symbol})
            endif()
        elseif(symbol MATCHES "^__aeabi_(c?[fd]|u?[il]2[fd])" OR symbol MATCHES "^__[a-z]*[sd]f[0-9]?$"
               OR symbol MATCHES "^__[a-z]*[sd]f[sdt]?[if][0-9]?$")
            list(APPEND found ${symbol})
        endif()
    endif()
endforeach()
list(LENGTH found count)
if(EXPECT STREQUAL "none" AND count GREATER 0)
    message(FATAL_ERROR "FAIL: ${ELF} links ${count} floating-point helper(s): ${found}")
elseif(EXPECT STREQUAL "some" AND count EQUAL 0)
    message(FATAL_ERROR "FAIL: no floating-point helper found in ${ELF}, which uses float: the check is blind")
endif()
list(REMOVE_DUPLICATES found)
message(STATUS "${ELF}: ${count} floating-point helper reference(s) ${found}")
