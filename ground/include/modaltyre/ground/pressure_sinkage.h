#pragma once
// The normal law of a deformable ground point: pressure against sinkage, with memory.
//
// Conventions (docs/soil.md section 1): sinkage z is measured downward from the undisturbed
// surface [m]; the pressure p >= 0 acts normal to the loaded surface [Pa]. A ground point
// remembers the deepest sinkage it has been pressed to, z_max (0: virgin soil):
//   loading   (z >= z_max): p = loading_Pa(z), the virgin curve;
//   unloading / reloading (z < z_max): p = unloading_Pa(z, z_max), a branch that meets the
//             virgin curve at z_max and reaches p = 0 at the rebound depth (the rut left behind).
// A rigid-plastic soil (no elastic rebound) has a vertical branch at z_max: it rebounds by 0
// and carries any pressure up to loading_Pa(z_max) there without further sinkage.
//
// sinkage_m(p, z_max) is the inverse the contact solvers use: continuous and non-decreasing in
// p, so that its integral over the force is a convex energy (the soil in series with the tyre
// keeps the contact problem a convex minimisation, docs/soil.md section 4).
namespace modaltyre::ground {

class PressureSinkage {
 public:
  virtual ~PressureSinkage() = default;
  /// Virgin loading curve p(z), z >= 0 [Pa].
  virtual double loading_Pa(double z_m) const = 0;
  /// Its inverse z(p), p >= 0 [m].
  virtual double loading_sinkage_m(double p_Pa) const = 0;
  /// Pressure at z < z_max on the unloading/reloading branch; 0 above the rebound depth.
  virtual double unloading_Pa(double z_m, double z_max_m) const = 0;
  /// The sinkage on that branch at p in [0, loading_Pa(z_max)] (z_max for a rigid-plastic soil).
  virtual double unloading_sinkage_m(double p_Pa, double z_max_m) const = 0;
  /// Depth of the surface after complete unloading from z_max: the rut [m], in [0, z_max].
  virtual double rebound_depth_m(double z_max_m) const = 0;
  /// No elastic rebound: the unloading branch is vertical at z_max.
  virtual bool rigid_plastic() const = 0;

  /// p(z) for a point that has been to z_max: loading beyond z_max, the branch below.
  double pressure_Pa(double z_m, double z_max_m) const;
  /// z(p) for a point that has been to z_max: the branch up to loading_Pa(z_max), then the
  /// virgin curve. Continuous and non-decreasing in p.
  double sinkage_m(double p_Pa, double z_max_m) const;
  /// dz/dp of sinkage_m at p (right derivative; 0 on a rigid-plastic branch) [m/Pa]. This
  /// default differentiates numerically; the laws below override it with their closed forms.
  virtual double compliance_m_per_Pa(double p_Pa, double z_max_m) const;
  /// The virgin curve's sinkage z(p) and its slope dz/dp at p >= 0 in one evaluation (the 3D
  /// patch's cell roots, contact/src/patch3d_soil.cc). This default calls loading_sinkage_m and
  /// compliance_m_per_Pa(p, 0); Bekker-Wong shares its power between the two.
  virtual double virgin_sinkage_m(double p_Pa, double& dz_dp_m_per_Pa) const;
  /// The work of the pressure per unit area, int_0^p sinkage_m(q, z_max) dq [J/m^2]: the soil's
  /// complementary energy, convex in p. This default integrates numerically (Gauss-Legendre,
  /// relative error below 1e-9); the laws below override it with their closed forms.
  virtual double work_J_m2(double p_Pa, double z_max_m) const;
  /// The pressure of the law's rate term at the sinkage rate dz/dt [m/s], on the virgin curve
  /// (`virgin`) or a branch below z_max: 0 for a rate-independent law (the Kelvin-Voigt soil's
  /// eta2 term, kelvin_voigt_soil.h). Negative while the surface rises.
  virtual double viscous_Pa(double dz_dt_m_s, bool virgin) const {
    (void)dz_dt_m_s, (void)virgin;
    return 0.0;
  }
};

}  // namespace modaltyre::ground
