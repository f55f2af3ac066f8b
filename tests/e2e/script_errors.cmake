# Runs the built hlrscript on broken input and checks exit statuses (65 script, 66 unreadable, 64 usage,
# 73 unwritable output), that errors name file:line:col (also inside an included file), and that
# nothing is written.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})

function(expect_failure code pattern)
  execute_process(COMMAND ${HLRSCRIPT} ${ARGN} WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc OUTPUT_VARIABLE out
                  ERROR_VARIABLE err)
  if(NOT rc EQUAL ${code})
    message(FATAL_ERROR "hlrscript ${ARGN}: expected exit ${code}, got ${rc}:\n${out}${err}")
  endif()
  if(NOT err MATCHES "${pattern}")
    message(FATAL_ERROR "hlrscript ${ARGN}: stderr does not match '${pattern}':\n${err}")
  endif()
  file(GLOB written ${WORK}/*)
  if(written)
    message(FATAL_ERROR "hlrscript ${ARGN} failed but wrote: ${written}")
  endif()
endfunction()

expect_failure(65 "broken.hls:4:28: error: bad argument 'sides' to cylinder\\(\\)[^\n]*\n +4 \\| draw cylinder[^\n]*\n +\\| +\\^"
               ${SCRIPTS}/broken.hls -o ${WORK}/out.pdf)
expect_failure(65 "lib/broken_part.hls:1:17: error: cannot apply '/' to a string and a number"
               ${SCRIPTS}/broken_include.hls -o ${WORK}/out.pdf)
expect_failure(66 "cannot read" ${SCRIPTS}/does-not-exist.hls -o ${WORK}/out.pdf)
expect_failure(64 "supported: pdf, svg, png, hpgl" ${SCRIPTS}/posts.hls -o ${WORK}/out.svgz)
expect_failure(64 "unrecognised option|unrecognized option" ${SCRIPTS}/posts.hls --colour red)
expect_failure(73 "does not exist" ${SCRIPTS}/posts.hls -o ${WORK}/no-such-dir/out.pdf)

# The input script itself is never an output.
file(COPY ${SCRIPTS}/posts.hls DESTINATION ${WORK}/../e2e-script-errors-input)
set(input ${WORK}/../e2e-script-errors-input/posts.hls)
file(READ ${input} before)
execute_process(COMMAND ${HLRSCRIPT} ${input} -o ${input} RESULT_VARIABLE rc ERROR_VARIABLE err)
file(READ ${input} after)
if(NOT rc EQUAL 64 OR NOT err MATCHES "unknown output type|refusing to overwrite" OR NOT before STREQUAL after)
  message(FATAL_ERROR "-o equal to the script: expected exit 64 and the script untouched, got ${rc}: ${err}")
endif()
