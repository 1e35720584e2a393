#pragma once
// A soil's normal law stretched in depth by the slip-sinkage factor f >= 1 (soil_options.h,
// Lyasko 2010): at a pressure p the soil sinks f times the law's sinkage, with its memory in the
// same depths,
//   z(p; z_max) = f Z(p; z_max / f),   p(z; z_max) = P(z / f; z_max / f),
// so every branch (loading, unloading, the rut) keeps its shape; for Bekker's law this is the
// modulus (k_c / b + k_phi) divided by f^n. f = 1 is the law itself.
#include <memory>

#include "modaltyre/ground/pressure_sinkage.h"

namespace modaltyre::ground {

class SlipSinkageLaw final : public PressureSinkage {
 public:
  SlipSinkageLaw(std::unique_ptr<PressureSinkage> law, double factor);
  double loading_Pa(double z_m) const override { return law_->loading_Pa(z_m / f_); }
  double loading_sinkage_m(double p_Pa) const override {
    return f_ * law_->loading_sinkage_m(p_Pa);
  }
  double unloading_Pa(double z_m, double z_max_m) const override {
    return law_->unloading_Pa(z_m / f_, z_max_m / f_);
  }
  double unloading_sinkage_m(double p_Pa, double z_max_m) const override {
    return f_ * law_->unloading_sinkage_m(p_Pa, z_max_m / f_);
  }
  double rebound_depth_m(double z_max_m) const override {
    return f_ * law_->rebound_depth_m(z_max_m / f_);
  }
  bool rigid_plastic() const override { return law_->rigid_plastic(); }
  double work_J_m2(double p_Pa, double z_max_m) const override {
    return f_ * law_->work_J_m2(p_Pa, z_max_m / f_);
  }
  double compliance_m_per_Pa(double p_Pa, double z_max_m) const override {
    return f_ * law_->compliance_m_per_Pa(p_Pa, z_max_m / f_);
  }
  double virgin_sinkage_m(double p_Pa, double& dz_dp_m_per_Pa) const override {
    const double z = f_ * law_->virgin_sinkage_m(p_Pa, dz_dp_m_per_Pa);
    dz_dp_m_per_Pa *= f_;
    return z;
  }
  double factor() const { return f_; }

 private:
  std::unique_ptr<PressureSinkage> law_;
  double f_;
};

}  // namespace modaltyre::ground
