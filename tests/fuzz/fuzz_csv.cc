// read_csv() and parse_finite_double() on arbitrary bytes.
//
// Pass 1 accepts every column name the project's readers know (none required), so that the
// fuzzer reaches the data rows of any seed; pass 2 is a strict schema (load_N required, at most
// 8 rows) for the refusals. Every accessor of each table read is then exercised.
#include <string>
#include <vector>

#include "fuzz_support.h"
#include "modaltyre/core/csv.h"

namespace {

using modaltyre::CsvSchema;
using modaltyre::CsvTable;

void touch(const CsvTable& t, const CsvSchema& schema) {
  for (std::size_t r = 0; r < t.rows(); ++r) {
    (void)t.line(r);
    for (const auto& c : t.columns()) {
      bool text = false;
      for (const auto& s : schema.text) text = text || s == c;
      if (text) {
        (void)t.text(r, c).size();
      } else {
        (void)t.number(r, c);
      }
    }
    (void)t.number_or(r, "load_N", 0.0);
  }
}

CsvSchema open_schema() {
  CsvSchema s;
  s.optional = {// hammer data
                "mode", "freq_hz", "damping_ratio", "point", "angle_deg", "radial", "tangential",
                // measurements and sweep output
                "load_N", "pressure_kPa", "hold_s", "speed_kmh", "horizontal_force_N", "branch",
                "surface", "sinking_mm", "length_mm", "width_mm", "rolling_resistance_N",
                "vertical_stiffness_N_mm", "peak_pressure_kPa", "iterations", "status",
                "message",
                // rheology
                "x_mm", "stress_kPa", "t_s", "deflection_mm", "longitudinal_force_N",
                "alpha1_deg", "alpha2_deg", "total_sinking_mm", "elastic_sinking_mm", "layer_mm",
                "speed_m_s"};
  s.text = {"branch", "surface", "status", "message"};
  return s;
}

CsvSchema strict_schema() {
  CsvSchema s;
  s.required = {"load_N"};
  s.optional = {"sinking_mm", "branch"};
  s.text = {"branch"};
  s.max_rows = 8;
  return s;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  static modaltyre::fuzz::ScratchFile file("csv");
  static const CsvSchema open = open_schema();
  static const CsvSchema strict = strict_schema();

  const std::string text = modaltyre::fuzz::as_text(data, size);
  (void)modaltyre::parse_finite_double(text);
  // Every comma-separated piece as a number, as the config and CSV readers do.
  std::size_t pos = 0;
  while (pos <= text.size()) {
    std::size_t end = text.find_first_of(",\n", pos);
    if (end == std::string::npos) end = text.size();
    (void)modaltyre::parse_finite_double(text.substr(pos, end - pos));
    pos = end + 1;
  }

  const std::string& path = file.write(data, size);
  modaltyre::fuzz::guarded([&] { touch(modaltyre::read_csv(path, open), open); });
  modaltyre::fuzz::guarded([&] { touch(modaltyre::read_csv(path, strict), strict); });
  return 0;
}
