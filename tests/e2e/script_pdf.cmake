# Runs the built hlrscript on tests/e2e/scripts/ and checks the PDFs with poppler: page counts for all
# frames, --frames, --shard, one file per frame (-o with {frame:02} and the script's own output name),
# the script's paper size, the default name FILE.pdf, and `check`, which writes nothing.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})

function(run_ok)
  execute_process(COMMAND ${HLRSCRIPT} ${ARGN} WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc OUTPUT_VARIABLE out
                  ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "hlrscript ${ARGN} failed (${rc}):\n${out}${err}")
  endif()
  set(last_out "${out}" PARENT_SCOPE)
endfunction()

function(expect_pages pdf pages)
  execute_process(COMMAND pdfinfo ${pdf} RESULT_VARIABLE rc OUTPUT_VARIABLE info ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "pdfinfo cannot read ${pdf}: ${err}")
  endif()
  if(NOT info MATCHES "Pages: +${pages}\n")
    message(FATAL_ERROR "${pdf}: expected ${pages} pages:\n${info}")
  endif()
  set(last_info "${info}" PARENT_SCOPE)
endfunction()

# Every frame, default name posts.pdf in the working directory, on the script's A3 portrait paper.
run_ok(${SCRIPTS}/posts.hls)
expect_pages(${WORK}/posts.pdf 3)
if(NOT last_info MATCHES "Page size: +841.89 x 1190.55 pts")
  message(FATAL_ERROR "expected A3 portrait (paper A3 portrait in the script):\n${last_info}")
endif()

run_ok(${SCRIPTS}/posts.hls -o ${WORK}/selected.pdf --frames 1-2 --jobs 2)
expect_pages(${WORK}/selected.pdf 2)
run_ok(${SCRIPTS}/posts.hls -o ${WORK}/shard.pdf --shard 2/2)
expect_pages(${WORK}/shard.pdf 1)

run_ok(${SCRIPTS}/posts.hls -o ${WORK}/frame-{frame:02}.pdf --hidden dashed)
foreach(f 00 01 02)
  expect_pages(${WORK}/frame-${f}.pdf 1)
endforeach()

run_ok(${SCRIPTS}/named_output.hls)
expect_pages(${WORK}/named-00.pdf 1)
expect_pages(${WORK}/named-01.pdf 1)

file(REMOVE ${WORK}/posts.pdf)
run_ok(check ${SCRIPTS}/posts.hls)
if(NOT last_out MATCHES "posts.hls: ok: 3 frames evaluated")
  message(FATAL_ERROR "check: unexpected summary: ${last_out}")
endif()
if(EXISTS ${WORK}/posts.pdf)
  message(FATAL_ERROR "check wrote ${WORK}/posts.pdf")
endif()
