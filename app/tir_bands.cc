#include "tir_bands.h"

#include <sstream>

#include "footprint_report.h"
#include "modaltyre/contact/tyre_model.h"

namespace modaltyre::app {
namespace {

/// The coefficients the nominal fit carries, in the .tir's order; VERTICAL_STIFFNESS in N/mm
/// (the unit printed beside the others' dimensionless values).
std::vector<double> coefficients(const tir::TirFit& f) {
  std::vector<double> v = {f.vertical_stiffness_N_m * 1e-3, f.q_fz2, f.q_ra1, f.q_ra2};
  if (f.q_rb1) v.insert(v.end(), {*f.q_rb1, *f.q_rb2});
  if (f.pfz1) v.push_back(*f.pfz1);
  return v;
}

std::vector<std::string> coefficient_names(const tir::TirFit& f) {
  std::vector<std::string> n = {"VERTICAL_STIFFNESS", "Q_FZ2", "Q_RA1", "Q_RA2"};
  if (f.q_rb1) n.insert(n.end(), {"Q_RB1", "Q_RB2"});
  if (f.pfz1) n.push_back("PFZ1");
  return n;
}

std::string unit(const std::string& name) { return name == "VERTICAL_STIFFNESS" ? " N/mm" : ""; }

}  // namespace

TirBands tir_bands(const contact::TyreConfig& config, const tir::TirExportOptions& options,
                   const tir::TirFit& f, const uncertainty::PropagationOptions& propagation) {
  TirBands b;
  b.names = coefficient_names(f);
  // A perturbation that takes the width or the pressure law away is not a band.
  const uncertainty::RowEvaluator refit = [&options](const contact::TyreConfig& c,
                                                     const modal::ModeIdentification& m,
                                                     const std::string&) {
    const tir::TirFit g = tir::fit_tir(contact::build_tyre_model(c, m), options);
    return std::make_pair(coefficient_names(g), coefficients(g));
  };
  b.result = uncertainty::propagate_row(config, contact::config_modes(config), refit, b.names,
                                        coefficients(f), "FNOMIN", "tir export", propagation);
  return b;
}

std::vector<std::string> tir_band_comments(const TirBands& bands) {
  std::vector<std::string> lines;
  const auto& r = bands.result;
  lines.push_back("uncertainty (" + r.method + ", " + std::to_string(r.inputs.size()) +
                  " uncertain inputs, docs/uncertainty.md): std and 95 % band per coefficient");
  const auto& row = r.cases.front().bands;
  for (std::size_t q = 0; q < bands.names.size(); ++q) {
    std::ostringstream s;
    s.precision(5);
    s << "  " << bands.names[q] << unit(bands.names[q]) << ": " << row[q].value << ", std "
      << row[q].std << ", 95 % [" << row[q].p025 << ", " << row[q].p975 << "]";
    lines.push_back(s.str());
  }
  return lines;
}

void print_tir_bands(const TirBands& bands) {
  std::vector<std::string> shown;
  for (const auto& n : bands.names) shown.push_back(n + unit(n));
  print_named_bands(shown, bands.result);
}

}  // namespace modaltyre::app
