# runtime/BUILTINS.md is what `hlrscript help reference` prints from the built-ins' tables: a built-in
# added or changed without regenerating it fails here. Regenerate with scripts/update_reference.sh.
execute_process(COMMAND ${HLRSCRIPT} help reference OUTPUT_VARIABLE generated RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "hlrscript help reference exited with ${status}")
endif()
file(READ ${REFERENCE} current)
if(NOT generated STREQUAL current)
  message(FATAL_ERROR "${REFERENCE} is not what 'hlrscript help reference' prints; run scripts/update_reference.sh")
endif()
