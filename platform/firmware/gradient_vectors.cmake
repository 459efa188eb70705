# Reads vectors/gradient/manifest.txt (format: docs/gradient.md) at configure time.
#
# qt_gradient_vector_cases(<dir> <max_width> <out_names> <out_sizes> <out_hashes>)
# returns, in manifest order, the cases the firmware can check: streams with no framing
# errors (so torn_stream is left out) whose max_width equals the stage capacity. Sets
# <out_names> to "" when there is no manifest. Re-runs CMake when the manifest changes.
function(qt_gradient_vector_cases dir max_width out_names out_sizes out_hashes)
    set(names "")
    set(sizes "")
    set(hashes "")
    set(manifest "${dir}/manifest.txt")
    if(EXISTS "${manifest}")
        set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${manifest}")
        file(STRINGS "${manifest}" lines)
        # name sizes frames seed in_beats out_beats errors max_width fnv1a64
        set(field_re "^([A-Za-z][A-Za-z0-9_]*) ([0-9x+]+) ([0-9]+) ([0-9]+) ([0-9]+) ([0-9]+) ([0-9]+) ([0-9]+) ([0-9a-f]+)$")
        foreach(line IN LISTS lines)
            if(line STREQUAL "" OR line MATCHES "^#")
                continue()
            endif()
            if(NOT line MATCHES "${field_re}")
                message(FATAL_ERROR "${manifest}: malformed line '${line}'")
            endif()
            if(CMAKE_MATCH_7 EQUAL 0 AND CMAKE_MATCH_8 EQUAL max_width)
                list(APPEND names "${CMAKE_MATCH_1}")
                list(APPEND sizes "${CMAKE_MATCH_2}")
                list(APPEND hashes "${CMAKE_MATCH_9}")
            endif()
        endforeach()
    endif()
    set(${out_names} "${names}" PARENT_SCOPE)
    set(${out_sizes} "${sizes}" PARENT_SCOPE)
    set(${out_hashes} "${hashes}" PARENT_SCOPE)
endfunction()
