# The FMU's self-containment test (included from tests/CMakeLists.txt): a host built from C
# library calls only, linked without the C++ runtime, loads a packed FMU in an empty
# environment outside the build tree (clean_load.cmake). Not in a sanitized build, whose
# ModalTyre.so needs the sanitizers' runtime by construction.
if(NOT MODALTYRE_FMU_SELF_CONTAINED)
  target_compile_definitions(fmu_tests PRIVATE MODALTYRE_FMU_SANITIZED)
endif()
if(MODALTYRE_FMU_SELF_CONTAINED)
  add_executable(fmu_clean_host ${CMAKE_CURRENT_LIST_DIR}/clean_host.cc)
  target_include_directories(fmu_clean_host PRIVATE ${PROJECT_SOURCE_DIR}/fmu/include)
  target_compile_options(fmu_clean_host PRIVATE -fno-exceptions -fno-rtti)
  target_link_options(fmu_clean_host PRIVATE -Wl,--as-needed)
  target_link_libraries(fmu_clean_host PRIVATE ${CMAKE_DL_LIBS})
  add_dependencies(fmu_clean_host modaltyre modaltyre_fmu_binary)
  add_test(NAME FmuSelfContained.LoadsWithGlibcAloneOutsideTheBuildTree
           COMMAND ${CMAKE_COMMAND} -DCLI=$<TARGET_FILE:modaltyre>
                   -DHOST=$<TARGET_FILE:fmu_clean_host>
                   -DCONFIG=${PROJECT_SOURCE_DIR}/configs/sf350_2d_table3.yaml
                   -P ${CMAKE_CURRENT_LIST_DIR}/clean_load.cmake)
  set_tests_properties(FmuSelfContained.LoadsWithGlibcAloneOutsideTheBuildTree
                       PROPERTIES TIMEOUT 300)
endif()
