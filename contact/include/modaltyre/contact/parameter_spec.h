#pragma once
// The parameter specification: every scalar of the tyre config that a fitter may move, declared
// once with its key, unit, the ranges the fitters search and how they transform it, and how it
// is read from and written into a TyreConfig. Its users:
//   validate  (studies/validation.h)   calibrates the entries with a `calibration` range,
//   discover  (discover/model_fit.h)   fits the entries with a `fit` range,
//   effects   (effects.h)              each effect parameter is an entry (key effects.EFFECT.NAME,
//                                      fit range = the catalogue's [min, max], which is also the
//                                      range the config reader accepts).
// Each entry also states the range a config may give the key (`accepted`), which the config
// reader checks (tyre_config.cc, patch3d_config.cc, effects.cc) and which is wider than either
// search range: a search range is where a fit looks, not what a config may state.
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "modaltyre/contact/tyre_config.h"

namespace modaltyre::contact {

/// How a fitter maps a bounded parameter value v to its search variable u.
enum class SearchTransform {
  log,           ///< u = ln v, unbounded: the range is kept by a penalty (validate's calibration)
  logistic,      ///< v = min + (max - min) sigma(u), sigma(u) = 1 / (1 + e^-u) (discover)
  log_logistic,  ///< ln v = ln min + (ln max - ln min) sigma(u) (discover, ranges >= 100x wide)
};

struct SearchRange {
  double min = 0, max = 0;  ///< in the unit of the key
  SearchTransform transform = SearchTransform::log;
};

/// discover's rule for a bounded search: in logarithms when the range is positive and spans at
/// least a factor of 100, linear otherwise.
SearchRange logistic_search(double min, double max);

/// A closed interval [min, max] in the unit of a key.
struct ValueRange {
  double min = 0, max = 0;
};

struct ParameterSpec {
  std::string key;   ///< dotted config key, e.g. "tread.modulus_MPa"
  std::string unit;  ///< the key's unit ("-" dimensionless), values are in it
  /// The values a config may state, checked by the config reader; nullopt: the reader's own
  /// check (footprint_3d.crown.radius_mm: any positive radius up to 1e6 mm).
  std::optional<ValueRange> accepted;
  /// validate's calibration range (ln-transformed; Levenberg-Marquardt); nullopt: validate does
  /// not calibrate it.
  std::optional<SearchRange> calibration;
  /// discover's fit range (logistic_search); nullopt: discover does not fit it.
  std::optional<SearchRange> fit;
  /// The value in the key's unit, and setting it as the config reader sets the key (InputError
  /// naming the config when the config has no such setting, e.g. a 3D key on a 2D config).
  std::function<double(const TyreConfig&)> get;
  std::function<void(TyreConfig&, double)> set;
};

/// Every parameter: the tyre config's scalars, then each effect's parameters (effect catalogue
/// order).
const std::vector<ParameterSpec>& parameter_catalogue();
/// nullptr when no parameter has that key.
const ParameterSpec* find_parameter(std::string_view key);
/// The range a config may state for `key` (an entry with an `accepted` range; std::logic_error
/// otherwise: a reader asking for a key the specification does not bound is a programming
/// error).
const ValueRange& accepted_range(std::string_view key);

}  // namespace modaltyre::contact
