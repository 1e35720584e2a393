#pragma once
// The repository's configurations and data files that many tests read, defined once for every
// test executable (MODALTYRE_SOURCE_DIR: tests/CMakeLists.txt). A test file's own copy would
// clash with its neighbours' in a unity translation unit (docs/ci.md).
#include <string>

namespace modaltyre_test {

inline const std::string kSrc = MODALTYRE_SOURCE_DIR;
/// The 2D SF-350 of the paper's Table 3.
inline const std::string kConfig2d = kSrc + "/configs/sf350_2d_table3.yaml";
/// The default tyre: the 3D SF-350.
inline const std::string kConfig3d = kSrc + "/configs/sf350.yaml";
/// The measured footprint of Table 3.
inline const std::string kTable3 = kSrc + "/configs/data/sf350_footprint_table3.csv";
/// The LETE sand's soil file.
inline const std::string kLeteSandYaml = kSrc + "/configs/soils/lete_sand.yaml";
/// The SF-350's hammer test at 12 points.
inline const std::string kHammer12pt = kSrc + "/configs/data/sf350_hammer_12pt.csv";
/// The sweep file name the in-memory sweeps report.
inline const std::string kSweepName = kSrc + "/configs/sweeps/in_memory_test.yaml";

}  // namespace modaltyre_test
