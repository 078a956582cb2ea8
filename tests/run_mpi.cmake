# The same run on 1 process and on 2 MPI ranks (1 thread each, then 1 and 2
# threads) must give byte-identical CSVs (docs/theory.md §8.6: a seed fixes every
# number; sim/ensemble.c shares the blocks of ensembles across the ranks).
# Hard spheres with heating: the majorant, fictitious collisions and Brownian
# catch-ups all take part.  Also: only rank 0 speaks, and bad input still
# exits 2 under mpiexec.  OpenMPI's mpiexec (-x, --oversubscribe).
# -DEXE -DMPIEXEC -DNP_FLAG -DSCENE -DOUT
set(run run ${SCENE} --set particles.n=64 --set particles.ensembles=200)

# 1 process, 1 thread, without mpiexec (MPI_Init as a singleton).
set(ENV{OMP_NUM_THREADS} 1)
execute_process(COMMAND ${EXE} ${run} --quiet --out ${OUT}-1.csv RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "gdsmc run (1 process) exited ${rc}")
endif()
file(READ ${OUT}-1.csv one)
string(REGEX MATCHALL "\n[0-9]" rows "${one}")
list(LENGTH rows nrows)
if(NOT nrows EQUAL 81)
  message(FATAL_ERROR "expected the scene's 81 output rows, got ${nrows}")
endif()

# 2 ranks; the summary line (rank 0's alone) counts the threads of all ranks,
# which shows that both took part.
foreach(layout "2x1" "1+2")
  if(layout STREQUAL "2x1")
    set(ranks ${NP_FLAG} 2 -x OMP_NUM_THREADS=1 ${EXE} ${run} --out ${OUT}-${layout}.csv)
    set(threads 2)
  else()   # MPMD: rank 0 with 1 thread, rank 1 with 2
    set(ranks ${NP_FLAG} 1 -x OMP_NUM_THREADS=1 ${EXE} ${run} --out ${OUT}-${layout}.csv :
              ${NP_FLAG} 1 -x OMP_NUM_THREADS=2 ${EXE} ${run} --out ${OUT}-${layout}.csv)
    set(threads 3)
  endif()
  file(REMOVE ${OUT}-${layout}.csv)
  execute_process(COMMAND ${MPIEXEC} --oversubscribe ${ranks}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "mpiexec (${layout}) exited ${rc}:\n${out}${err}")
  endif()
  string(REGEX MATCHALL "gdsmc run:" lines "${out}${err}")
  list(LENGTH lines nlines)
  if(NOT nlines EQUAL 1 OR NOT err MATCHES "200 ensembles of 64 particles.* on ${threads} threads")
    message(FATAL_ERROR "expected one summary line from rank 0 with ${threads} threads "
                        "(${layout}), got:\n${out}${err}")
  endif()
  file(READ ${OUT}-${layout}.csv two)
  if(NOT one STREQUAL two)
    message(FATAL_ERROR "CSV differs between 1 process and 2 ranks (${layout}): "
                        "diff ${OUT}-1.csv ${OUT}-${layout}.csv")
  endif()
  message(STATUS "identical CSVs with 1 process and 2 ranks (${layout}), ${nrows} rows")
endforeach()

# Bad input under mpiexec: exit 2 and the message once (rank 1 is silent).
execute_process(COMMAND ${MPIEXEC} --oversubscribe ${NP_FLAG} 2 ${EXE} run ${SCENE}
                        --set particles.n=0
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(REGEX MATCHALL "gdsmc run: [^\n]*particles.n" lines "${out}${err}")
list(LENGTH lines nlines)
if(NOT rc EQUAL 2 OR NOT nlines EQUAL 1)
  message(FATAL_ERROR "bad input on 2 ranks: exit ${rc} (expected 2), ${nlines} messages "
                      "(expected 1):\n${out}${err}")
endif()
message(STATUS "bad input on 2 ranks: exit ${rc}, one message")
