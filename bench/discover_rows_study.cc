// The check of discover's many-row approximations (docs/discover.md, "Many rows"): the same
// test matrices run exactly (every fit searched on all rows, every fold re-fitted) and with the
// approximations (search on a spread subset, Gauss-Newton finish, one-step folds); prints the
// conclusions, every candidate's Delta BIC and cross-validated RMS, the named parameters and
// the footprints each run solved. Takes a few minutes (the exact runs).
//   build/bench/discover_rows_study
#include <malloc.h>

#include <chrono>
#include <cstdio>
#include <map>
#include <string>

#include "modaltyre/discover/discover.h"
#include "test_matrix.h"

using namespace modaltyre;

namespace {

struct Run {
  discover::DiscoverReport report;
  double seconds = 0;
};

Run run(const contact::TyreConfig& cfg, const studies::MeasurementSet& data, int exact_rows) {
  discover::DiscoverOptions opt;
  opt.fit.exact_rows = exact_rows;
  const auto t0 = std::chrono::steady_clock::now();
  Run r{discover::discover(cfg, data, opt), 0};
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

void compare(const std::string& title, const contact::TyreConfig& cfg,
             const studies::MeasurementSet& data) {
  const Run exact = run(cfg, data, 1000000);
  const Run approx = run(cfg, data, 64);
  std::printf("\n== %s: %zu rows\n", title.c_str(), data.rows.size());
  std::printf("exact:       %s\n  %ld footprints, %.1f s\n", exact.report.conclusion.c_str(),
              exact.report.footprints, exact.seconds);
  std::printf("approximate: %s\n  %ld footprints, %.1f s\n", approx.report.conclusion.c_str(),
              approx.report.footprints, approx.seconds);
  std::printf("%-6s %-20s %12s %12s %12s %12s\n", "round", "candidate", "dBIC exact", "dBIC appr.",
              "CV% exact", "CV% appr.");
  for (std::size_t k = 0; k < exact.report.rounds.size() && k < approx.report.rounds.size(); ++k) {
    std::map<std::string, discover::CandidateScore> other;
    for (const auto& c : approx.report.rounds[k]) other[c.name] = c;
    for (const auto& c : exact.report.rounds[k]) {
      if (!c.testable) continue;
      const auto& a = other.at(c.name);
      std::printf("%-6zu %-20s %12.2f %12.2f %12.3f %12.3f\n", k + 1, c.name.c_str(), c.delta_bic,
                  a.delta_bic, 100 * c.cv_rms_after, 100 * a.cv_rms_after);
    }
  }
  for (std::size_t i = 0; i < exact.report.effects.size() && i < approx.report.effects.size();
       ++i) {
    for (const auto& [key, value] : exact.report.effects[i].parameters) {
      std::printf("%-45s exact %.4g +- %.3g   approximate %.4g +- %.3g\n", key.c_str(), value,
                  exact.report.effects[i].standard_errors.at(key),
                  approx.report.effects[i].parameters.at(key),
                  approx.report.effects[i].standard_errors.at(key));
    }
  }
}

}  // namespace

int main() {
  mallopt(M_MMAP_THRESHOLD, 32 << 20);  // as the CLI (app/main.cc)
  mallopt(M_TRIM_THRESHOLD, 256 << 20);
  const std::string path = std::string(MODALTYRE_SOURCE_DIR) + "/configs/sf350_2d_table3.yaml";
  const auto cfg = contact::load_tyre_config(path);
  const auto mesh = contact::load_tyre_config(path, {"contact.unit_length_mm=2"});
  compare("creeping tread", cfg, bench::test_matrix(mesh, 10, 2, 5, false, 5));
  compare("creeping tread and pressure", cfg, bench::test_matrix(mesh, 10, 3, 5, true, 7));
  return 0;
}
