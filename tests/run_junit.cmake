# --junit (issue 14): the JUnit report of a run whose checks pass, fail and
# skip parses (Python's xml.etree) and holds exactly the verdict lines; with
# REPORTS (the run's --out), so do the verdicts files and the index there;
# with SUMMARY, the closing line matches it (a regular expression).
file(REMOVE ${OUT}.xml)
execute_process(COMMAND ${EXE} verify ${ARGS} --junit ${OUT}.xml
                RESULT_VARIABLE rc OUTPUT_FILE ${OUT}.txt ERROR_QUIET)
if(NOT rc EQUAL CODE)
  message(FATAL_ERROR "exit ${rc}, expected ${CODE}")
endif()
if(SUMMARY)   # the closing line
  file(READ ${OUT}.txt text)
  if(NOT text MATCHES "\n${SUMMARY}\n$")
    message(FATAL_ERROR "the closing line is not '${SUMMARY}':\n${text}")
  endif()
endif()
execute_process(COMMAND ${PYTHON} ${CHECK} ${OUT}.xml ${OUT}.txt ${REPORTS}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the JUnit report does not match the verdicts:\n${out}${err}")
endif()
message(STATUS "${out}")
