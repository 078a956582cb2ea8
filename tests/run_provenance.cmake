# Every report file carries its provenance (issue 13): each CSV and gnuplot
# script a case writes starts with "# gdsmc VERSION verify: scene ...", each
# Markdown table names "gdsmc VERSION" in its notes.  Checked on the files
# that cases with every figure kind write (curves, points and theory,
# work-precision and targets) and, with PAPER set, on every committed file of
# reports/paper, so that a version raised without regenerating them fails.
function(check_dir dir)
  file(GLOB files ${dir}/*.csv ${dir}/*.gp ${dir}/*.md)
  list(LENGTH files count)
  if(count EQUAL 0)
    message(FATAL_ERROR "no report files in ${dir}")
  endif()
  foreach(f ${files})
    file(STRINGS ${f} lines LIMIT_COUNT 3)
    if(f MATCHES "\\.md$")   # the notes paragraph, after the title
      string(FIND "${lines}" "gdsmc ${VERSION} verify: scene " at)
      set(ok 0)
      if(at GREATER -1)
        set(ok 1)
      endif()
    else()                    # the first line
      list(GET lines 0 first)
      string(FIND "${first}" "# gdsmc ${VERSION} verify: scene " at)
      set(ok 0)
      if(at EQUAL 0)
        set(ok 1)
      endif()
    endif()
    if(NOT ok)
      message(FATAL_ERROR "${f}: no provenance of gdsmc ${VERSION} at its start:\n${lines}")
    endif()
  endforeach()
  message(STATUS "${count} files in ${dir} carry the provenance of gdsmc ${VERSION}")
endfunction()

file(REMOVE_RECURSE ${OUT})
foreach(c brs-ex1 ms-a2-white-noise cost-brs-ex2)
  execute_process(COMMAND ${EXE} verify --suite quick --case ${c} --out ${OUT}
                  RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "gdsmc verify --case ${c} exited ${rc}:\n${err}")
  endif()
endforeach()
check_dir(${OUT})
if(PAPER)
  check_dir(${PAPER})
endif()
