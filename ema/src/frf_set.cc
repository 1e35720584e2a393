#include "modaltyre/ema/frf_set.h"

#include <cmath>
#include <map>
#include <utility>

#include "modaltyre/core/csv.h"
#include "modaltyre/core/errors.h"

namespace modaltyre::ema {

const char* to_string(FrfType type) {
  switch (type) {
    case FrfType::receptance:
      return "receptance";
    case FrfType::mobility:
      return "mobility";
    case FrfType::accelerance:
      return "accelerance";
  }
  return "?";
}

FrfType parse_frf_type(const std::string& text, const std::string& where) {
  for (FrfType t : {FrfType::accelerance, FrfType::mobility, FrfType::receptance}) {
    if (text == to_string(t)) return t;
  }
  throw InputError({where, 0, ""}, "unknown FRF type '" + printable(text) +
                                       "'; expected accelerance, mobility or receptance");
}

const char* to_string(Direction d) { return d == Direction::radial ? "radial" : "tangential"; }

std::string to_string(const Dof& d) {
  return "point " + std::to_string(d.point) + " " + to_string(d.dir);
}

FrfSet convert_frf_type(const FrfSet& set, FrfType to) {
  FrfSet out = set;
  out.type = to;
  const int power = static_cast<int>(to) - static_cast<int>(set.type);
  if (power == 0) return out;
  constexpr double kTwoPi = 6.283185307179586;
  for (std::size_t f = 0; f < set.freq_hz.size(); ++f) {
    if (power < 0 && set.freq_hz[f] <= 0) {
      throw InputError({set.path, set.channels.empty() ? 0 : set.channels.front().line, "freq_hz"},
                       std::string("a line at 0 Hz cannot be converted from ") +
                           to_string(set.type) + " to " + to_string(to) +
                           " (division by j omega); leave it out of the band");
    }
    const std::complex<double> jw(0.0, kTwoPi * set.freq_hz[f]);
    const std::complex<double> factor = std::pow(jw, power);
    for (auto& c : out.channels) c.values[f] *= factor;
  }
  return out;
}

void check_frf_set(const FrfSet& set, const FrfLimits& limits) {
  if (set.channels.empty()) throw InputError({set.path, 0, ""}, "contains no FRF");
  if (set.channels.size() > limits.max_channels) {
    throw InputError({set.path, set.channels[limits.max_channels].line, ""},
                     "more than " + std::to_string(limits.max_channels) + " FRFs; refusing");
  }
  const std::size_t n = set.freq_hz.size();
  if (n < 2) {
    throw InputError({set.path, set.channels.front().line, "freq_hz"},
                     "an FRF needs at least 2 spectral lines, got " + std::to_string(n));
  }
  if (n > limits.max_lines || n * set.channels.size() > limits.max_values) {
    throw InputError({set.path, set.channels.front().line, "freq_hz"},
                     std::to_string(set.channels.size()) + " FRFs of " + std::to_string(n) +
                         " lines exceed the limits (" + std::to_string(limits.max_lines) +
                         " lines, " + std::to_string(limits.max_values) + " values)");
  }
  for (std::size_t f = 0; f < n; ++f) {
    // Up to 1e5 Hz, the hammer data's limit: a tyre's modes lie below a few kHz.
    if (!std::isfinite(set.freq_hz[f]) || set.freq_hz[f] < 0 || set.freq_hz[f] > 1e5 ||
        (f > 0 && !(set.freq_hz[f] > set.freq_hz[f - 1]))) {
      throw InputError({set.path, set.channels.front().line, "freq_hz"},
                       "frequencies must be in [0, 1e5] Hz and strictly increasing (line " +
                           std::to_string(f + 1) + " of the FRF)");
    }
  }
  std::map<std::pair<std::pair<int, int>, std::pair<int, int>>, int> seen;
  for (const auto& c : set.channels) {
    const auto key = std::make_pair(std::make_pair(c.response.point, int(c.response.dir)),
                                    std::make_pair(c.reference.point, int(c.reference.dir)));
    if (auto [it, fresh] = seen.emplace(key, c.line); !fresh) {
      throw InputError({set.path, c.line, ""}, "second FRF of response " + to_string(c.response) +
                                                   " and reference " + to_string(c.reference) +
                                                   " (first at line " + std::to_string(it->second) +
                                                   ")");
    }
    if (c.values.size() != n) {
      throw InputError({set.path, c.line, "freq_hz"}, "has " + std::to_string(c.values.size()) +
                                                          " lines, the first FRF has " +
                                                          std::to_string(n));
    }
    for (const auto& v : c.values) {
      if (!std::isfinite(v.real()) || !std::isfinite(v.imag())) {
        throw InputError({set.path, c.line, ""}, "non-finite FRF value");
      }
      // Tyre FRFs are ~1e-6 m/N (receptance) to ~1e2 (m/s^2)/N; 1e12 is a unit error, and
      // converting it by (2 pi f)^2 must stay finite.
      if (std::abs(v) > 1e12) {
        throw InputError({set.path, c.line, ""}, "FRF value beyond 1e12 in magnitude");
      }
    }
  }
}

}  // namespace modaltyre::ema
