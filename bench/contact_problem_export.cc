// Exports one footprint contact problem (compliance C, initial gaps s) together with this
// project's solution and its median solve time, for bench/compare_nnls.py.
//   contact_problem_export M FILE [REPEATS]
// File layout (little-endian): int64 m; m*m doubles C (column-major); m doubles s;
// m doubles f (solution); double delta (sinking); double median solve time [s].
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "modaltyre/contact/footprint.h"
#include "modaltyre/solvers/unilateral_contact.h"

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: contact_problem_export M FILE [REPEATS]\n");
    return 2;
  }
  const int m_target = std::atoi(argv[1]);
  const int repeats = argc > 3 ? std::max(1, std::atoi(argv[3])) : 5;
  if (m_target < 10) return 2;
  using namespace modaltyre;
  const std::string config = std::string(MODALTYRE_SOURCE_DIR) + "/configs/sf350_2d_table3.yaml";
  // A 180 mm window holds the 5478 N patch (about 124 mm) with margin.
  const auto model = contact::build_tyre_model(contact::load_tyre_config(
      config, {"contact.window_mm=180", "contact.unit_length_mm=" + std::to_string(180.0 / m_target)}));
  solvers::ContactProblem p;
  p.compliance = model.vertical_compliance;
  p.initial_gap = model.sag;
  p.load_N = 5478;
  std::vector<double> times;
  solvers::ContactSolution sol;
  for (int r = 0; r < repeats; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    sol = solvers::solve_unilateral_contact(p);
    times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  if (!sol.converged()) {
    std::fprintf(stderr, "no convergence: %s\n", sol.message.c_str());
    return 1;
  }
  std::sort(times.begin(), times.end());
  const double median = times[times.size() / 2];
  std::ofstream out(argv[2], std::ios::binary);
  const std::int64_t m = model.candidates();
  out.write(reinterpret_cast<const char*>(&m), sizeof m);
  out.write(reinterpret_cast<const char*>(p.compliance.data()), sizeof(double) * m * m);
  out.write(reinterpret_cast<const char*>(p.initial_gap.data()), sizeof(double) * m);
  out.write(reinterpret_cast<const char*>(sol.force.data()), sizeof(double) * m);
  out.write(reinterpret_cast<const char*>(&sol.approach_m), sizeof(double));
  out.write(reinterpret_cast<const char*>(&median), sizeof(double));
  return out ? 0 : 1;
}
