#include "modaltyre/ema/frf_csv.h"

#include <cmath>
#include <map>
#include <tuple>

#include "modaltyre/core/csv.h"
#include "modaltyre/core/errors.h"

namespace modaltyre::ema {
namespace {

int point_at(const CsvTable& t, std::size_t row, const std::string& col) {
  const double v = t.number(row, col);
  if (v != std::floor(v) || v < 1 || v > kMaxPointNumber) {
    throw InputError({t.path(), t.line(row), col},
                     "must be a whole point number from 1 to " + std::to_string(kMaxPointNumber));
  }
  return static_cast<int>(v);
}

Direction dir_at(const CsvTable& t, std::size_t row, const std::string& col) {
  const std::string& s = t.text(row, col);
  if (s == "radial") return Direction::radial;
  if (s == "tangential") return Direction::tangential;
  throw InputError({t.path(), t.line(row), col},
                   "'" + printable(s) + "' is not a direction; expected radial or tangential");
}

// Two grids agree when their lines differ by less than a part in 1e6 of the line's frequency
// (CSV text rounding), or 1e-9 Hz at 0 Hz.
bool same_frequency(double a, double b) { return std::abs(a - b) <= 1e-6 * std::abs(a) + 1e-9; }

}  // namespace

FrfSet read_frf_csv(const std::string& path, FrfType type, const FrfLimits& limits) {
  CsvSchema schema;
  schema.required = {
      "response_point", "response_dir", "reference_point", "reference_dir", "freq_hz", "re", "im"};
  schema.text = {"response_dir", "reference_dir"};
  schema.max_bytes = limits.max_bytes;
  schema.max_rows = limits.max_values;
  const CsvTable t = read_csv(path, schema);

  FrfSet set;
  set.path = path;
  set.type = type;
  using Key = std::tuple<int, int, int, int>;
  std::map<Key, std::size_t> index;  // DOF pair -> channel
  std::vector<std::vector<double>> freqs;
  for (std::size_t r = 0; r < t.rows(); ++r) {
    const Dof resp{point_at(t, r, "response_point"), dir_at(t, r, "response_dir")};
    const Dof ref{point_at(t, r, "reference_point"), dir_at(t, r, "reference_dir")};
    const double f = t.number(r, "freq_hz");
    if (f < 0) throw InputError({path, t.line(r), "freq_hz"}, "frequency must be >= 0 Hz");
    const Key key{resp.point, int(resp.dir), ref.point, int(ref.dir)};
    auto [it, fresh] = index.try_emplace(key, set.channels.size());
    if (fresh) {
      if (set.channels.size() >= limits.max_channels) {
        throw InputError({path, t.line(r), "response_point"},
                         "more than " + std::to_string(limits.max_channels) + " FRFs; refusing");
      }
      set.channels.push_back({resp, ref, {}, t.line(r)});
      freqs.emplace_back();
    }
    auto& ch = set.channels[it->second];
    auto& fs = freqs[it->second];
    if (!fs.empty() && !(f > fs.back())) {
      throw InputError({path, t.line(r), "freq_hz"},
                       "frequencies of the FRF of response " + to_string(resp) + " and reference " +
                           to_string(ref) + " must increase (previous row of this FRF: " +
                           std::to_string(fs.back()) + " Hz)");
    }
    const auto& first = freqs.front();
    const std::size_t k = fs.size();
    if (it->second > 0 && (k >= first.size() || !same_frequency(first[k], f))) {
      throw InputError({path, t.line(r), "freq_hz"},
                       "line " + std::to_string(k + 1) + " of this FRF is at " + std::to_string(f) +
                           " Hz; the first FRF (line " + std::to_string(set.channels.front().line) +
                           ") has " +
                           (k < first.size() ? std::to_string(first[k]) + " Hz there"
                                             : "only " + std::to_string(first.size()) + " lines") +
                           "; every FRF needs the same frequencies");
    }
    fs.push_back(f);
    ch.values.emplace_back(t.number(r, "re"), t.number(r, "im"));
  }
  if (!set.channels.empty()) set.freq_hz = freqs.front();
  for (std::size_t c = 1; c < set.channels.size(); ++c) {
    if (freqs[c].size() != set.freq_hz.size()) {
      throw InputError({path, set.channels[c].line, "freq_hz"},
                       "the FRF starting here has " + std::to_string(freqs[c].size()) +
                           " lines, the first FRF has " + std::to_string(set.freq_hz.size()));
    }
  }
  check_frf_set(set, limits);
  return set;
}

}  // namespace modaltyre::ema
