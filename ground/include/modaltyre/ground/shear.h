#pragma once
// The tangential contact, one interface for every ground (docs/soil.md section 2).
//
// A contact point (a ground point under the tyre, or a tread element on the road) enters the
// contact at its front and is carried through it. Along the way it accumulates the shear
// displacement j, the relative tangential displacement of tread and ground since entry
// (signed: positive where the tread moves backward relative to the ground, i.e. where a driven
// wheel pushes the ground back and is pushed forward). The contact solver advances each point
// by the increment dj of each step (a step along the patch in steady rolling, a time step in a
// transient) at its current normal stress sigma; the law returns the shear stress tau on the
// tyre, of the sign of the displacement that made it, and keeps what it needs in the point.
//
//   JanosiHanamoto (soil):  tau = (c + sigma tan phi)(1 - exp(-|j| / K)) sign(j)
//     (Janosi & Hanamoto 1961; Wong, Theory of Ground Vehicles, 4th ed., eq. 2.56): the shear
//     stress of the soil depends on the total displacement j, not on its history;
//   CoulombFriction (a rigid road): a tread spring of stiffness k per unit area in series with
//     Coulomb friction mu sigma: the elastic part e of j sticks while k |e| < mu sigma, and
//     slides at mu sigma otherwise (e is capped, the rest of dj is slip); tau = k e. The brush
//     model of tyre mechanics, stick and slip from one rule.
//
// Both give tau = 0 at j = 0 and |tau| <= strength_Pa(sigma). The co-simulation (issue 34)
// takes CoulombFriction for braking and traction on a road, the soil laws JanosiHanamoto.
namespace modaltyre::ground {

/// What a contact point carries through the contact.
struct ShearPoint {
  double displacement_m = 0;  ///< j, accumulated since entry (signed)
  double elastic_m = 0;       ///< Coulomb: the elastic (stick) part of j
  bool sliding = false;       ///< Coulomb: the last step slid
};

class ShearLaw {
 public:
  virtual ~ShearLaw() = default;
  /// Advances `point` by dj at normal stress sigma >= 0 [Pa]; returns tau [Pa].
  virtual double advance(ShearPoint& point, double normal_stress_Pa, double increment_m) const = 0;
  /// The largest |tau| at sigma [Pa].
  virtual double strength_Pa(double normal_stress_Pa) const = 0;
};

struct JanosiParams {
  double cohesion_kPa = 0;         ///< c >= 0 [kPa]
  double friction_angle_deg = 0;   ///< phi in [0, 89] [deg]
  double shear_modulus_K_mm = 25;  ///< K > 0 [mm] (shear deformation modulus)
  void validate() const;           ///< std::invalid_argument naming the parameter
};

class JanosiHanamoto final : public ShearLaw {
 public:
  explicit JanosiHanamoto(const JanosiParams& params);
  double advance(ShearPoint& point, double normal_stress_Pa, double increment_m) const override;
  double strength_Pa(double normal_stress_Pa) const override;
  /// The law itself: tau(sigma, j) [Pa].
  double stress_Pa(double normal_stress_Pa, double displacement_m) const;

 private:
  double c_Pa_, tan_phi_, K_m_;
};

class CoulombFriction final : public ShearLaw {
 public:
  /// mu >= 0; stick stiffness k > 0 per unit area [Pa/m] (tread: G / h).
  CoulombFriction(double mu, double stick_stiffness_Pa_m);
  double advance(ShearPoint& point, double normal_stress_Pa, double increment_m) const override;
  double strength_Pa(double normal_stress_Pa) const override;

 private:
  double mu_, k_;
};

}  // namespace modaltyre::ground
