#include "modaltyre/uncertainty/propagation.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>
#include <stdexcept>

#include "alternatives.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/uncertainty/order_mixture.h"

namespace modaltyre::uncertainty {
namespace {

/// The 97.5 % point of the standard normal: the linearised band is +-1.96 sigma.
constexpr double kZ975 = 1.959963984540054;
/// A perturbation never takes a quantity below this share of its nominal value (a sample of a
/// very uncertain input must not make a mass or a modulus negative).
constexpr double kMinFactor = 0.05;
/// Relative resolution of an output (four printed digits): differences below it are noise.
constexpr double kOutputResolution = 1e-4;

Outputs perturbed(const contact::TyreConfig& config, const modal::ModeIdentification& modes,
                  const Evaluator& evaluate, const std::vector<UncertainInput>& inputs,
                  const std::vector<double>& x, const std::string& what) {
  contact::TyreConfig c = config;
  modal::ModeIdentification m = modes;
  for (std::size_t j = 0; j < inputs.size(); ++j) {
    if (x[j] != 0) apply(inputs[j], std::max(x[j], kMinFactor - 1), c, m);
  }
  return evaluate(c, m, what);
}

}  // namespace

/// Every row has one value per output, all finite: a model that returns fewer, or NaN, would
/// make a band of garbage.
void check_shape(const Outputs& v, std::size_t rows, std::size_t outputs, const std::string& what) {
  bool ok = v.size() == rows;
  for (const auto& r : v) {
    ok = ok && r.size() == outputs;
    for (double x : r) ok = ok && std::isfinite(x);
  }
  if (!ok) {
    throw ComputationError("uncertainty: the model with " + what +
                           " gave a different number of outputs, or a non-finite one");
  }
}

namespace {

double percentile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  const double pos = q * (v.size() - 1);
  const auto lo = static_cast<std::size_t>(std::floor(pos));
  const auto hi = std::min(lo + 1, v.size() - 1);
  return v[lo] + (pos - lo) * (v[hi] - v[lo]);
}

}  // namespace

void PropagationOptions::validate() const {
  if (samples < kMinSamples || samples > kMaxSamples) {
    throw std::invalid_argument("samples must be in " + std::to_string(kMinSamples) + ".." +
                                std::to_string(kMaxSamples) + ", got " + std::to_string(samples));
  }
  if (!(max_nonlinearity > 0) || !std::isfinite(max_nonlinearity)) {
    throw std::invalid_argument("max_nonlinearity must be > 0");
  }
  if (threads < 0 || threads > 4096) throw std::invalid_argument("threads must be in 0..4096");
}

namespace {

// The continuous inputs' bands; `nominal_out` gets the nominal outputs and, when sampled,
// `samples_out` the samples.
PropagationResult propagate_continuous(const contact::TyreConfig& config,
                                       const modal::ModeIdentification& modes,
                                       const Evaluator& evaluate, const OutputSet& outputs,
                                       const PropagationOptions& o, Outputs& nominal_out,
                                       std::vector<Outputs>& samples_out) {
  o.validate();
  std::vector<UncertainInput> inputs = collect_inputs(config, modes);
  inputs.insert(inputs.end(), o.extra_inputs.begin(), o.extra_inputs.end());
  const std::size_t n = inputs.size(), no = outputs.names.size();
  if (no == 0) throw std::invalid_argument("uncertainty: no outputs to propagate to");
  if (!outputs.curved.empty() && outputs.curved.size() != no) {
    throw std::invalid_argument("uncertainty: OutputSet.curved must have one flag per output");
  }
  PropagationResult r;
  const Outputs nominal =
      outputs.nominal.empty() ? evaluate(config, modes, "the nominal inputs") : outputs.nominal;
  const std::size_t nc = nominal.size();
  check_shape(nominal, nc, no, "the nominal inputs");
  nominal_out = nominal;
  const auto row_label = [&](std::size_t c) {
    return c < outputs.row_labels.size() ? outputs.row_labels[c] : "row " + std::to_string(c + 1);
  };
  r.evaluations = outputs.nominal.empty() ? 1 : 0;  // model evaluations made here
  const int total = static_cast<int>(1 + 2 * n);
  if (o.progress) o.progress(1, total);

  // Central differences at +-1 sigma, every input in parallel.
  std::vector<Outputs> plus(n), minus(n);
  std::string failure;
  // OMP_NUM_THREADS may say anything: no more threads than a few per core.
  const int threads =
      o.threads > 0 ? o.threads : std::min(omp_get_max_threads(), 4 * omp_get_num_procs());
  int done = 1;
#pragma omp parallel for schedule(dynamic) num_threads(threads)
  for (long k = 0; k < static_cast<long>(2 * n); ++k) {
    const std::size_t j = static_cast<std::size_t>(k) / 2;
    const double sign = k % 2 ? -1.0 : 1.0;
    std::vector<double> x(n, 0.0);
    x[j] = sign * inputs[j].rel_std;
    try {
      Outputs v = perturbed(config, modes, evaluate, inputs, x, inputs[j].name);
      check_shape(v, nc, no, inputs[j].name);
#pragma omp critical
      {
        (sign > 0 ? plus[j] : minus[j]) = std::move(v);
        ++done;
        if (o.progress) o.progress(done, total);
      }
    } catch (const std::exception& e) {
#pragma omp critical
      failure = e.what();
    }
  }
  if (!failure.empty()) throw ComputationError(failure);
  r.evaluations += static_cast<int>(2 * n);

  double worst = 0;
  std::string worst_name;
  r.cases.assign(nc, {});
  for (std::size_t c = 0; c < nc; ++c) r.cases[c].bands.assign(no, {});
  for (std::size_t j = 0; j < n; ++j) {
    InputEffect e;
    e.input = inputs[j];
    e.sensitivity.assign(nc, std::vector<double>(no, 0.0));
    for (std::size_t c = 0; c < nc; ++c) {
      for (std::size_t q = 0; q < no; ++q) {
        const double d1 = 0.5 * (plus[j][c][q] - minus[j][c][q]);
        e.sensitivity[c][q] = d1;
        const bool gridded = !outputs.curved.empty() && !outputs.curved[q];
        const double d2 = 0.5 * (plus[j][c][q] + minus[j][c][q] - 2 * nominal[c][q]);
        // A second difference below the outputs' resolution is not curvature that moves a
        // band: the 3D width and peak step with the cells (a 2.5 mm column), and any output is
        // printed to four digits.
        const double resolution = kOutputResolution * std::abs(nominal[c][q]);
        if (!gridded && std::abs(d2) > resolution) {
          const double ratio = std::abs(d2) / std::max(std::abs(d1), resolution);
          if (ratio > e.nonlinearity) {
            e.nonlinearity = ratio;
            e.nonlinear_output = outputs.names[q] + " at " + row_label(c);
          }
        }
        r.cases[c].bands[q].std += d1 * d1;  // variance for now
      }
      e.sinking_sensitivity.push_back(0.5 * (plus[j][c][0] - minus[j][c][0]));
    }
    if (e.nonlinearity > worst) {
      worst = e.nonlinearity;
      worst_name = e.input.name + ", " + e.nonlinear_output;
    }
    r.inputs.push_back(std::move(e));
  }
  for (std::size_t c = 0; c < nc; ++c) {
    for (std::size_t q = 0; q < no; ++q) {
      Band& b = r.cases[c].bands[q];
      b.value = nominal[c][q];
      b.std = std::sqrt(b.std);
      b.p025 = b.value - kZ975 * b.std;
      b.p975 = b.value + kZ975 * b.std;
    }
  }
  std::ostringstream check;
  check.precision(3);
  if (n == 0) {
    r.method = "linear";
    r.check = "no uncertain input (noise-free shapes, nothing stated): the bands have zero width";
    return r;
  }
  check << "central differences at +-1 sigma of " << n << " inputs; ";
  if (worst > 0) {
    check << "largest second/first difference " << worst << " (" << worst_name << ")";
  } else {
    check << "no second difference above the outputs' resolution (1e-4)";
  }
  check << ", threshold " << o.max_nonlinearity;
  if (!outputs.curved.empty() && std::count(outputs.curved.begin(), outputs.curved.end(), false)) {
    // Not checked: grid quantities (a maximum over cells, a map's cells); a few named.
    check << " (not checked, a grid's quantities:";
    std::size_t named = 0, unnamed = 0;
    for (std::size_t q = 0; q < no; ++q) {
      if (outputs.curved[q]) continue;
      if (named < 3) {
        check << (named ? ", " : " ") << outputs.names[q];
        ++named;
      } else {
        ++unnamed;
      }
    }
    if (unnamed) check << " and " << unnamed << " more";
    check << ")";
  }
  const bool sample =
      o.method == Method::sampled || (o.method == Method::automatic && worst > o.max_nonlinearity);
  if (!sample) {
    r.method = "linear";
    r.check = check.str();
    return r;
  }

  // Monte Carlo: every input at once, one seeded generator per sample.
  const int m = o.samples;
  std::vector<Outputs> s(static_cast<std::size_t>(m));
  int sampled = 0;
#pragma omp parallel for schedule(dynamic) num_threads(threads)
  for (int k = 0; k < m; ++k) {
    std::mt19937_64 rng(o.seed + 0x9E3779B97F4A7C15ULL * static_cast<unsigned long>(k + 1));
    std::normal_distribution<double> normal(0.0, 1.0);
    std::vector<double> x(n);
    for (std::size_t j = 0; j < n; ++j) x[j] = inputs[j].rel_std * normal(rng);
    try {
      const std::string what = "sample " + std::to_string(k);
      s[static_cast<std::size_t>(k)] = perturbed(config, modes, evaluate, inputs, x, what);
      check_shape(s[static_cast<std::size_t>(k)], nc, no, what);
#pragma omp critical
      if (o.progress) o.progress(++sampled, m);
    } catch (const std::exception& e) {
#pragma omp critical
      failure = e.what();
    }
  }
  if (!failure.empty()) throw ComputationError(failure);
  r.evaluations += m;
  for (std::size_t c = 0; c < nc; ++c) {
    for (std::size_t q = 0; q < no; ++q) {
      std::vector<double> v;
      double mean = 0;
      for (const auto& sample : s) v.push_back(sample[c][q]), mean += sample[c][q];
      mean /= m;
      double var = 0;
      for (double x : v) var += (x - mean) * (x - mean);
      Band& b = r.cases[c].bands[q];
      b.value = mean;
      b.std = std::sqrt(var / (m - 1));
      b.p025 = percentile(v, 0.025);
      b.p975 = percentile(v, 0.975);
    }
  }
  r.method = "sampled";
  check << "; " << m << " Monte Carlo samples (seed " << o.seed << ")"
        << (o.method == Method::sampled ? " as asked"
                                        : " because the linearisation is not trusted");
  r.check = check.str();
  samples_out = std::move(s);
  return r;
}

}  // namespace

PropagationResult propagate_outputs(const contact::TyreConfig& config,
                                    const modal::ModeIdentification& modes,
                                    const Evaluator& evaluate, const OutputSet& outputs,
                                    const PropagationOptions& o) {
  Outputs nominal;
  std::vector<Outputs> samples;
  PropagationResult r = propagate_continuous(config, modes, evaluate, outputs, o, nominal, samples);
  mix_alternatives(r, config, modes, evaluate, nominal, samples);
  return r;
}

PropagationResult propagate_row(const contact::TyreConfig& config,
                                const modal::ModeIdentification& modes,
                                const RowEvaluator& evaluate, const std::vector<std::string>& names,
                                const std::vector<double>& nominal, const std::string& label,
                                const std::string& command, const PropagationOptions& options) {
  const Evaluator rows = [&](const contact::TyreConfig& c, const modal::ModeIdentification& m,
                             const std::string& what) {
    auto [got, values] = evaluate(c, m, what);
    if (got != names) {
      throw ComputationError(command + " --uncertainty: with " + what +
                             " the result carries other quantities than at the nominal inputs");
    }
    return Outputs{std::move(values)};
  };
  OutputSet outputs;
  outputs.names = names;
  outputs.row_labels = {label};
  outputs.nominal = {nominal};
  return propagate_outputs(config, modes, rows, outputs, options);
}

}  // namespace modaltyre::uncertainty
