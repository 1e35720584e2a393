#pragma once
// `modaltyre fmu CONFIG --output TYRE.fmu`: an FMI 2.0 co-simulation FMU of the transient tyre,
// a zip archive (libzip, Debian's libzip-dev, BSD-3-Clause) that holds everything the shared
// library needs and nothing that points back to the build tree:
//
//   modelDescription.xml                 the description (model_description.h, tyre_variables.h)
//   binaries/linux64/ModalTyre.so        the FMI functions with the project's libraries linked
//                                        in statically (fmu/CMakeLists.txt)
//   documentation/externalDependencies.txt  what the library needs outside the FMU (glibc and
//                                        its version), read from its ELF file (elf_needs.h)
//   resources/tyre.yaml                  the config, --set overrides applied, comments kept, its
//                                        data paths rewritten to the copies beside it
//   resources/data/<hammer CSV>          the hammer data the config names (modal.hammer_csv)
//   resources/soil.yaml                  with --ground: the soil file, its overrides applied
//   resources/fmu.yaml                   the GUID, the config's and the soil file's names,
//                                        read by fmi2Instantiate (resources.h)
#include <string>
#include <vector>

namespace modaltyre::fmu {

struct PackageOptions {
  std::string config_path;
  /// --set key=value, applied to the packaged config (with a ground_path: ground.KEY to the
  /// soil file, as `traction --ground` takes them)
  std::vector<std::string> overrides;
  std::string ground_path;  ///< --ground SOIL.yaml: the soil the tyre runs on ("" : the config's)
  std::string output_path;  ///< the .fmu to write (whole or not at all)
  std::string binary_path;  ///< the built ModalTyre.so
};

struct PackageResult {
  std::string guid;
  std::vector<std::string> entries;  ///< archive members, in the order written
  std::string model_description;     ///< the XML written
};

/// Writes the FMU. InputError for a bad config (file, line, key), a missing binary or an output
/// that cannot be written; ComputationError when the transient model cannot be built.
PackageResult write_fmu(const PackageOptions& options);

/// Where `modaltyre fmu` looks for ModalTyre.so: beside the running executable (the build tree)
/// and in its install folder (../<libdir>/modaltyre). The first that exists, else "".
std::string find_fmu_binary();

}  // namespace modaltyre::fmu
