# The outside MF 6.2 longitudinal check of issue 46 ("done when"): `modaltyre tir export` and
# `modaltyre fmu` on a config, then tests/tir/mf_slip_outside_check.py (no code shared with
# tir/) drives the FMU at constant wheel speed through the example ctypes host and holds the
# exported longitudinal force and rolling resistance against it.
#   cmake -DSRC=.. -DCLI=.. -DPYTHON=.. -DCONFIG=.. -DWORK=.. -P mf_slip_outside_check.cmake
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
foreach(step "tir;export;${SRC}/${CONFIG};--output;${WORK}/exported.tir"
             "fmu;${SRC}/${CONFIG};--output;${WORK}/tyre.fmu")
  execute_process(COMMAND ${CLI} ${step} RESULT_VARIABLE code OUTPUT_VARIABLE out
                  ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "modaltyre ${step} exited ${code}\n${out}\n${err}")
  endif()
endforeach()
execute_process(COMMAND ${PYTHON} ${SRC}/tests/tir/mf_slip_outside_check.py ${WORK}/exported.tir
                        ${WORK}/tyre.fmu
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}")
if(NOT code EQUAL 0)
  message(FATAL_ERROR "mf_slip_outside_check.py exited ${code}\n${err}")
endif()
