# The packed FMU loads where nothing of the project is (FMI 2.0 section 2.3, issue 46 item 1):
# packs CONFIG with the built `modaltyre fmu`, unzips it into a fresh folder under the system's
# temporary directory (outside the build tree), checks that the host itself needs nothing but
# glibc, and runs it there with an empty environment (no LD_LIBRARY_PATH, no PATH):
# tests/fmu/clean_host.cc loads ModalTyre.so, presses the tyre and fails if the process then
# holds any shared object but glibc's and the FMU's (libyaml-cpp, libstdc++, libgomp, ...).
#   cmake -DCLI=... -DHOST=... -DCONFIG=... -P clean_load.cmake
foreach(v CLI HOST CONFIG)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "clean_load.cmake: -D${v}= is required")
  endif()
endforeach()
if(DEFINED ENV{TMPDIR})
  set(tmp "$ENV{TMPDIR}")
else()
  set(tmp "/tmp")
endif()
string(RANDOM LENGTH 12 tag)
set(work "${tmp}/modaltyre_clean_fmu_${tag}")
file(MAKE_DIRECTORY "${work}/unzipped")

execute_process(COMMAND "${CLI}" fmu "${CONFIG}" --output "${work}/tyre.fmu"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  file(REMOVE_RECURSE "${work}")
  message(FATAL_ERROR "modaltyre fmu failed (${rc}):\n${out}${err}")
endif()
file(ARCHIVE_EXTRACT INPUT "${work}/tyre.fmu" DESTINATION "${work}/unzipped")
file(COPY "${HOST}" DESTINATION "${work}")
get_filename_component(host_name "${HOST}" NAME)

# The host must not bring the C++ runtime in itself, or the check below would prove nothing.
execute_process(COMMAND readelf -d "${work}/${host_name}" OUTPUT_VARIABLE dyn RESULT_VARIABLE rc)
string(REGEX MATCHALL "Shared library: \\[[^]]+\\]" host_needs "${dyn}")
foreach(n IN LISTS host_needs)
  if(NOT n MATCHES "\\[(libc\\.so\\.6|libm\\.so\\.6|ld-linux-x86-64\\.so\\.2)\\]")
    file(REMOVE_RECURSE "${work}")
    message(FATAL_ERROR "the clean host itself needs ${n}")
  endif()
endforeach()

execute_process(COMMAND env -i "${work}/${host_name}" "${work}/unzipped"
                WORKING_DIRECTORY "${work}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
set(deps "")
if(EXISTS "${work}/unzipped/documentation/externalDependencies.txt")
  file(READ "${work}/unzipped/documentation/externalDependencies.txt" deps)
endif()
file(REMOVE_RECURSE "${work}")
message(STATUS "${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the FMU did not load and run with glibc alone (${rc})")
endif()
if(NOT deps MATCHES "Required: the GNU C library \\(glibc\\), version 2\\.[0-9]+ or newer")
  message(FATAL_ERROR "externalDependencies.txt does not state the glibc version:\n${deps}")
endif()
