# `mpirun -n 2 modaltyre sweep` writes the same CSV, byte for byte, as one process; a bad sweep
# file stops every rank with exit code 2 and one message. Run by CTest when the build has
# MODALTYRE_WITH_MPI=ON:  cmake -DSRC=.. -DCLI=.. -DMPIEXEC=.. -DWORK=.. -P mpi_sweep_test.cmake
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
# OpenMPI refuses root without these; two ranks may exceed the cores a CI machine grants.
set(ENV{OMPI_ALLOW_RUN_AS_ROOT} 1)
set(ENV{OMPI_ALLOW_RUN_AS_ROOT_CONFIRM} 1)
set(ENV{ASAN_OPTIONS} detect_leaks=0)  # LeakSanitizer reports OpenMPI's own allocations
set(mpirun ${MPIEXEC} -n 2 --oversubscribe)

# Three models (moduli) x loads, with one model whose cases all fail: the shares cut through
# models, and failed rows travel like the others.
file(WRITE ${WORK}/grid.yaml "base: ${SRC}/configs/sf350_2d_table3.yaml
set:
  modal.compliance_scale: 0.9
grid:
  solver.max_iterations: [1, 200]
  tread.modulus_MPa: [4, 6, 9]
  load_N: [2000, 3500, 5000, 6500, 8000]
output: unused.csv
")

function(run_sweep label expect_code)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL expect_code)
    message(FATAL_ERROR "${label}: exit ${code}, expected ${expect_code}\nstdout:\n${out}\nstderr:\n${err}")
  endif()
  set(last_err "${err}" PARENT_SCOPE)
endfunction()

foreach(flags "" "--warm-start")
  run_sweep("one process ${flags}" 0 ${CLI} sweep ${WORK}/grid.yaml --threads 1 ${flags}
            --output ${WORK}/single.csv)
  run_sweep("mpirun -n 2 ${flags}" 0 ${mpirun} ${CLI} sweep ${WORK}/grid.yaml --threads 1 ${flags}
            --output ${WORK}/mpi.csv)
  if(NOT last_err MATCHES "x 2 MPI ranks")
    message(FATAL_ERROR "the summary does not mention the two ranks:\n${last_err}")
  endif()
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${WORK}/single.csv ${WORK}/mpi.csv
                  RESULT_VARIABLE differ)
  if(differ)
    message(FATAL_ERROR "mpirun -n 2 ${flags}: the CSV differs from the single-process one")
  endif()
  file(STRINGS ${WORK}/mpi.csv lines)
  list(LENGTH lines n)
  if(NOT n EQUAL 31)
    message(FATAL_ERROR "expected a header and 30 rows, got ${n} lines")
  endif()
  file(REMOVE ${WORK}/mpi.csv)
endforeach()

# A bad sweep file: exit 2 from every rank, the message once, no output file.
file(WRITE ${WORK}/bad.yaml "base: ${SRC}/configs/sf350_2d_table3.yaml\ngrid:\n  load_N: [1000, -5]\noutput: ${WORK}/bad.csv\n")
run_sweep("bad sweep under mpirun" 2 ${mpirun} ${CLI} sweep ${WORK}/bad.yaml)
string(REGEX MATCHALL "bad.yaml" mentions "${last_err}")
list(LENGTH mentions count)
if(NOT count EQUAL 1 OR NOT last_err MATCHES "bad.yaml:3")
  message(FATAL_ERROR "expected one message naming bad.yaml:3, got:\n${last_err}")
endif()
if(EXISTS ${WORK}/bad.csv)
  message(FATAL_ERROR "a failed sweep left an output file")
endif()
