# Unity builds of the module libraries (docs/ci.md): CMake compiles the sources of each library
# as a few translation units of up to MODALTYRE_UNITY_LIBRARY_BATCH files each, so that the standard
# library, Eigen, yaml-cpp and the module's own headers are parsed, and their inline functions
# and common template instances compiled, once per batch instead of once per file. Included from
# the top-level CMakeLists.txt after the modules. The program (app/) is one unity translation
# unit of its own; the Python module (python/CMakeLists.txt) and the test executables declared
# with modaltyre_add_test(... UNITY ...) (tests/CMakeLists.txt) use the same option and
# MODALTYRE_UNITY_BATCH.
#
# Rules for the sources of a library or unity test executable (a batch is one translation unit):
# - file-local helpers (anonymous namespace, `static`, namespace-scope `const`/`constexpr`) must
#   have names unique within their target, or the file is listed below as kept out;
# - no `#define` before the includes that changes what a header declares.
# -DMODALTYRE_UNITY_BUILD=OFF compiles every file on its own (faster rebuilds after editing one
# file of a large batch).
option(MODALTYRE_UNITY_BUILD "Compile each library as a few unity translation units" ON)
set(MODALTYRE_UNITY_BATCH 8 CACHE STRING
    "Source files per unity translation unit of the test executables and the Python module")
# The libraries: 16 files a batch (fewer, larger units: about 8 % less compiler CPU than 8 in
# the README's build, largest unit 1.3 GB; docs/ci.md, fifth round); 8 in the sanitizer and fuzz
# builds, whose units need about 1.6 times the memory (2.0 GB at 8 already) on 2-job CI runners
# of 7 GB. The test executables stay at 8: their files' file-local names clash at 16.
if(MODALTYRE_SANITIZE OR MODALTYRE_FUZZ)
  set(_modaltyre_unity_library_batch 8)
else()
  set(_modaltyre_unity_library_batch 16)
endif()
set(MODALTYRE_UNITY_LIBRARY_BATCH ${_modaltyre_unity_library_batch} CACHE STRING
    "Source files per unity translation unit of a library")

if(MODALTYRE_UNITY_BUILD)
  foreach(module IN ITEMS core modal ema solvers rheology ground contact transient studies discover
                          tir init uncertainty report fmu)
    set_target_properties(modaltyre_${module} PROPERTIES UNITY_BUILD ON
                          UNITY_BUILD_BATCH_SIZE ${MODALTYRE_UNITY_LIBRARY_BATCH})
  endforeach()

  # Kept out of the batches, each compiled on its own:
  # - the two largest translation units (Eigen's BDCSVD and the LSCF's polynomial and complex
  #   solvers; 2.0 and 1.3 GB of compiler memory under ASan alone): a batch with them would need
  #   over 2.5 GB and serialise the build on one core;
  # - fmu/src/package.cc, the only user of libzip: the FMU's shared library (fmu/CMakeLists.txt)
  #   takes from the static archives only the objects it needs and does not link libzip; in a
  #   batch with the instance's files the packaging would come along and its libzip calls
  #   would stay undefined;
  # - the files with per-function instruction-set attributes and intrinsics (their AVX2 clones
  #   and `target` attributes stay in a translation unit of their own);
  # - modal/ and transient/ files whose file-local helpers share a name with another file's of
  #   the same module (kTwoPi, basis_row; kDisplacementTolerance, kJacobianEdgeMargin_m); kept
  #   out rather than renamed while those modules are edited elsewhere.
  set(_modaltyre_unity_alone
      transient/src/model.cc
      ema/src/lscf.cc
      fmu/src/package.cc
      solvers/src/serial_vector_ops.cc
      solvers/src/dense_product.cc
      transient/src/cell_kernels.cc
      transient/src/column_product.cc
      transient/src/cell_system.cc
      modal/src/modal_basis.cc
      modal/src/ring_basis.cc
      modal/src/ring_model.cc)
  foreach(file IN LISTS _modaltyre_unity_alone)
    string(REGEX MATCH "^[a-z]+" module ${file})
    set_source_files_properties(${PROJECT_SOURCE_DIR}/${file} TARGET_DIRECTORY modaltyre_${module}
                                PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
  endforeach()
endif()
