# SIGINT or SIGTERM (SIG) during a long verify run: gdsmc stops after the
# ensemble in progress with exit status 130, says how to resume, and leaves
# no half-written file (issue 5: nothing lost).  The run (paper A Ex 3 at the
# paper's sizes) takes minutes, so the signal after 3 s always lands mid-run.
file(REMOVE_RECURSE ${OUT})
execute_process(COMMAND timeout --preserve-status -s ${SIG} 3 ${EXE} verify --case grw-ex3
                        --out ${OUT}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 130)
  message(FATAL_ERROR "exit status ${rc} after SIG${SIG}, expected 130:\n${out}${err}")
endif()
if(NOT err MATCHES "stopped on request.*run the same command with --resume")
  message(FATAL_ERROR "no stop message after SIG${SIG}:\n${err}")
endif()
file(GLOB_RECURSE partial ${OUT}/*.tmp)
if(partial)
  message(FATAL_ERROR "half-written files left behind: ${partial}")
endif()
message(STATUS "SIG${SIG}: exit 130, nothing half-written")
