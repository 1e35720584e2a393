#include "modaltyre/fmu/package.h"

#include <unistd.h>
#include <zip.h>

#include <array>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "modaltyre/contact/tyre_config.h"
#include "modaltyre/contact/tyre_model.h"
#include "modaltyre/core/config_edit.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/core/input_file.h"
#include "modaltyre/fmu/elf_needs.h"
#include "modaltyre/fmu/resources.h"
#include "modaltyre/fmu/tyre_variables.h"
#include "modaltyre/fmu/tyre_wheel.h"
#include "modaltyre/ground/ground_settings.h"
#include "modaltyre/transient/driven_tyre.h"
#include "modaltyre/transient/model.h"

#ifndef MODALTYRE_FMU_INSTALL_RELPATH
#define MODALTYRE_FMU_INSTALL_RELPATH "lib/modaltyre"
#endif

namespace modaltyre::fmu {
namespace {

namespace fs = std::filesystem;

/// Size limits of what is packed: a config, a hammer CSV and the shared library.
constexpr std::uintmax_t kMaxConfigBytes = 16u << 20;
constexpr std::uintmax_t kMaxDataBytes = 256u << 20;
constexpr std::uintmax_t kMaxBinaryBytes = 512u << 20;

/// 64-bit FNV-1a (Fowler-Noll-Vo) over bytes, from a given offset basis.
std::uint64_t fnv1a(const std::string& bytes, std::uint64_t hash) {
  for (unsigned char ch : bytes) {
    hash ^= ch;
    hash *= 0x100000001b3ull;
  }
  return hash;
}

/// A GUID-shaped digest of the packaged model (config and data): the same inputs give the same
/// GUID, another config another one.
std::string digest_guid(const std::string& bytes) {
  const std::uint64_t a = fnv1a(bytes, 0xcbf29ce484222325ull);
  const std::uint64_t b = fnv1a(bytes, 0x84222325cbf29ce4ull ^ a);
  char buf[48];
  std::snprintf(buf, sizeof buf, "{%08x-%04x-%04x-%04x-%012llx}", unsigned(a >> 32),
                unsigned((a >> 16) & 0xffff), unsigned(a & 0xffff), unsigned(b >> 48),
                static_cast<unsigned long long>(b & 0xffffffffffffull));
  return buf;
}

struct Entry {
  std::string name, bytes;
  bool executable = false;
};

/// Writes the archive. libzip writes to a temporary file beside `path` and renames it over
/// `path` in zip_close(), so the output is whole or absent.
void write_zip(const std::string& path, const std::vector<Entry>& entries) {
  int err = 0;
  zip_t* za = zip_open(path.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &err);
  if (!za) {
    zip_error_t e;
    zip_error_init_with_code(&e, err);
    const std::string msg = zip_error_strerror(&e);
    zip_error_fini(&e);
    throw InputError(InputLocation{path, 0, "--output"}, "cannot create the FMU: " + msg);
  }
  auto fail = [&](const std::string& what) {
    const std::string msg = what + ": " + zip_strerror(za);
    zip_discard(za);
    throw InputError(InputLocation{path, 0, "--output"}, "cannot write the FMU: " + msg);
  };
  for (const Entry& e : entries) {
    // The archive copies the buffer at zip_close(); the entries outlive it.
    zip_source_t* src = zip_source_buffer(za, e.bytes.data(), e.bytes.size(), 0);
    if (!src) fail(e.name);
    const zip_int64_t index = zip_file_add(za, e.name.c_str(), src, ZIP_FL_ENC_UTF_8);
    if (index < 0) {
      zip_source_free(src);
      fail(e.name);
    }
    const zip_uint32_t mode = e.executable ? 0100755 : 0100644;
    if (zip_file_set_external_attributes(za, zip_uint64_t(index), 0, ZIP_OPSYS_UNIX, mode << 16) <
        0)
      fail(e.name);
  }
  if (zip_close(za) < 0) fail("closing");
}

}  // namespace

std::string find_fmu_binary() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return "";
  const std::string name = std::string(kModelIdentifier) + ".so";
  for (const fs::path& p :
       {exe.parent_path() / name, exe.parent_path() / ".." / MODALTYRE_FMU_INSTALL_RELPATH / name})
    if (fs::is_regular_file(p, ec)) return fs::weakly_canonical(p, ec).string();
  return "";
}

namespace {

/// The ground the FMU will run, refused here when it cannot (issue 46 item 3), naming the key:
/// a rigid profile (the FMU's road is its road_profile parameter and terrain_height input), and
/// on a soil what the soil transient refuses (tyre.rigid; the Kelvin-Voigt rate term on the 3D
/// patch) or cannot start (its Bekker width's footprint: contact.window_mm, ...).
void check_ground(const transient::TransientModel& model, const std::string& ground_source) {
  const contact::TyreConfig& config = model.tyre.config;
  if (config.ground.model == ground::GroundModel::profile)
    throw InputError(InputLocation{ground_source, 0, "ground.model"},
                     "a profile ground is not packed into the FMU: its road is the "
                     "road_profile parameter (or terrain_height); leave ground: out");
  if (!config.ground.soil()) return;
  if (config.rigid)
    throw InputError(InputLocation{config.source, 0, "tyre.rigid"},
                     "the FMU on a soil runs the flexible tyre (the rigid wheel is traction's)");
  if (config.footprint_3d && config.ground.model == ground::GroundModel::kelvin_voigt &&
      config.ground.kelvin_voigt.eta2_kPa_s > 0)
    throw InputError(InputLocation{ground_source, 0, "ground.kelvin_voigt.eta2_kPa_s"},
                     "the 3D patch models the Kelvin-Voigt soil's elastic law only (docs/soil.md "
                     "section 8.3): set it to 0, or pack a 2D config");
  try {
    const transient::DrivenTyre probe(model);  // Bekker's b on the soil (driven_tyre.h)
  } catch (const ComputationError& e) {
    throw InputError(InputLocation{ground_source, 0, "ground.model"},
                     std::string("the FMU cannot start on this soil: ") + e.what());
  }
}

}  // namespace

PackageResult write_fmu(const PackageOptions& o) {
  // With a soil file the ground.KEY overrides are its own, the rest the config's (as traction).
  std::vector<std::string> tyre_sets, ground_sets;
  for (const std::string& s : o.overrides)
    (!o.ground_path.empty() && s.rfind("ground.", 0) == 0 ? ground_sets : tyre_sets).push_back(s);
  // The config as every command reads it: InputErrors name file, line and key.
  contact::TyreConfig config = contact::load_tyre_config(o.config_path, tyre_sets);
  if (!o.ground_path.empty()) config.ground = ground::load_ground_file(o.ground_path, ground_sets);
  if (o.binary_path.empty())
    throw InputError("the FMU's shared library " + std::string(kModelIdentifier) +
                     ".so was not found beside modaltyre nor in its install folder (build the "
                     "target modaltyre_fmu_binary)");
  const std::string binary = read_input_file(o.binary_path, "the FMU's shared library",
                                             "shared libraries", kMaxBinaryBytes);
  // The model the FMU will build, built once here: a config the transient refuses fails now.
  const transient::TransientModel model =
      transient::build_transient_model(contact::build_tyre_model(config));
  check_ground(model, o.ground_path.empty() ? o.config_path : o.ground_path);

  // The data path is rewritten to the copy in the archive (a --set of it chose the file).
  std::vector<std::string> overrides;
  for (const std::string& s : tyre_sets)
    if (s.rfind("modal.hammer_csv=", 0) != 0) overrides.push_back(s);
  std::vector<Entry> data;
  if (!config.hammer_csv.empty()) {
    const std::string name = "data/" + fs::path(config.hammer_csv).filename().string();
    data.push_back({"resources/" + name,
                    read_input_file(config.hammer_csv, "a CSV file", "CSV files", kMaxDataBytes)});
    overrides.push_back("modal.hammer_csv=" + name);
  }
  const std::string text =
      read_input_file(o.config_path, "a YAML file", "YAML files", kMaxConfigBytes);
  const std::optional<std::string> packed =
      set_keys_in_text(text, o.config_path, overrides, "set by modaltyre fmu");
  if (!packed)
    throw InputError(InputLocation{o.config_path, 0, "modal.hammer_csv"},
                     "cannot rewrite the config's keys in place for the FMU (a value spanning "
                     "lines or a flow mapping?)");

  // A soil file goes beside the config with its overrides applied.
  std::optional<std::string> soil;
  if (!o.ground_path.empty()) {
    const std::string soil_text =
        read_input_file(o.ground_path, "a YAML file", "YAML files", kMaxConfigBytes);
    soil = set_keys_in_text(soil_text, o.ground_path, ground_sets, "set by modaltyre fmu");
    if (!soil)
      throw InputError(InputLocation{o.ground_path, 0, "ground"},
                       "cannot rewrite the soil file's keys in place for the FMU (a value "
                       "spanning lines or a flow mapping?)");
  }

  std::string digest_input = *packed;
  for (const Entry& e : data) digest_input += e.name + '\n' + e.bytes;
  if (soil) digest_input += "\nsoil.yaml\n" + *soil;
  TyreDescriptionInfo info;
  info.tyre_name = config.name;
  info.guid = digest_guid(digest_input);
  info.outer_radius_m = config.outer_radius_m;
  info.friction_coefficient = config.ground.friction_coefficient;
  info.section_height_m = section_height_m(config);
  info.soil = config.ground.soil() ? &config.ground : nullptr;
  info.patch_3d = config.footprint_3d.has_value();

  PackageResult result;
  result.guid = info.guid;
  result.model_description = to_xml(tyre_model_description(info));
  std::vector<Entry> entries;
  entries.push_back({"modelDescription.xml", result.model_description});
  const std::string binary_entry = "binaries/linux64/" + std::string(kModelIdentifier) + ".so";
  entries.push_back({binary_entry, binary, true});
  entries.push_back(
      {"documentation/externalDependencies.txt",
       external_dependencies_text(read_elf_needs(binary, o.binary_path), binary_entry)});
  entries.push_back({"resources/tyre.yaml", *packed});
  if (soil) entries.push_back({"resources/soil.yaml", *soil});
  for (Entry& e : data) entries.push_back(std::move(e));
  entries.push_back({std::string("resources/") + kResourceRecord,
                     resource_record_text(info.guid, "tyre.yaml", soil ? "soil.yaml" : "")});
  write_zip(o.output_path, entries);
  for (const Entry& e : entries) result.entries.push_back(e.name);
  return result;
}

}  // namespace modaltyre::fmu
