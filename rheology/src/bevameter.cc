#include "modaltyre/rheology/bevameter.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <set>

#include "modaltyre/core/csv.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/core/number_format.h"
#include "modaltyre/solvers/linear_least_squares.h"

namespace modaltyre::rheology {
namespace {

// Largest values a plate or shear test can hold: beyond them a unit error.
constexpr double kMaxPlateWidth_m = 10, kMaxSinkage_m = 10, kMaxStress_Pa = 1e9;

// Golden-section minimum of f on [a, b] (unimodal); 100 steps shrink the bracket by 1e-21.
double golden_minimum(const std::function<double(double)>& f, double a, double b) {
  const double g = 0.5 * (std::sqrt(5.0) - 1);
  double c = b - g * (b - a), d = a + g * (b - a), fc = f(c), fd = f(d);
  for (int i = 0; i < 100 && b - a > 1e-12 * (std::abs(a) + std::abs(b)); ++i) {
    if (fc < fd) {
      b = d, d = c, fd = fc, c = b - g * (b - a), fc = f(c);
    } else {
      a = c, c = d, fc = fd, d = a + g * (b - a), fd = f(d);
    }
  }
  return 0.5 * (a + b);
}

// The best of a coarse grid, then golden section between its neighbours (the residual of a
// variable projection need not be unimodal over the whole range).
double grid_then_golden(const std::function<double(double)>& f, double lo, double hi, int grid,
                        bool logarithmic) {
  auto at = [&](int k) {
    const double t = double(k) / grid;
    return logarithmic ? lo * std::pow(hi / lo, t) : lo + (hi - lo) * t;
  };
  int best = 0;
  double fbest = 1e300;
  for (int k = 0; k <= grid; ++k) {
    const double v = f(at(k));
    if (v < fbest) fbest = v, best = k;
  }
  return golden_minimum(f, at(std::max(0, best - 1)), at(std::min(grid, best + 1)));
}

// Data that cannot separate the parameters (a singular Jacobian J of the residuals in them) give
// no estimate at all, not a precise one (issue 44: "false precision").
void require_determined(const Eigen::MatrixXd& J, const std::string& path, const std::string& rows,
                        const std::string& parameters, const std::string& remedy) {
  const Eigen::VectorXd sv = Eigen::JacobiSVD<Eigen::MatrixXd>(J).singularValues();
  const double smallest = sv(sv.size() - 1);
  if (!(smallest > 1e-9 * sv(0)))
    throw InputError({path, 0, ""}, rows + " cannot determine " + parameters +
                                        " together (their Jacobian is singular: condition " +
                                        number_text(sv(0) / std::max(smallest, 1e-300)) + "); " +
                                        remedy);
}

// Standard errors sqrt(diag(s^2 (J^T J)^-1)) with s^2 = RSS / (rows - parameters).
Eigen::VectorXd standard_errors(const Eigen::MatrixXd& J, double rss) {
  const double dof = std::max<double>(1, J.rows() - J.cols());
  const Eigen::MatrixXd cov =
      (J.transpose() * J).completeOrthogonalDecomposition().pseudoInverse() * (rss / dof);
  return cov.diagonal().cwiseMax(0).cwiseSqrt();
}

// n outside 0-2 has no physical pressure-sinkage law behind it: the pressure would grow faster
// than the square of the sinkage (a hard layer under the plate, sinkages not counted from the
// surface) or not at all. The data's reason: each plate's own log-log slope.
void add_loading_warnings(BevameterResult& res, const std::vector<PlateRow>& load,
                          PlateShape shape) {
  auto warn = [&](const std::string& w) {
    res.warnings.push_back(w);
    res.report.notes.push_back("warning: " + w);
  };
  if (res.n > 2 || res.n < 0.06) {
    std::map<double, std::pair<const PlateRow*, const PlateRow*>> ends;  // shallowest, deepest
    for (const auto& r : load) {
      auto& e = ends[r.bekker_b_m];
      if (!e.first || r.sinkage_m < e.first->sinkage_m) e.first = &r;
      if (!e.second || r.sinkage_m > e.second->sinkage_m) e.second = &r;
    }
    std::string slopes;
    for (const auto& [b, e] : ends) {
      const double slope = std::log(e.second->pressure_Pa / e.first->pressure_Pa) /
                           std::log(e.second->sinkage_m / e.first->sinkage_m);
      slopes += (slopes.empty() ? "" : "; ") + std::string("b = ") + number_text(b * 1e3) +
                " mm: " + number_text(round_sig(e.first->pressure_Pa * 1e-3, 4)) + " kPa at " +
                number_text(round_sig(e.first->sinkage_m * 1e3, 4)) + " mm to " +
                number_text(round_sig(e.second->pressure_Pa * 1e-3, 4)) + " kPa at " +
                number_text(round_sig(e.second->sinkage_m * 1e3, 4)) + " mm, as z^" +
                number_text(round_sig(slope, 3));
    }
    warn("n = " + number_text(round_sig(res.n, 4)) +
         " is outside 0-2, where no soil's pressure-sinkage law lies (" +
         (res.n > 2 ? "faster than the square of the sinkage: a hard layer under the plate, or "
                      "sinkages not counted from the surface"
                    : "a pressure that does not grow with sinkage") +
         "); the data: " + slopes);
  }
  if (!(res.k_c >= 0))
    warn("k_c = " + number_text(round_sig(res.k_c, 4)) +
         " < 0: the smaller plate carries less pressure at the same sinkage than the larger one; "
         "check the plate sizes (" +
         bekker_b_convention(shape) + ")");
}

// k0 < 0: the unloading slopes rise faster than in proportion to z_max, and the line through
// them reaches zero stiffness at a positive z_max (physically impossible below it).
void add_k0_warning(BevameterResult& res, const std::vector<double>& zmax,
                    const std::vector<double>& ku) {
  std::string cycles;
  for (std::size_t i = 0; i < zmax.size(); ++i)
    cycles += (i ? ", " : "") + number_text(round_sig(ku[i], 4)) + " at " +
              number_text(round_sig(zmax[i] * 1e3, 4)) + " mm";
  const std::string w =
      "k0 = " + number_text(round_sig(res.k0, 4)) +
      " kN/m^3 < 0 (an unloading stiffness below zero for z_max < " +
      number_text(round_sig(-res.k0 / res.Au * 1e3, 4)) +
      " mm): the cycles' slopes k_u [kN/m^3] (" + cycles +
      ") rise faster than in proportion to z_max; a soil file takes k0 >= 0: the fit through "
      "the origin gives k0 = 0, Au = " +
      number_text(round_sig(res.Au_through_origin, 4)) + " kN/m^4";
  res.warnings.push_back(w);
  res.report.notes.push_back("warning: " + w);
}

}  // namespace

std::string bekker_b_convention(PlateShape shape) {
  return shape == PlateShape::circular ? "circular plates: Bekker's b = the plate's radius"
                                       : "rectangular plates: Bekker's b = the plate's width";
}

PlateData read_plate_sinkage_csv(const std::string& path) {
  // The plate's shape from its size column: b is the width of a rectangle, the radius of a
  // circle (Wong, Theory of Ground Vehicles, section 2.4); a diameter would double k_c / b.
  const std::vector<std::string> header = read_csv_header(path);
  auto has = [&](const char* c) {
    return std::find(header.begin(), header.end(), c) != header.end();
  };
  if (has("plate_diameter_mm"))
    throw InputError({path, 0, "plate_diameter_mm"},
                     "Bekker's b of a circular plate is its radius (Wong, Theory of Ground "
                     "Vehicles, section 2.4): give plate_radius_mm (the diameter / 2), or "
                     "plate_width_mm for a rectangular plate");
  if (has("plate_width_mm") && has("plate_radius_mm"))
    throw InputError({path, 0, "plate_radius_mm"},
                     "both plate_width_mm and plate_radius_mm: a file holds one plate shape, "
                     "rectangular (b = the width) or circular (b = the radius)");
  const bool circular = has("plate_radius_mm");
  const char* size_column = circular ? "plate_radius_mm" : "plate_width_mm";
  CsvSchema schema;
  schema.required = {size_column, "sinkage_mm", "pressure_kPa"};
  schema.optional = {"cycle"};
  const CsvTable t = read_csv(path, schema);
  PlateData d;
  d.path = path;
  d.shape = circular ? PlateShape::circular : PlateShape::rectangular;
  for (std::size_t r = 0; r < t.rows(); ++r) {
    PlateRow row;
    row.line = t.line(r);
    row.bekker_b_m = t.number(r, size_column) * 1e-3;
    row.sinkage_m = t.number(r, "sinkage_mm") * 1e-3;
    row.pressure_Pa = t.number(r, "pressure_kPa") * 1e3;
    const double cycle = t.number_or(r, "cycle", 0);
    auto bad = [&](const char* col, const std::string& msg) {
      throw InputError({path, row.line, col}, msg);
    };
    if (!(row.bekker_b_m > 0 && row.bekker_b_m <= kMaxPlateWidth_m))
      bad(size_column, "must be in (0, 10000] mm");
    if (!(row.sinkage_m >= 0 && row.sinkage_m <= kMaxSinkage_m))
      bad("sinkage_mm", "must be in [0, 10000] mm");
    if (!(row.pressure_Pa >= 0 && row.pressure_Pa <= kMaxStress_Pa))
      bad("pressure_kPa", "must be in [0, 1e6] kPa");
    if (!(cycle >= 0 && cycle <= 1000 && cycle == std::floor(cycle)))
      bad("cycle", "must be a whole number in [0, 1000] (0: virgin loading)");
    row.cycle = static_cast<int>(cycle);
    d.rows.push_back(row);
  }
  return d;
}

BevameterResult identify_bevameter(const PlateData& d) {
  // Virgin loading rows with a positive sinkage and pressure carry the Bekker fit.
  const char* size_column = d.shape == PlateShape::circular ? "plate_radius_mm" : "plate_width_mm";
  std::vector<PlateRow> load;
  std::map<double, std::set<double>> sinkages;  // per plate
  for (const auto& r : d.rows) {
    if (r.cycle == 0 && r.sinkage_m > 0 && r.pressure_Pa > 0) {
      load.push_back(r);
      sinkages[r.bekker_b_m].insert(r.sinkage_m);
    }
  }
  if (sinkages.size() < 2)
    throw InputError({d.path, 0, size_column},
                     "bevameter needs loading rows of at least two plate sizes to separate k_c "
                     "from k_phi (got " +
                         std::to_string(sinkages.size()) + ")");
  if (load.size() < 4)
    throw InputError({d.path, 0, ""},
                     "bevameter needs at least four loading rows with sinkage "
                     "and pressure > 0");
  // The curve's shape n shows only in how one plate's pressure grows with its sinkage: a plate
  // pressed to one sinkage only cannot tell n from k (issue 44: "false precision").
  for (const auto& [b, zs] : sinkages)
    if (zs.size() < 2)
      throw InputError({d.path, 0, "sinkage_mm"},
                       "the plate of b = " + number_text(b * 1e3) +
                           " mm has its loading rows at one sinkage (" +
                           number_text(*zs.begin() * 1e3) +
                           " mm): n (how pressure grows with sinkage) cannot be determined; "
                           "measure each plate at two sinkages or more");
  const std::size_t N = load.size();
  // Variable projection: at fixed n, p_i = k_c z^n / b + k_phi z^n is linear; relative residuals.
  auto linear_fit = [&](double n, solvers::LinearFit& fit) {
    Eigen::MatrixXd A(N, 2);
    Eigen::VectorXd y = Eigen::VectorXd::Ones(N);
    for (std::size_t i = 0; i < N; ++i) {
      const double zn = std::pow(load[i].sinkage_m, n) * 1e3 / load[i].pressure_Pa;  // kPa units
      A(i, 0) = zn / load[i].bekker_b_m;
      A(i, 1) = zn;
    }
    fit = solvers::solve_linear_least_squares(A, y);
  };
  auto rss_at = [&](double n) {
    solvers::LinearFit fit;
    linear_fit(n, fit);
    return fit.residuals.squaredNorm();
  };
  const double n = grid_then_golden(rss_at, 0.05, 3.0, 60, false);
  solvers::LinearFit fit;
  linear_fit(n, fit);
  BevameterResult res;
  res.n = n, res.k_c = fit.coef(0), res.k_phi = fit.coef(1);
  // Full Jacobian of the relative residuals in (n, k_c, k_phi).
  Eigen::MatrixXd J(N, 3);
  double rss = 0, rss_abs = 0;
  for (std::size_t i = 0; i < N; ++i) {
    const double z = load[i].sinkage_m, b = load[i].bekker_b_m, p = load[i].pressure_Pa;
    const double k = res.k_c / b + res.k_phi, zn = std::pow(z, n);
    const double model_Pa = k * zn * 1e3;
    J(i, 0) = model_Pa * std::log(z) / p;
    J(i, 1) = zn * 1e3 / b / p;
    J(i, 2) = zn * 1e3 / p;
    rss += std::pow(model_Pa / p - 1, 2);
    rss_abs += std::pow(model_Pa - p, 2);
  }
  require_determined(J, d.path, "the loading rows", "n, k_c and k_phi",
                     "measure more sinkages and plate sizes");
  const Eigen::VectorXd se = standard_errors(J, rss);
  res.n_se = se(0), res.k_c_se = se(1), res.k_phi_se = se(2);
  auto& rep = res.report;
  rep.method = "bevameter";
  rep.rows = static_cast<int>(N);
  rep.residual_rms = std::sqrt(rss_abs / N) * 1e-3;
  rep.residual_unit = "kPa";
  rep.parameters = {{"n", res.n, "-", res.n_se},
                    {"k_c", res.k_c, "kN/m^(n+1)", res.k_c_se},
                    {"k_phi", res.k_phi, "kN/m^(n+2)", res.k_phi_se}};
  rep.notes.push_back("Bekker p = (k_c/b + k_phi) z^n over the virgin loading rows (cycle 0) of " +
                      std::to_string(sinkages.size()) + " plate sizes (" +
                      bekker_b_convention(d.shape) +
                      "); n by golden section, k_c and k_phi by linear least squares, on "
                      "relative residuals");
  add_loading_warnings(res, load, d.shape);

  // Unloading-reloading cycles: slope k_u of each, then k_u = k0 + Au z_max.
  std::map<int, std::vector<PlateRow>> cycles;
  for (const auto& r : d.rows)
    if (r.cycle > 0) cycles[r.cycle].push_back(r);
  if (!cycles.empty()) {
    std::vector<double> zmax, ku;
    for (const auto& [id, rows] : cycles) {
      if (rows.size() < 2)
        throw InputError({d.path, rows.front().line, "cycle"},
                         "unloading cycle " + std::to_string(id) + " needs at least two rows");
      Eigen::MatrixXd A(rows.size(), 2);
      Eigen::VectorXd y(rows.size());
      double top = 0;
      for (std::size_t i = 0; i < rows.size(); ++i) {
        A(i, 0) = 1, A(i, 1) = rows[i].sinkage_m, y(i) = rows[i].pressure_Pa * 1e-3;
        top = std::max(top, rows[i].sinkage_m);
      }
      double lo = 1e300;
      for (const auto& r : rows) lo = std::min(lo, r.sinkage_m);
      if (!(top > lo))
        throw InputError({d.path, rows.front().line, "sinkage_mm"},
                         "unloading cycle " + std::to_string(id) + " has one sinkage only");
      const solvers::LinearFit line = solvers::solve_linear_least_squares(A, y);
      zmax.push_back(top);
      ku.push_back(line.coef(1));  // kPa/m = kN/m^3
    }
    res.has_unloading = true;
    std::set<double> distinct(zmax.begin(), zmax.end());
    double zz = 0, zk = 0;
    for (std::size_t i = 0; i < zmax.size(); ++i) zz += zmax[i] * zmax[i], zk += zmax[i] * ku[i];
    res.Au_through_origin = zk / zz;
    if (distinct.size() >= 2) {
      Eigen::MatrixXd A(zmax.size(), 2);
      Eigen::VectorXd y(zmax.size());
      for (std::size_t i = 0; i < zmax.size(); ++i) A(i, 0) = 1, A(i, 1) = zmax[i], y(i) = ku[i];
      const solvers::LinearFit w = solvers::solve_linear_least_squares(A, y);
      res.k0 = w.coef(0), res.k0_se = w.std_error(0);
      res.Au = w.coef(1), res.Au_se = w.std_error(1);
      rep.notes.push_back("Wong's k_u = k0 + Au z_max over " + std::to_string(zmax.size()) +
                          " unloading cycles (slope of each cycle's rows)");
      if (res.k0 < 0) add_k0_warning(res, zmax, ku);
    } else {
      double mean = 0;
      for (double v : ku) mean += v;
      res.k0 = mean / ku.size(), res.Au = 0;
      rep.notes.push_back("one z_max among the cycles: k0 = their mean slope, Au = 0");
    }
    rep.parameters.push_back({"k0", res.k0, "kN/m^3", res.k0_se});
    rep.parameters.push_back({"Au", res.Au, "kN/m^4", res.Au_se});
  }
  return res;
}

ShearData read_shear_csv(const std::string& path) {
  CsvSchema schema;
  schema.required = {"normal_stress_kPa", "shear_displacement_mm", "shear_stress_kPa"};
  const CsvTable t = read_csv(path, schema);
  ShearData d;
  d.path = path;
  for (std::size_t r = 0; r < t.rows(); ++r) {
    ShearRow row;
    row.line = t.line(r);
    row.normal_stress_Pa = t.number(r, "normal_stress_kPa") * 1e3;
    row.displacement_m = t.number(r, "shear_displacement_mm") * 1e-3;
    row.shear_stress_Pa = t.number(r, "shear_stress_kPa") * 1e3;
    auto bad = [&](const char* col, const std::string& msg) {
      throw InputError({path, row.line, col}, msg);
    };
    if (!(row.normal_stress_Pa >= 0 && row.normal_stress_Pa <= kMaxStress_Pa))
      bad("normal_stress_kPa", "must be in [0, 1e6] kPa");
    if (!(row.displacement_m >= 0 && row.displacement_m <= kMaxSinkage_m))
      bad("shear_displacement_mm", "must be in [0, 10000] mm");
    if (!(row.shear_stress_Pa >= 0 && row.shear_stress_Pa <= kMaxStress_Pa))
      bad("shear_stress_kPa", "must be in [0, 1e6] kPa");
    d.rows.push_back(row);
  }
  return d;
}

ShearResult identify_shear(const ShearData& d) {
  std::vector<ShearRow> rows;
  std::map<double, double> peak;  // largest shear stress per normal stress
  for (const auto& r : d.rows) {
    if (!(r.displacement_m > 0)) continue;  // j = 0 carries no information on K
    rows.push_back(r);
    peak[r.normal_stress_Pa] = std::max(peak[r.normal_stress_Pa], r.shear_stress_Pa);
  }
  if (peak.size() < 2)
    throw InputError({d.path, 0, "normal_stress_kPa"},
                     "shear needs rows at two or more normal stresses to separate c from phi");
  if (rows.size() < 5)
    throw InputError({d.path, 0, ""}, "shear needs at least five rows with displacement > 0");
  for (const auto& [sigma, top] : peak)
    if (!(top > 0))
      throw InputError({d.path, 0, "shear_stress_kPa"},
                       "every normal stress needs a shear stress > 0");
  const std::size_t N = rows.size();
  auto weight = [&](const ShearRow& r) { return 1.0 / peak[r.normal_stress_Pa]; };
  double jmax = 0;
  for (const auto& r : rows) jmax = std::max(jmax, r.displacement_m);
  auto linear_fit = [&](double K, solvers::LinearFit& fit) {
    Eigen::MatrixXd A(N, 2);
    Eigen::VectorXd y(N);
    for (std::size_t i = 0; i < N; ++i) {
      const double g = -std::expm1(-rows[i].displacement_m / K), w = weight(rows[i]);
      A(i, 0) = w * g, A(i, 1) = w * g * rows[i].normal_stress_Pa;
      y(i) = w * rows[i].shear_stress_Pa;
    }
    fit = solvers::solve_linear_least_squares(A, y);
  };
  auto rss_at = [&](double K) {
    solvers::LinearFit fit;
    linear_fit(K, fit);
    return fit.residuals.squaredNorm();
  };
  const double K = grid_then_golden(rss_at, 1e-3 * jmax, 10 * jmax, 80, true);
  solvers::LinearFit fit;
  linear_fit(K, fit);
  const double c = fit.coef(0), tphi = fit.coef(1);
  Eigen::MatrixXd J(N, 3);
  double rss = 0, rss_abs = 0;
  for (std::size_t i = 0; i < N; ++i) {
    const double j = rows[i].displacement_m, s = rows[i].normal_stress_Pa, w = weight(rows[i]);
    const double e = std::exp(-j / K), g = 1 - e, strength = c + s * tphi;
    J(i, 0) = w * g;
    J(i, 1) = w * g * s;
    J(i, 2) = w * strength * (-e * j / (K * K));
    const double r = strength * g - rows[i].shear_stress_Pa;
    rss += std::pow(w * r, 2), rss_abs += r * r;
  }
  require_determined(J, d.path, "the rows", "c, phi and K",
                     "measure each normal stress at several displacements");
  const Eigen::VectorXd se = standard_errors(J, rss);
  ShearResult res;
  res.cohesion_kPa = c * 1e-3, res.cohesion_se = se(0) * 1e-3;
  res.friction_angle_deg = std::atan(tphi) * 180 / M_PI;
  res.friction_angle_se = se(1) / (1 + tphi * tphi) * 180 / M_PI;  // d atan = d tan / (1 + tan^2)
  res.K_mm = K * 1e3, res.K_se = se(2) * 1e3;
  auto& rep = res.report;
  rep.method = "shear";
  rep.rows = static_cast<int>(N);
  rep.residual_rms = std::sqrt(rss_abs / N) * 1e-3;
  rep.residual_unit = "kPa";
  rep.parameters = {{"cohesion_kPa", res.cohesion_kPa, "kPa", res.cohesion_se},
                    {"friction_angle_deg", res.friction_angle_deg, "deg", res.friction_angle_se},
                    {"shear_modulus_K_mm", res.K_mm, "mm", res.K_se}};
  rep.notes.push_back("Janosi-Hanamoto tau = (c + sigma tan phi)(1 - exp(-j/K)) over " +
                      std::to_string(peak.size()) +
                      " normal stresses; K by golden section, c "
                      "and tan phi by linear least squares, residuals relative to each normal "
                      "stress's largest shear stress");
  if (!(c >= 0)) rep.notes.push_back("warning: c < 0: check the data");
  return res;
}

}  // namespace modaltyre::rheology
