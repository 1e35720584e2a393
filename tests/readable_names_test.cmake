# Issue 16 item 9: every parameterised test prints its case readably. GoogleTest prints a
# parameter without a PrintTo overload as raw bytes ("GetParam() = 24-byte object <89-97 ...>");
# this lists every test executable's tests and refuses such a line, naming the suite.
#   cmake "-DEXES=a;b" -P readable_names_test.cmake
set(bad "")
foreach(exe IN LISTS EXES)
  execute_process(COMMAND ${exe} --gtest_list_tests RESULT_VARIABLE code OUTPUT_VARIABLE out
                  ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "${exe} --gtest_list_tests: exit ${code}\n${err}")
  endif()
  string(REGEX MATCHALL "[^\n]*-byte object <[^\n]*" lines "${out}")
  foreach(line IN LISTS lines)
    string(SUBSTRING "${line}" 0 160 line)
    string(APPEND bad "\n  ${exe}: ${line}")
  endforeach()
endforeach()
if(bad)
  message(FATAL_ERROR "parameters printed as raw bytes (give the case a PrintTo or "
                      "operator<<, and the suite a name generator):${bad}")
endif()
