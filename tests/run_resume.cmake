# Nothing lost (issue 5): a verify run interrupted twice and resumed twice
# must leave the same tables as an uninterrupted run.
#
# The interrupts are deterministic: GDSMC_STOP_AFTER_RUNS=K makes gdsmc act
# as if SIGINT arrived after K finished simulations (exit 130).  Both runs
# write to the same directory (OUT) in turn, so the figure scripts, which
# name their files, compare byte for byte too.  The only cells allowed to
# differ are the measured times: the columns cpu_s, wall_s and ns_per_event
# of each table (the index's too), the notes' "wall time X s" and a verdicts
# file's "wall_s = W, cpu_s = C" (resumed rows keep the times
# recorded when they ran, the other rows are timed afresh).
cmake_policy(SET CMP0007 NEW)   # keep empty list elements: empty table cells
set(ARGS verify --suite quick --case ${CASE} --out ${OUT})

function(run_gdsmc expect_rc stop_after)
  set(ENV{GDSMC_STOP_AFTER_RUNS} ${stop_after})
  execute_process(COMMAND ${EXE} ${ARGS} ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out
                  ERROR_VARIABLE err)
  if(NOT rc EQUAL expect_rc)
    message(FATAL_ERROR "gdsmc ${ARGS} ${ARGN} (stop after ${stop_after}) exited ${rc}, "
                        "expected ${expect_rc}:\n${out}${err}")
  endif()
  set(last_output "${out}${err}" PARENT_SCOPE)
endfunction()

# Blank the timing cells of a CSV or Markdown table and the notes' wall time.
function(mask_timing text result)
  string(REPLACE ";" "<semicolon>" text "${text}")
  string(REGEX REPLACE "wall time [0-9.]+ s" "wall time ? s" text "${text}")
  string(REGEX REPLACE "wall_s = [0-9.]+, cpu_s = [0-9.]+" "wall_s = ?, cpu_s = ?" text
         "${text}")
  string(REPLACE "\n" ";" lines "${text}")
  set(masked "")
  set(timing "")
  foreach(line IN LISTS lines)
    if(line MATCHES "^\\| ")
      set(sep "|")
    else()
      set(sep ",")
    endif()
    string(REPLACE "${sep}" ";" cells "${line}")
    if(line MATCHES "^\\| .*\\| cpu_s \\|" OR line MATCHES "^[^# ]*,cpu_s(,|$)")
      # a table's header row: find the timing columns
      set(timing "")
      set(i 0)
      foreach(cell IN LISTS cells)
        string(STRIP "${cell}" name)
        if(name STREQUAL "cpu_s" OR name STREQUAL "wall_s" OR name STREQUAL "ns_per_event")
          list(APPEND timing ${i})
        endif()
        math(EXPR i "${i} + 1")
      endforeach()
    elseif(timing AND NOT line MATCHES "^#")
      list(LENGTH cells ncells)
      foreach(i IN LISTS timing)
        if(i LESS ncells)
          list(REMOVE_AT cells ${i})
          list(INSERT cells ${i} "?")
        endif()
      endforeach()
    endif()
    string(REPLACE ";" "${sep}" line "${cells}")
    string(APPEND masked "${line}\n")
  endforeach()
  set(${result} "${masked}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE ${OUT} ${OUT}-uninterrupted)
run_gdsmc(${RC} 0)
file(RENAME ${OUT} ${OUT}-uninterrupted)

run_gdsmc(130 1)
if(NOT last_output MATCHES "run the same command with --resume")
  message(FATAL_ERROR "the interrupted run does not say how to resume:\n${last_output}")
endif()
file(GLOB partial ${OUT}/*.tmp ${OUT}/.checkpoint/*.tmp)
if(partial)
  message(FATAL_ERROR "half-written files left behind: ${partial}")
endif()
if(NOT EXISTS ${OUT}/${CASE}.csv)
  message(FATAL_ERROR "the interrupted run left no table of its finished row")
endif()
run_gdsmc(130 1 --resume)
run_gdsmc(${RC} 0 --resume)
string(REGEX MATCHALL "taken from its checkpoint" reused "${last_output}")
list(LENGTH reused nreused)
if(NOT nreused EQUAL 2)
  message(FATAL_ERROR "expected 2 simulations taken from checkpoints, saw ${nreused}:\n"
                      "${last_output}")
endif()

file(GLOB_RECURSE expected RELATIVE ${OUT}-uninterrupted ${OUT}-uninterrupted/*.csv
     ${OUT}-uninterrupted/*.md ${OUT}-uninterrupted/*.gp)
list(LENGTH expected nfiles)
if(nfiles LESS 3)
  message(FATAL_ERROR "the uninterrupted run wrote only ${nfiles} tables")
endif()
foreach(f IN LISTS expected)
  if(NOT EXISTS ${OUT}/${f})
    message(FATAL_ERROR "${f}: missing after the resumed run")
  endif()
  file(READ ${OUT}-uninterrupted/${f} a)
  file(READ ${OUT}/${f} b)
  mask_timing("${a}" a)
  mask_timing("${b}" b)
  if(NOT a STREQUAL b)
    message(FATAL_ERROR "${f} differs between the uninterrupted and the resumed run")
  endif()
endforeach()
message(STATUS "${nfiles} files identical (timings aside) after two interrupts and resumes")
