# Checks one example scene (examples/**/*.hls) on every device, each file read by a real reader:
# `hlrscript check` accepts it; the PDF has one page per frame (poppler's pdfinfo); one SVG per frame that
# librsvg's rsvg-convert converts; one PNG per frame whose header has the size the paper and dpi give;
# one HPGL file per frame that hp2xx renders; and the JSON has one entry per frame whose pen plan reaches
# the lift lower bound with one lift per stroke, hidden ones included (CMake's own JSON parser reads it).
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

# ---- SVG, PNG, HPGL: one file per frame ----
execute_process(COMMAND "${HLRSCRIPT}" "${SCRIPT}" -o "${dir}/${stem}-{frame:03}.svg"
                WORKING_DIRECTORY "${dir}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 600)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "hlrscript ${SCRIPT} -o ...svg failed (${rc}):\n${err}${out}")
endif()
file(GLOB svgs "${dir}/*.svg")
list(LENGTH svgs n)
if(NOT n EQUAL PAGES)
  message(FATAL_ERROR "${SCRIPT}: expected ${PAGES} SVG file(s), got ${n}")
endif()
foreach(svg IN LISTS svgs)
  execute_process(COMMAND rsvg-convert -o "${svg}.png" "${svg}" RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "rsvg-convert cannot read ${svg}:\n${err}")
  endif()
endforeach()

# A4 landscape (every example's paper but the A3 sheets') at 40 dpi: 297 mm and 210 mm → 468 × 331 pixels
# (rounded); A3 landscape, 420 mm and 297 mm → 661 × 468.
file(READ "${SCRIPT}" script_text)
if(script_text MATCHES "\npaper A3 landscape")
  set(png_w 661)
  set(png_h 468)
  set(png_paper "A3 landscape")
else()
  set(png_w 468)
  set(png_h 331)
  set(png_paper "A4 landscape")
endif()
execute_process(COMMAND "${HLRSCRIPT}" "${SCRIPT}" -o "${dir}/${stem}-{frame:03}.png" --dpi 40
                WORKING_DIRECTORY "${dir}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 600)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "hlrscript ${SCRIPT} -o ...png failed (${rc}):\n${err}${out}")
endif()
file(GLOB pngs "${dir}/${stem}-???.png")
list(LENGTH pngs n)
if(NOT n EQUAL PAGES)
  message(FATAL_ERROR "${SCRIPT}: expected ${PAGES} PNG file(s), got ${n}")
endif()
foreach(png IN LISTS pngs)
  file(READ "${png}" head LIMIT 24 HEX)
  # Signature 89 50 4E 47 0D 0A 1A 0A, then the IHDR chunk: length, "IHDR", width, height (big-endian).
  if(NOT head MATCHES "^89504e470d0a1a0a0000000d49484452(........)(........)$")
    message(FATAL_ERROR "${png} is not a PNG (header ${head})")
  endif()
  math(EXPR w "0x${CMAKE_MATCH_1}")
  math(EXPR h "0x${CMAKE_MATCH_2}")
  if(NOT w EQUAL png_w OR NOT h EQUAL png_h)
    message(FATAL_ERROR "${png}: expected ${png_w} x ${png_h} pixels (${png_paper} at 40 dpi), got ${w} x ${h}")
  endif()
endforeach()

execute_process(COMMAND "${HLRSCRIPT}" "${SCRIPT}" -o "${dir}/${stem}-{frame:03}.hpgl" --plotter hp7475a
                WORKING_DIRECTORY "${dir}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 600)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "hlrscript ${SCRIPT} -o ...hpgl --plotter hp7475a failed (${rc}):\n${err}${out}")
endif()
file(GLOB plots "${dir}/*.hpgl")
list(LENGTH plots n)
if(NOT n EQUAL PAGES)
  message(FATAL_ERROR "${SCRIPT}: expected ${PAGES} HPGL file(s), got ${n}")
endif()
foreach(plot IN LISTS plots)
  # By name in its directory: hp2xx overflows a fixed buffer on long paths (a deep build directory).
  get_filename_component(plot_name "${plot}" NAME)
  execute_process(COMMAND hp2xx -q -m png -f "${plot_name}.png" "${plot_name}" WORKING_DIRECTORY "${dir}"
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 OR NOT EXISTS "${plot}.png")
    message(FATAL_ERROR "hp2xx cannot render ${plot} (${rc}):\n${err}${out}")
  endif()
endforeach()

# ---- JSON: one entry per frame; every frame's strokes (visible + hidden) are its lifts, at the lower bound ----
set(json "${dir}/${stem}.json")
execute_process(COMMAND "${HLRSCRIPT}" "${SCRIPT}" -o "${json}"
                WORKING_DIRECTORY "${dir}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 600)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "hlrscript ${SCRIPT} -o ${json} failed (${rc}):\n${err}${out}")
endif()
file(READ "${json}" text)
string(JSON format GET "${text}" format)
string(JSON frames LENGTH "${text}" frames)
if(NOT format STREQUAL "hlrscript.lines/1" OR NOT frames EQUAL PAGES)
  message(FATAL_ERROR "${json}: expected format hlrscript.lines/1 and ${PAGES} frame(s), got ${format}, ${frames}")
endif()
math(EXPR last "${frames} - 1")
foreach(i RANGE ${last})
  string(JSON lifts GET "${text}" frames ${i} stats lifts)
  string(JSON bound GET "${text}" frames ${i} stats lift_lower_bound)
  string(JSON strokes LENGTH "${text}" frames ${i} strokes)
  # Lifts count every planned stroke: the hidden layer's and the hatching's too, when the script draws them.
  string(JSON hidden ERROR_VARIABLE no_hidden LENGTH "${text}" frames ${i} hidden_strokes)
  if(no_hidden)
    set(hidden 0)
  endif()
  string(JSON hatch ERROR_VARIABLE no_hatch LENGTH "${text}" frames ${i} hatch_strokes)
  if(no_hatch)
    set(hatch 0)
  endif()
  math(EXPR drawn "${strokes} + ${hidden} + ${hatch}")
  if(NOT lifts EQUAL bound OR NOT drawn EQUAL lifts)
    message(FATAL_ERROR
            "${json} frame ${i}: ${strokes} strokes + ${hidden} hidden + ${hatch} hatch, ${lifts} lifts, lower bound ${bound}")
  endif()
endforeach()
file(REMOVE_RECURSE "${dir}")
