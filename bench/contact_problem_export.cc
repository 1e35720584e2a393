// Exports one footprint contact problem (compliance C, initial gaps s) together with this
// project's solutions and their median solve times, for bench/compare_nnls.py: the solver on
// the exported dense matrix, and the footprint's own solve (the matrix-free Toeplitz operator of
// the contact block, FFT products, what `modaltyre footprint` runs).
//   contact_problem_export M FILE [REPEATS]
// File layout (little-endian): int64 m; m*m doubles C (column-major); m doubles s;
// m doubles f (dense solution); double delta (sinking); double median solve time [s];
// m doubles f, double delta, double median time [s] of the footprint's solve.
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "modaltyre/contact/footprint.h"
#include "modaltyre/solvers/instruction_set.h"
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
  // The instruction set the solves ran (compare_nnls.py reports it with the times).
  std::printf("instruction_set: %s\n", solvers::instruction_set_label().c_str());
  const std::string config = std::string(MODALTYRE_SOURCE_DIR) + "/configs/sf350_2d_table3.yaml";
  // A 180 mm window holds the 5478 N patch (about 124 mm) with margin.
  const auto model = contact::build_tyre_model(contact::load_tyre_config(
      config,
      {"contact.window_mm=180", "contact.unit_length_mm=" + std::to_string(180.0 / m_target)}));
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
  if (!sol.ok()) {
    std::fprintf(stderr, "no convergence: %s\n", sol.message.c_str());
    return 1;
  }
  std::sort(times.begin(), times.end());
  const double median = times[times.size() / 2];
  // The footprint's own solve of the same load case (matrix-free, warm nothing).
  std::vector<double> mf_times;
  contact::FootprintResult fr;
  for (int r = 0; r < repeats; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    fr = contact::solve_footprint(model, contact::LoadCase{p.load_N, 0});
    mf_times.push_back(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  if (!fr.ok()) {
    std::fprintf(stderr, "footprint solve did not converge: %s\n", fr.message.c_str());
    return 1;
  }
  std::sort(mf_times.begin(), mf_times.end());
  const double mf_median = mf_times[mf_times.size() / 2];
  std::vector<double> f_mf(sol.force.size(), 0.0);
  std::size_t k = 0;
  for (std::size_t i = 0; i < f_mf.size(); ++i)
    if (fr.active[i]) f_mf[i] = fr.units.at(k++).fz_N;
  std::ofstream out(argv[2], std::ios::binary);
  const std::int64_t m = model.candidates();
  out.write(reinterpret_cast<const char*>(&m), sizeof m);
  out.write(reinterpret_cast<const char*>(p.compliance.data()), sizeof(double) * m * m);
  out.write(reinterpret_cast<const char*>(p.initial_gap.data()), sizeof(double) * m);
  out.write(reinterpret_cast<const char*>(sol.force.data()), sizeof(double) * m);
  out.write(reinterpret_cast<const char*>(&sol.approach_m), sizeof(double));
  out.write(reinterpret_cast<const char*>(&median), sizeof(double));
  out.write(reinterpret_cast<const char*>(f_mf.data()), sizeof(double) * m);
  out.write(reinterpret_cast<const char*>(&fr.sinking_m), sizeof(double));
  out.write(reinterpret_cast<const char*>(&mf_median), sizeof(double));
  return out ? 0 : 1;
}
