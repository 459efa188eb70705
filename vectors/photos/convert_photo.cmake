# cmake -DTOOL=<jpegtopnm|pngtopnm> -DIN=<photo> -DOUT=<file.pnm> -P convert_photo.cmake
# Runs the netpbm converter with its output in OUT (a PGM or PPM: image_io reads both).
get_filename_component(dir ${OUT} DIRECTORY)
file(MAKE_DIRECTORY ${dir})
execute_process(COMMAND ${TOOL} ${IN} OUTPUT_FILE ${OUT}.part RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
    file(REMOVE ${OUT}.part)
    message(FATAL_ERROR "${TOOL} ${IN} failed (${rc}): ${err}")
endif()
file(RENAME ${OUT}.part ${OUT})
