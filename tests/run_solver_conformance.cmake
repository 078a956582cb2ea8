# The solver protocol's conformance test (issue 14): grw-ex4 at quick sizes
# with the built-in engine, and again through the protocol with the built-in
# engine as the external solver (gdsmc run --result).  The verdicts and every
# table, curve and figure file must be the same, timings masked and the
# provenance's "; solver '...' (solver line)" (which names the solver) aside.
file(REMOVE_RECURSE ${OUT}-engine ${OUT}-protocol)
execute_process(COMMAND ${EXE} verify --suite quick --case grw-ex4 --out ${OUT}-engine
                RESULT_VARIABLE rc_engine OUTPUT_VARIABLE verdicts_engine ERROR_QUIET)
execute_process(COMMAND ${EXE} verify --suite quick --case grw-ex4 --out ${OUT}-protocol
                        --solver "${EXE} run {scene} --result {out} --quiet"
                RESULT_VARIABLE rc_protocol OUTPUT_VARIABLE verdicts_protocol
                ERROR_VARIABLE err)
if(NOT rc_engine EQUAL 0 OR NOT rc_protocol EQUAL 0)
  message(FATAL_ERROR "exit ${rc_engine} (engine), ${rc_protocol} (protocol):\n${err}")
endif()
if(NOT verdicts_engine STREQUAL verdicts_protocol)
  message(FATAL_ERROR "the verdicts differ:\n${verdicts_engine}\n---\n${verdicts_protocol}")
endif()
string(REGEX MATCH "verify: [0-9]+ passed, 0 failed" summary "${verdicts_protocol}")
if(NOT summary)
  message(FATAL_ERROR "no verdict summary:\n${verdicts_protocol}")
endif()
file(GLOB files ${OUT}-protocol/*.csv ${OUT}-protocol/*.md ${OUT}-protocol/*.gp)
list(LENGTH files count)
if(count LESS 4)
  message(FATAL_ERROR "only ${count} report files in ${OUT}-protocol")
endif()
foreach(f ${files})
  file(READ ${f} text)
  string(REGEX REPLACE "; solver '[^'\n]*'( \\([^\n]*\\))?" "" text "${text}")
  file(WRITE ${f} "${text}")
endforeach()
execute_process(COMMAND ${PYTHON} ${COMPARE} ${OUT}-engine ${OUT}-protocol
                RESULT_VARIABLE rc OUTPUT_VARIABLE diff)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the reports differ:\n${diff}")
endif()
message(STATUS "${summary}, the same through the protocol; ${diff}")
