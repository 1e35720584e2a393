// Modal basis of the carcass: pair weights, mass normalisation, compliance scale and the
// dispersion extension of unmeasured orders.
#include "modaltyre/modal/modal_basis.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

#include "modal_test_constants.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/modal/hammer_data.h"
#include "modaltyre/modal/mode_identification.h"

namespace modaltyre::modal {
namespace {

using test::kMu;
using test::kPi;
using test::kR;
using test::kTwoPi;
// Rounding only: products and sums of a few doubles.
constexpr double kRoundTol = 1e-12;

HammerData sf350() {
  return read_hammer_csv(std::string(MODALTYRE_SOURCE_DIR) + "/configs/data/sf350_hammer_12pt.csv");
}

const ModalTerm* term_of_mode(const ModalBasis& b, int id) {
  for (const auto& t : b.terms)
    if (t.measured && t.mode_id == id) return &t;
  return nullptr;
}

// Measured pairs weigh 1/2 per member, breathing and rotation (order 0) weigh 1; aliased modes
// are not used as measured terms.
TEST(ModalBasis, PairAndOrderZeroWeights) {
  const auto id = identify_modes(sf350());
  ModalBasisOptions o;
  o.extend = false;
  const auto b = build_modal_basis(id, o);
  EXPECT_EQ(b.measured_terms, 12);  // modes 1-11 and the rotation 14
  EXPECT_EQ(b.terms.size(), 12u);
  EXPECT_TRUE(b.warnings.empty());
  for (int m : {1, 2, 4, 5, 6, 7, 8, 9, 10, 11}) {
    const auto* t = term_of_mode(b, m);
    ASSERT_NE(t, nullptr) << "mode " << m;
    EXPECT_EQ(t->weight, 0.5) << "mode " << m;
  }
  for (int m : {3, 14}) {
    const auto* t = term_of_mode(b, m);
    ASSERT_NE(t, nullptr) << "mode " << m;
    EXPECT_EQ(t->order, 0);
    EXPECT_EQ(t->weight, 1.0) << "mode " << m;
  }
  for (int m : {12, 13, 15, 16}) EXPECT_EQ(term_of_mode(b, m), nullptr) << "mode " << m;
  // Frequencies and damping carried over.
  EXPECT_NEAR(term_of_mode(b, 6)->omega_rad_s, kTwoPi * 155.739, 1e-9);
  EXPECT_EQ(term_of_mode(b, 6)->damping_ratio, 0.03370);
}

// A lone member of a pair stands for its unmeasured twin: weight 1. A missing breathing mode is
// reported as a warning.
TEST(ModalBasis, LoneMemberAndMissingOrderZero) {
  auto data = sf350();
  std::erase_if(data.modes, [](const MeasuredMode& m) { return m.id == 5 || m.id == 3; });
  const auto id = identify_modes(data);
  ModalBasisOptions o;
  o.extend = false;
  const auto b = build_modal_basis(id, o);
  ASSERT_NE(term_of_mode(b, 4), nullptr);
  EXPECT_EQ(term_of_mode(b, 4)->weight, 1.0);
  EXPECT_EQ(term_of_mode(b, 6)->weight, 0.5);
  ASSERT_EQ(b.warnings.size(), 1u);
  EXPECT_NE(b.warnings[0].find("order-0"), std::string::npos);
}

// Mass normalisation: a ring mode pair of order k contributes a^2 / omega^2 with
// a^2 = 1/(pi mu R) (order 0: 1/(2 pi mu R)) to the static compliance coefficient; the pair
// weights make the two members' contributions average.
TEST(ModalBasis, StaticCoefficientsMatchRingNormalisation) {
  // 3 % shape noise at 12 points: |c|^2 has relative standard deviation 2*0.03*sqrt(2/12) =
  // 2.4 % per member; 4 sigmas of the pair mean (1.7 %) give 7 %.
  constexpr double kNormTol = 0.07;
  const auto data = sf350();
  const auto id = identify_modes(data);
  ModalBasisOptions o;
  o.extend = false;
  const auto b = build_modal_basis(id, o);
  const double a2 = 1 / (kPi * kMu * kR), a02 = 1 / (2 * kPi * kMu * kR);
  auto w2 = [&](int mode) { return std::pow(kTwoPi * data.modes[mode - 1].freq_hz, 2); };
  const std::map<int, std::pair<int, int>> pairs = {
      {1, {1, 2}}, {2, {4, 5}}, {3, {6, 7}}, {4, {8, 9}}, {5, {10, 11}}};
  for (const auto& [k, p] : pairs) {
    const double expect = a2 * 0.5 * (1 / w2(p.first) + 1 / w2(p.second));
    EXPECT_NEAR(b.static_rr(k) / expect, 1.0, kNormTol) << "order " << k;
  }
  // Order 0: breathing (radial a0) plus rotation (radial ~0).
  EXPECT_NEAR(b.static_rr(0) / (a02 / w2(3)), 1.0, kNormTol);
}

// compliance_scale multiplies every term (measured and extension), nothing else changes.
TEST(ModalBasis, ComplianceScaleScalesEveryTerm) {
  constexpr double kScale = 2.5;
  const auto id = identify_modes(sf350());
  ModalBasisOptions o1, o2;
  o1.max_order = o2.max_order = 60;
  o2.compliance_scale = kScale;
  const auto b1 = build_modal_basis(id, o1), b2 = build_modal_basis(id, o2);
  ASSERT_EQ(b1.terms.size(), b2.terms.size());
  for (std::size_t i = 0; i < b1.terms.size(); ++i) {
    const auto &t1 = b1.terms[i], &t2 = b2.terms[i];
    EXPECT_EQ(t1.order, t2.order);
    EXPECT_EQ(t1.omega_rad_s, t2.omega_rad_s);
    EXPECT_EQ(t1.weight, t2.weight);
    EXPECT_LE(std::abs(t2.P_rr - kScale * t1.P_rr), kRoundTol * std::abs(t2.P_rr));
    EXPECT_LE(std::abs(t2.P_rt - kScale * t1.P_rt), kRoundTol * std::abs(t2.P_rt));
    EXPECT_LE(std::abs(t2.P_tt - kScale * t1.P_tt), kRoundTol * std::abs(t2.P_tt));
  }
  for (int k = 0; k <= 60; ++k)
    EXPECT_NEAR(b2.static_rr(k), kScale * b1.static_rr(k), kRoundTol * b2.static_rr(k));
}

// Extension: every order from the first unresolved one up to max_order gets exactly one term
// on the dispersion law, with the mean measured |c_r|^2 of orders >= 2 and the inextensional
// ring's tangential shape (|c_t| = |c_r|/k, 90 degrees out of phase).
TEST(ModalBasis, ExtensionFillsUnmeasuredOrders) {
  constexpr int kMax = 40;
  const auto id = identify_modes(sf350());
  ModalBasisOptions o;
  o.max_order = kMax;
  const auto b = build_modal_basis(id, o);
  EXPECT_EQ(b.max_order, kMax);
  double amp = 0;
  int n = 0;
  for (const auto& m : id.modes) {
    if (m.kind == ModeKind::radial && !m.aliased && m.apparent_order >= 2) {
      amp += std::norm(m.c_radial);
      ++n;
    }
  }
  ASSERT_EQ(n, 8);
  amp /= n;
  std::map<int, int> ext, meas;
  for (const auto& t : b.terms) (t.measured ? meas : ext)[t.order]++;
  for (int k = 0; k <= 5; ++k) {
    EXPECT_EQ(ext.count(k), 0u) << "order " << k;
    EXPECT_GE(meas[k], 2) << "order " << k;
  }
  for (int k = 6; k <= kMax; ++k) EXPECT_EQ(ext[k], 1) << "order " << k;
  EXPECT_EQ(ext.size(), std::size_t(kMax - 5));
  for (const auto& t : b.terms) {
    if (t.measured) continue;
    const int k = t.order;
    EXPECT_EQ(t.weight, 1.0);
    EXPECT_NEAR(t.omega_rad_s, std::sqrt(id.dispersion.omega_sq(k)), kRoundTol * t.omega_rad_s);
    EXPECT_NEAR(t.P_rr.real(), amp, kRoundTol * amp);
    EXPECT_NEAR(t.P_tt.real(), amp / (double(k) * k), kRoundTol * amp);
    EXPECT_NEAR(t.P_rt.real(), 0.0, kRoundTol * amp);
    EXPECT_NEAR(std::abs(t.P_rt.imag()), amp / k, kRoundTol * amp);
    EXPECT_GT(t.damping_ratio, 0.0);
  }
  // The measured data fix the sign of the radial-tangential coupling the extension uses:
  // all measured orders >= 2 and the extension agree in the sign of Im(P_rt).
  int sign = 0;
  for (const auto& t : b.terms) {
    if (t.order < 2) continue;
    const int s = t.P_rt.imag() > 0 ? 1 : -1;
    if (sign == 0) sign = s;
    EXPECT_EQ(s, sign) << "order " << t.order << (t.measured ? " measured" : " extension");
  }
}

// Extension without a valid dispersion fit is refused with an InputError.
TEST(ModalBasis, ExtensionNeedsDispersion) {
  auto data = sf350();
  // Keep orders 0, 1 and 2 only: one order >= 2 cannot define the law.
  std::erase_if(data.modes, [](const MeasuredMode& m) { return m.id > 5 && m.id != 14; });
  const auto id = identify_modes(data);
  ASSERT_FALSE(id.dispersion.valid);
  ModalBasisOptions o;
  o.max_order = 20;
  EXPECT_THROW(build_modal_basis(id, o), InputError);
  o.extend = false;
  EXPECT_NO_THROW(build_modal_basis(id, o));
}

}  // namespace
}  // namespace modaltyre::modal
