#pragma once
// The uncertainty bands in the commands' JSON (issue 35): per case
// `uncertainty: {sinking_mm: {std, p025, p975}, contact_length_mm: {...}, ...}` and the
// document's `uncertainty_method`, `uncertainty_check` and `uncertainty_inputs`.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "modaltyre/uncertainty/propagation.h"

namespace modaltyre::report {

/// Adds the bands to the document's `cases` (same order) and the method, check and inputs.
void add_uncertainty_json(nlohmann::json& document, const uncertainty::PropagationResult& r);

/// {name: {value, std, p025, p975}} of one row's bands (names and bands in the same order).
nlohmann::json bands_json(const std::vector<std::string>& names,
                          const std::vector<uncertainty::Band>& bands);

/// Adds only the document's `uncertainty_method`, `_check`, `_inputs` and `_evaluations`.
void add_uncertainty_method_json(nlohmann::json& document, const uncertainty::PropagationResult& r);

/// "14.5 +- 0.4": the value to the digits its 2-sigma half-width supports (two significant
/// digits of the half-width), or the value alone to `plain_decimals` when the width is zero.
std::string plus_minus(double value, double two_sigma, int plain_decimals);

/// "18.9 [15.2, 23.6]": the band's value and its 2.5 and 97.5 % points (the JSON's p025 and
/// p975, which a skewed or mixed band need not hold symmetrically), to the digits its half-width
/// supports (two significant digits of it); a band of zero width prints the value to
/// `plain_decimals` and says "(fixed: no uncertain input moves it)".
std::string band_text(const uncertainty::Band& band, int plain_decimals);

/// The tables' words for band_text's columns.
inline constexpr const char* kBandHeading = "value [2.5 %, 97.5 %] (the JSON's value [p025, p975])";

}  // namespace modaltyre::report
