# Checks one example scene (examples/**/*.hls): `hlrscript check` accepts it, and rendering it to a PDF
# gives a file that poppler's pdfinfo reads, with the expected number of pages (one per frame).
#
#   cmake -DHLRSCRIPT=path/to/hlrscript -DSCRIPT=examples/desens/landing.hls -DPAGES=33 -DWORK=scratch-dir
#         -P tests/e2e/render_example.cmake
#
# hlrscript runs in a fresh directory under WORK, so an `output` in the script cannot land in the
# source tree; `-o` names the PDF there.

foreach(var HLRSCRIPT SCRIPT PAGES WORK)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "render_example.cmake: pass -D${var}=...")
  endif()
endforeach()

get_filename_component(stem "${SCRIPT}" NAME_WE)
get_filename_component(parent "${SCRIPT}" DIRECTORY)
get_filename_component(group "${parent}" NAME)
set(dir "${WORK}/${group}-${stem}")
file(REMOVE_RECURSE "${dir}")
file(MAKE_DIRECTORY "${dir}")

execute_process(COMMAND "${HLRSCRIPT}" check "${SCRIPT}"
                WORKING_DIRECTORY "${dir}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 120)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "hlrscript check ${SCRIPT} failed (${rc}):\n${err}${out}")
endif()

set(pdf "${dir}/${stem}.pdf")
execute_process(COMMAND "${HLRSCRIPT}" "${SCRIPT}" -o "${pdf}"
                WORKING_DIRECTORY "${dir}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 600)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "hlrscript ${SCRIPT} -o ${pdf} failed (${rc}):\n${err}${out}")
endif()
if(NOT EXISTS "${pdf}")
  message(FATAL_ERROR "hlrscript ${SCRIPT} exited 0 but wrote no ${pdf}")
endif()

execute_process(COMMAND pdfinfo "${pdf}" RESULT_VARIABLE rc OUTPUT_VARIABLE info ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "pdfinfo cannot read ${pdf}:\n${err}")
endif()
if(NOT info MATCHES "Pages: +([0-9]+)\n")
  message(FATAL_ERROR "pdfinfo reports no page count for ${pdf}:\n${info}")
endif()
if(NOT CMAKE_MATCH_1 EQUAL PAGES)
  message(FATAL_ERROR "${SCRIPT}: expected ${PAGES} page(s), the PDF has ${CMAKE_MATCH_1}:\n${info}")
endif()
file(REMOVE_RECURSE "${dir}")
