# Installs the built project into a scratch prefix, builds examples/footprint_consumer against it
# with find_package(ModalTyre) and runs it on the bundled config; when the Python module is built
# (PYTHON = its interpreter, PYTHON_DIR = its package directory under the prefix), imports it
# from the prefix with only that directory on PYTHONPATH and solves a footprint.
# Arguments: SRC, BIN, WORK [, PYTHON, PYTHON_DIR].
file(REMOVE_RECURSE ${WORK})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BIN} --prefix ${WORK}/prefix
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(rc)
  message(FATAL_ERROR "cmake --install failed: ${rc}")
endif()
# The licence is part of the installed package (share/doc/ModalTyre/LICENSE), byte for byte.
file(GLOB_RECURSE installed_licence ${WORK}/prefix/share/doc/*/LICENSE)
if(NOT installed_licence)
  message(FATAL_ERROR "the installed package carries no LICENSE under share/doc")
endif()
file(READ ${SRC}/LICENSE want)
file(READ ${installed_licence} got)
if(NOT want STREQUAL got)
  message(FATAL_ERROR "the installed ${installed_licence} differs from ${SRC}/LICENSE")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SRC}/examples/footprint_consumer -B ${WORK}/consumer
                        -G Ninja -DCMAKE_PREFIX_PATH=${WORK}/prefix -DCMAKE_BUILD_TYPE=Release
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc)
  message(FATAL_ERROR "configuring the consumer failed:\n${out}\n${err}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK}/consumer
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc)
  message(FATAL_ERROR "building the consumer failed:\n${out}\n${err}")
endif()
execute_process(COMMAND ${WORK}/consumer/footprint_consumer ${SRC}/configs/sf350_2d_table3.yaml 5478
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc OR NOT out MATCHES "sinking_mm [0-9.]+ contact_length_mm [0-9.]+")
  message(FATAL_ERROR "the consumer did not solve a footprint (${rc}):\n${out}\n${err}")
endif()
message(STATUS "consumer: ${out}")
if(PYTHON)
  set(site ${WORK}/prefix/${PYTHON_DIR})
  execute_process(
    COMMAND ${CMAKE_COMMAND} -E env PYTHONPATH=${site} ${PYTHON} -c
            "import modaltyre; print(modaltyre.__file__); print(modaltyre.Tyre('${SRC}/configs/sf350_2d_table3.yaml').footprint(5478).sinking_mm)"
    WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(rc OR NOT out MATCHES "^${site}/modaltyre/__init__.py\n[0-9.]+\n$")
    message(FATAL_ERROR "the installed Python module did not import from ${site} (${rc}):\n${out}\n${err}")
  endif()
  message(STATUS "python: ${out}")
endif()
file(REMOVE_RECURSE ${WORK})
