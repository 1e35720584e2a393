#pragma once
// The sidewalls' nonlinear pneumatic stiffness (docs/validation.md, "The sidewalls' pneumatic
// softening"; optional key footprint_3d.sidewall). Membrane picture: a sidewall meridian of
// fixed length L between the rim and the belt edge, inflated by p to a circular arc of radius
// rho (meridional tension T = p rho per unit circumference, the hoop curvature neglected),
// half-angle alpha, radial chord c = 2 rho sin(alpha), so sin(alpha) / alpha = c / L. It pulls
// the belt edge towards the rim with
//   F(c) = T cos(alpha) = (p L / 2) cos(alpha) / alpha          [N/m per sidewall]
//   F'(c) = (p / 2) (alpha sin(alpha) + cos(alpha)) / (sin(alpha) - alpha cos(alpha)) > 0.
// Pressing the belt in by u (towards the rim) shortens the chord to c0 - u; the sidewall's
// restoring force F(c0) - F(c0 - u) softens (F is convex in c). The modes, measured at small
// amplitude about the inflated state, contain its linear part F'(c0) u (in the ring's foundation
// s0), so the model lacks, per unit circumference and for the two sidewalls,
//   e(u) = 2 [F'(c0) u - (F(c0) - F(c0 - u))] >= 0,
// the restoring force the linearised sidewalls carry and the real ones do not. It acts on the
// belt like an extra load towards the rim: w = C (F + e(w) ds) (patch3d.h).
namespace modaltyre::contact {

struct SidewallMembrane {
  bool enabled = false;  ///< false: the linear sidewalls of the modes (today's model)
  double chord_m = 0;    ///< c0, the meridian's radial chord at rest (rim to belt edge)
  double length_m = 0;   ///< L, the meridian's length, > c0
  /// The config states the section (enabled or, with enabled: false, its chord for the
  /// sidewall_softening effect of effects.h to switch on).
  bool given = false;
  /// Throws std::invalid_argument unless 0 < chord < length.
  void validate() const;
};

/// The meridian arc's half-angle alpha in (0, pi) with sin(alpha) / alpha = ratio, ratio in
/// (0, 1), by bisection to the last bit.
double meridian_half_angle(double chord_over_length);

/// F(c): one sidewall's pull on the belt edge towards the rim [N/m] at chord c (0 < c < L).
double sidewall_pull_N_per_m(double pressure_Pa, double length_m, double chord_m);

/// F'(c): its radial stiffness [N/m^2].
double sidewall_stiffness_N_per_m2(double pressure_Pa, double length_m, double chord_m);

/// e(u) of one membrane at one pressure, with the rest state's F(c0) and F'(c0) computed once:
/// the 3D patch's fixed point evaluates it for every section at every step.
class SidewallLostForce {
 public:
  SidewallLostForce(const SidewallMembrane& s, double pressure_Pa);
  /// e(u) [N/m] at an inward displacement u of the belt (u < c0 and c0 - u < L; NaN outside).
  double operator()(double displacement_m) const;

 private:
  bool active_;  ///< enabled and p != 0 (else e = 0)
  double pressure_Pa_, chord_m_, length_m_;
  double pull0_N_per_m_ = 0, stiffness0_N_per_m2_ = 0;  ///< F(c0), F'(c0)
};

/// e(u): the two sidewalls' lost restoring force per unit circumference [N/m] at an inward
/// displacement u of the belt (u < c0 and c0 - u < L; NaN outside). One evaluation of
/// SidewallLostForce.
double sidewall_lost_force_N_per_m(const SidewallMembrane& s, double pressure_Pa,
                                   double displacement_m);

}  // namespace modaltyre::contact
