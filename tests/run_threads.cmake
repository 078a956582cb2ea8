# The same run with OMP_NUM_THREADS=1 and 2 must give byte-identical CSVs
# (ensemble j always uses random stream (seed, j); sums in fixed blocks).
foreach(threads 1 2)
  set(ENV{OMP_NUM_THREADS} ${threads})
  execute_process(COMMAND ${EXE} run ${SCENE} --set particles.n=64
                          --set particles.ensembles=600 --out ${OUT}-${threads}.csv
                  RESULT_VARIABLE rc ERROR_VARIABLE summary)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "gdsmc run with ${threads} threads exited ${rc}")
  endif()
  # the run's summary names the threads it used: else the comparison is vacuous
  if(NOT summary MATCHES "wall on ${threads} threads?\n")
    message(FATAL_ERROR "gdsmc run with OMP_NUM_THREADS=${threads} did not use ${threads} "
                        "threads:\n${summary}")
  endif()
endforeach()
file(READ ${OUT}-1.csv one)
file(READ ${OUT}-2.csv two)
if(NOT one STREQUAL two)
  message(FATAL_ERROR "CSV differs between 1 and 2 threads")
endif()
string(REGEX MATCHALL "\n[0-9]" rows "${one}")
list(LENGTH rows nrows)
if(NOT nrows EQUAL 81)
  message(FATAL_ERROR "expected the scene's 81 output rows, got ${nrows}")
endif()
message(STATUS "identical CSVs with 1 and 2 threads, ${nrows} rows")
