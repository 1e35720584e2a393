#include "modaltyre/fmu/resources.h"

#include <filesystem>

#include "modaltyre/core/config_tree.h"
#include "modaltyre/core/errors.h"

namespace modaltyre::fmu {

std::string resource_folder_from_uri(const std::string& uri) {
  std::string path = uri;
  if (uri.rfind("file:", 0) == 0) {
    path = uri.substr(5);
    // file:///abs, file://localhost/abs, file:/abs (RFC 8089 forms hosts use).
    if (path.rfind("//", 0) == 0) {
      const std::size_t slash = path.find('/', 2);
      const std::string host =
          path.substr(2, slash == std::string::npos ? std::string::npos : slash - 2);
      if (!(host.empty() || host == "localhost"))
        throw InputError("resource location '" + uri + "' names a remote host");
      path = slash == std::string::npos ? "/" : path.substr(slash);
    }
    std::string decoded;
    for (std::size_t i = 0; i < path.size(); ++i) {
      if (path[i] != '%') {
        decoded += path[i];
        continue;
      }
      auto hex = [&](char ch) -> int {
        if (ch >= '0' && ch <= '9') return ch - '0';
        if (ch >= 'a' && ch <= 'f') return ch - 'a' + 10;
        if (ch >= 'A' && ch <= 'F') return ch - 'A' + 10;
        return -1;
      };
      if (i + 2 >= path.size() || hex(path[i + 1]) < 0 || hex(path[i + 2]) < 0)
        throw InputError("resource location '" + uri + "' has a malformed %-escape");
      decoded += static_cast<char>(hex(path[i + 1]) * 16 + hex(path[i + 2]));
      i += 2;
    }
    path = decoded;
  } else if (uri.find("://") != std::string::npos) {
    throw InputError("resource location '" + uri + "' is not a file: URI");
  }
  if (path.empty()) throw InputError("the resource location is empty");
  return path;
}

ResourceRecord read_resource_record(const std::string& folder) {
  const std::filesystem::path file = std::filesystem::path(folder) / kResourceRecord;
  const ConfigTree tree = ConfigTree::load(file.string());
  ConfigSection root = tree.root();
  ResourceRecord r;
  r.guid = root.text("guid", "");
  if (r.guid.empty()) root.fail("guid", "the FMU's GUID is missing");
  const std::string config = root.text("config", "");
  if (config.empty()) root.fail("config", "the config's file name is missing");
  const std::string ground = root.text("ground", "");
  tree.reject_unknown_keys();
  r.config_path = (std::filesystem::path(folder) / config).string();
  if (!ground.empty()) r.ground_path = (std::filesystem::path(folder) / ground).string();
  return r;
}

std::string resource_record_text(const std::string& guid, const std::string& config_name,
                                 const std::string& ground_name) {
  std::string text =
      "# Written by modaltyre fmu: the FMU's GUID (checked by fmi2Instantiate), its tyre config "
      "and its soil file (modaltyre fmu --ground).\nguid: \"" +
      guid + "\"\nconfig: \"" + config_name + "\"\n";
  if (!ground_name.empty()) text += "ground: \"" + ground_name + "\"\n";
  return text;
}

}  // namespace modaltyre::fmu
