# Optimisation levels of a Release build (docs/ci.md, fifth round; issue 47): CMake's -O3 stays
# for the modules whose loops the run time is spent in (the footprint's contact solve, the
# transient integration, the modal kernels, the solvers, the soil), and GCC's -O2 is given to
# the others (the command line, reports, fits, identification, studies, the FMU's glue), which
# it compiles 10-30 % faster. The answers do not depend on it: without -ffast-math neither level
# reassociates or contracts floating-point operations (the README's footprints and the
# transient's outputs were compared byte for byte). -O2 everywhere was measured 13-16 % slower
# on the 3D transient, hence the split. Included from the top-level CMakeLists.txt after the
# modules; the sanitizer and fuzz builds (RelWithDebInfo) set their own level.
set(MODALTYRE_COLD_OPTIMISATION "-O2" CACHE STRING
    "Optimisation flag of the modules outside the hot loops in Release builds (empty: the build type's own)")

if(MODALTYRE_COLD_OPTIMISATION)
  set(_modaltyre_cold_targets modaltyre modaltyre_core modaltyre_ema modaltyre_rheology
                              modaltyre_studies modaltyre_discover modaltyre_tir modaltyre_init
                              modaltyre_uncertainty modaltyre_report modaltyre_fmu _modaltyre)
  foreach(target IN LISTS _modaltyre_cold_targets)
    if(TARGET ${target})
      # After CMAKE_CXX_FLAGS_RELEASE on the command line: the last -O wins.
      target_compile_options(${target} PRIVATE
                             $<$<CONFIG:Release>:${MODALTYRE_COLD_OPTIMISATION}>)
    endif()
  endforeach()
endif()
