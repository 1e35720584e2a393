#pragma once
// The FMU's resources folder as fmi2Instantiate sees it: the location URI the host passes
// (file:///.../resources or a plain path), the GUID written at packaging, the tyre config.
#include <string>

namespace modaltyre::fmu {

/// File name of the small record beside the config (guid, config file name).
inline constexpr const char* kResourceRecord = "fmu.yaml";

/// A resource location URI as hosts pass it ("file:///abs/path", "file:/abs/path",
/// "file://localhost/abs/path", with %XX escapes; a plain path is taken as it is) to a local
/// folder path. InputError for another scheme or a malformed escape.
std::string resource_folder_from_uri(const std::string& uri);

struct ResourceRecord {
  std::string guid;
  std::string config_path;  ///< absolute: the folder + the config's name
  std::string ground_path;  ///< a soil file packed with --ground (folder + name), else ""
};

/// Reads <folder>/fmu.yaml; InputError (file, line, key) if it is missing or malformed.
ResourceRecord read_resource_record(const std::string& folder);

/// The record's text (YAML) for a GUID, a config file name and a soil file name ("": none).
std::string resource_record_text(const std::string& guid, const std::string& config_name,
                                 const std::string& ground_name = "");

}  // namespace modaltyre::fmu
