# ctest script: regenerates doc/messages.md into OUTPUT and compares it with the committed page.
#   cmake -DTOOL=<stella-messages> -DSOURCE_DIR=<repo> -DOUTPUT=<tmp file> -P CheckDoc.cmake
execute_process(COMMAND ${TOOL} doc OUTPUT_FILE ${OUTPUT} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "stella-messages doc failed (${rc})")
endif()
file(READ ${OUTPUT} new)
file(READ ${SOURCE_DIR}/doc/messages.md old)
if(NOT new STREQUAL old)
  message(FATAL_ERROR "doc/messages.md is stale; regenerate with: ${TOOL} doc > ${SOURCE_DIR}/doc/messages.md")
endif()
message(STATUS "doc/messages.md is up to date")
