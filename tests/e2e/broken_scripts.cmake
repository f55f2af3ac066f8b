# Runs hlrscript on one script of the broken-script corpus (tests/e2e/broken/*.hls) and checks that it
# fails the way the script's header says, and that it writes nothing.
#
#   cmake -DHLRSCRIPT=path/to/hlrscript -DSCRIPT=tests/e2e/broken/NAME.hls -DWORK=scratch-dir
#         -P tests/e2e/broken_scripts.cmake
#
# Each broken script starts with its expectations, one per comment line:
#   # expect-exit: 65                  the exit status
#   # expect-location: 7:12            line:col of the error; stderr must contain "NAME.hls:7:12:" and a
#                                      caret line; `none` for errors no script position fits (bad options)
#   # expect-message: unknown vertex   text stderr must contain
#   # expect-file: support/x.hls       optional: the file the location is in (default: the script)
#   # args: --camera nope              optional: more command-line arguments, after the script
#
# The script and its helpers (tests/e2e/broken/support/) are copied into a fresh directory under WORK,
# hlrscript runs there on the copy, and afterwards the directory must hold exactly the files copied:
# no PDF, no JSON, no temporary file left behind.

foreach(var HLRSCRIPT SCRIPT WORK)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "broken_scripts.cmake: pass -D${var}=...")
  endif()
endforeach()

get_filename_component(name "${SCRIPT}" NAME)
get_filename_component(stem "${SCRIPT}" NAME_WE)
get_filename_component(corpus "${SCRIPT}" DIRECTORY)

# ---- the expectations ----
# Read as one string and matched key by key (file(STRINGS) would split a message at each ';').
file(READ "${SCRIPT}" text)
string(PREPEND text "\n")
function(header_value key out)
  if(text MATCHES "\n# ${key}: *([^\n]*[^ \n]) *\n")
    set(${out} "${CMAKE_MATCH_1}" PARENT_SCOPE)
  else()
    set(${out} "" PARENT_SCOPE)
  endif()
endfunction()
header_value(expect-exit expect_exit)
header_value(expect-location expect_location)
header_value(expect-message expect_message)
header_value(expect-file expect_file)
header_value(args args_text)
if(expect_file STREQUAL "")
  set(expect_file "${name}")
endif()
separate_arguments(args UNIX_COMMAND "${args_text}")
if(NOT expect_exit MATCHES "^[0-9]+$" OR NOT expect_location MATCHES "^(none|[0-9]+:[0-9]+)$"
   OR expect_message STREQUAL "")
  message(FATAL_ERROR "${name}: the header needs '# expect-exit:', '# expect-location:' (line:col or none) "
                      "and '# expect-message:' lines")
endif()

# ---- a fresh directory holding the script and its helpers ----
set(dir "${WORK}/${stem}")
file(REMOVE_RECURSE "${dir}")
file(MAKE_DIRECTORY "${dir}")
file(COPY "${SCRIPT}" DESTINATION "${dir}")
if(IS_DIRECTORY "${corpus}/support")
  file(COPY "${corpus}/support" DESTINATION "${dir}")
endif()
file(GLOB_RECURSE before RELATIVE "${dir}" LIST_DIRECTORIES false "${dir}/*")

execute_process(COMMAND "${HLRSCRIPT}" "${name}" ${args}
                WORKING_DIRECTORY "${dir}"
                RESULT_VARIABLE rc
                OUTPUT_VARIABLE out
                ERROR_VARIABLE err
                TIMEOUT 120)

# The text of the first line of `text` that contains `needle`, from just after it to the end of the line;
# "<none>" when no line does.
function(rest_of_line text needle out)
  string(FIND "${text}" "${needle}" at)
  if(at EQUAL -1)
    set(${out} "<none>" PARENT_SCOPE)
    return()
  endif()
  string(LENGTH "${needle}" length)
  math(EXPR at "${at} + ${length}")
  string(SUBSTRING "${text}" ${at} -1 rest)
  string(FIND "${rest}" "\n" end)
  string(SUBSTRING "${rest}" 0 ${end} rest)
  set(${out} "${rest}" PARENT_SCOPE)
endfunction()

set(problems "")
if(NOT rc STREQUAL expect_exit)
  string(APPEND problems "  exit status: expected ${expect_exit}, got ${rc}\n")
endif()
# The message must be in the error line itself (the source line printed below it does not count), and
# that line must start with the place: "FILE:LINE:COL: error: ...".
if(expect_location STREQUAL "none")
  rest_of_line("${err}" "error: " message_line)
else()
  rest_of_line("${err}" "${expect_file}:${expect_location}: error: " message_line)
  if(message_line STREQUAL "<none>")
    string(APPEND problems "  stderr has no error at '${expect_file}:${expect_location}:'\n")
  endif()
  # The printer's caret line: "     |      ^" (a '~' underline may follow the caret).
  if(NOT err MATCHES "\n *[|][^\n]*\\^")
    string(APPEND problems "  stderr shows no caret line under the source line\n")
  endif()
endif()
string(FIND "${message_line}" "${expect_message}" at)
if(at EQUAL -1)
  string(APPEND problems "  the error does not say '${expect_message}'\n")
endif()

file(GLOB_RECURSE after RELATIVE "${dir}" LIST_DIRECTORIES false "${dir}/*")
list(REMOVE_ITEM after ${before})
if(after)
  list(JOIN after ", " written)
  string(APPEND problems "  files were written although the script is wrong: ${written}\n")
endif()

if(problems)
  message(FATAL_ERROR "${name} (hlrscript ${name} ${args}):\n${problems}--- stderr ---\n${err}--- stdout ---\n${out}")
endif()
file(REMOVE_RECURSE "${dir}")
