# Run COMMAND (a ;-list) in WORKDIR and require exit code CODE.  With LAST
# (not empty): the last non-blank line of its standard error must be exactly
# LAST (a refusal's reason, docs/solver-protocol.md).  With RESULT (not
# empty): the file must match every regular expression of RESULT_HAS (a
# ;-list) and none of RESULT_LACKS.  Used by tests/examples.cmake.
if(NOT RESULT STREQUAL "")
  file(REMOVE "${RESULT}")
endif()
execute_process(COMMAND ${COMMAND} WORKING_DIRECTORY ${WORKDIR}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL CODE)
  message(FATAL_ERROR "exit code ${rc}, expected ${CODE}; output:\n${out}\nerror:\n${err}")
endif()
if(NOT LAST STREQUAL "")
  string(STRIP "${err}" stripped)
  string(REGEX MATCH "[^\n]*$" last "${stripped}")
  if(NOT last STREQUAL LAST)
    message(FATAL_ERROR "the last line of standard error is\n  '${last}'\nexpected\n  '${LAST}'")
  endif()
endif()
if(NOT RESULT STREQUAL "")
  file(READ "${RESULT}" text)
  foreach(re IN LISTS RESULT_HAS)
    if(NOT text MATCHES "${re}")
      message(FATAL_ERROR "${RESULT} does not match '${re}':\n${text}")
    endif()
  endforeach()
  foreach(re IN LISTS RESULT_LACKS)
    if(text MATCHES "${re}")
      message(FATAL_ERROR "${RESULT} matches '${re}':\n${text}")
    endif()
  endforeach()
endif()
message(STATUS "ok: exit ${rc}; ${err}")
