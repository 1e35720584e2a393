# The outside MF-formula check of issue 20 ("done when"): `modaltyre tir export` on a config, then
# tests/tir/mf_outside_check.py (numpy only, no code shared with tir/) reads the file and holds
# VERTICAL_STIFFNESS, the sinking and the lengths against the model's own footprints.
#   cmake -DSRC=.. -DCLI=.. -DPYTHON=.. -DCONFIG=.. -DWORK=.. -P mf_outside_check.cmake
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
execute_process(COMMAND ${CLI} tir export ${SRC}/${CONFIG} --output ${WORK}/exported.tir
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "tir export exited ${code}\n${out}\n${err}")
endif()
execute_process(COMMAND ${PYTHON} ${SRC}/tests/tir/mf_outside_check.py ${CLI} ${SRC}/${CONFIG}
                        ${WORK}/exported.tir
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}")
if(NOT code EQUAL 0)
  message(FATAL_ERROR "mf_outside_check.py exited ${code}\n${err}")
endif()
