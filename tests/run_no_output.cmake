# No partial output (issue 5, developers' guide: bad input gets "exit code 2,
# and no partial output"): run EXE with ARGS (a ;-list, in WORKDIR) whose
# --out names OUT, and require
#   - exit code CODE,
#   - standard error matching REGEX (anchor it: ^...$), standard output empty,
#   - afterwards neither OUT nor OUT.tmp (the file being written) exists.
# Options:
#   PRE=TEXT     OUT exists beforehand with TEXT; it must be left as it was
#                (a failing run never touches an existing file).
#   OUT_IS_DIR=1 OUT is an existing directory (so the final rename fails); it
#                must still be one, and OUT.tmp must not exist.
#   SIGNAL=SIG, AFTER=S  send SIG after S seconds (timeout --preserve-status).
#   STDOUT_FILE=PATH     standard output goes to PATH (e.g. /dev/full) and is
#                not checked.
# Used by tests/cli_tests.cmake.
foreach(var EXE ARGS WORKDIR CODE REGEX OUT)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_no_output.cmake: ${var} not set")
  endif()
endforeach()

file(REMOVE_RECURSE "${OUT}" "${OUT}.tmp")
get_filename_component(dir "${OUT}" DIRECTORY)
file(MAKE_DIRECTORY "${dir}")
if(DEFINED PRE)
  file(WRITE "${OUT}" "${PRE}")
elseif(OUT_IS_DIR)
  file(MAKE_DIRECTORY "${OUT}")
endif()

set(cmd ${EXE} ${ARGS})
if(DEFINED SIGNAL)
  set(cmd timeout --preserve-status -s ${SIGNAL} ${AFTER} ${cmd})
endif()
if(DEFINED STDOUT_FILE)
  execute_process(COMMAND ${cmd} WORKING_DIRECTORY ${WORKDIR} RESULT_VARIABLE rc
                  OUTPUT_FILE ${STDOUT_FILE} ERROR_VARIABLE err)
  set(out "")
else()
  execute_process(COMMAND ${cmd} WORKING_DIRECTORY ${WORKDIR} RESULT_VARIABLE rc
                  OUTPUT_VARIABLE out ERROR_VARIABLE err)
endif()

if(NOT rc EQUAL CODE)
  message(FATAL_ERROR "exit code ${rc}, expected ${CODE}; stderr:\n${err}")
endif()
if(NOT err MATCHES "${REGEX}")
  message(FATAL_ERROR "stderr does not match '${REGEX}':\n${err}")
endif()
if(NOT out STREQUAL "")
  message(FATAL_ERROR "partial output on standard output:\n${out}")
endif()
if(EXISTS "${OUT}.tmp")
  message(FATAL_ERROR "half-written ${OUT}.tmp left behind")
endif()
if(DEFINED PRE)
  file(READ "${OUT}" now)
  if(NOT now STREQUAL PRE)
    message(FATAL_ERROR "the existing ${OUT} was changed:\n${now}")
  endif()
elseif(OUT_IS_DIR)
  if(NOT IS_DIRECTORY "${OUT}")
    message(FATAL_ERROR "the directory ${OUT} was replaced")
  endif()
elseif(EXISTS "${OUT}")
  file(READ "${OUT}" now)
  message(FATAL_ERROR "partial output: ${OUT} exists after a failed run:\n${now}")
endif()
message(STATUS "ok: exit ${rc}, ${err}no partial output")
