#pragma once
// The lateral law of each section for the reduction of patch3d.h, internal to the contact
// library. A section at approach d (its belt's support, or its rigid belt, at d from the road)
// carries F = Phi(d); on a fixed lateral pattern (the cells in contact) it is affine, d = c F + o,
// with the section compliance c and offset o. Two laws:
//   RigidSections     laterally rigid belt: the pattern is the n lowest drops, c = t / n,
//                     o = mean of those drops (sorted-drop law)
//   FlexibleSections  lateral belt compliance G (patch3d.h LateralBelt): on the pattern A,
//                     M = G + t I, M_AA a = 1, M_AA b = z_A: c = 1 / 1^T a, o = 1^T b / 1^T a,
//                     f_A = d a - b; psi and the pattern from one small contact problem per
//                     section (min 1/2 f^T M f + z^T f, f >= 0, 1^T f = F).
#include <Eigen/Dense>
#include <memory>
#include <stdexcept>
#include <vector>

#include "modaltyre/ground/pressure_sinkage.h"

namespace modaltyre::contact::detail {

class SectionLaws {
 public:
  virtual ~SectionLaws() = default;
  /// Section compliance c and offset o on section i's current pattern.
  virtual void reduced(int i, double& compliance, double& offset) const = 0;
  /// Whether the current pattern holds at approach d with the section force F (F = 0: the
  /// section is out of contact).
  virtual bool consistent(int i, double F, double d, double tol) const = 0;
  /// Cell forces of section i at approach d on its current pattern (into f, columns entries).
  virtual void cell_forces(int i, double d, double* f) const = 0;
  /// Psi_i(F), the section's least energy at force F [J]; `update` also moves section i's
  /// pattern to the one at F.
  virtual double energy(int i, double F, bool update) = 0;
  /// Starts section i's pattern from the cells a previous solution loads (f: columns entries,
  /// some > 0), a warm start; the default keeps the law's own first pattern.
  virtual void start_from(int /*i*/, const double* /*f*/) {}
  /// psi_i(F), the section's approach at force F (its pattern unchanged): the merit of the
  /// non-symmetric (rolling) iteration. Not for a soil (rolling on a soil is refused).
  virtual double approach(int /*i*/, double /*F*/) {
    throw std::logic_error("3D patch: this section law has no approach for a rolling carcass");
  }
};

std::unique_ptr<SectionLaws> rigid_sections(const std::vector<double>& t,
                                            const std::vector<double>& z);
std::unique_ptr<SectionLaws> flexible_sections(const std::vector<double>& t,
                                               const std::vector<double>& z,
                                               const Eigen::MatrixXd& G, int max_iterations);

/// A soil under every cell in series with its tread (patch3d_soil.cc): `area` the road area of a
/// cell of each section [m^2]; virgin soil.
std::unique_ptr<SectionLaws> soil_sections(const std::vector<double>& t,
                                           const std::vector<double>& z,
                                           const ground::PressureSinkage& law,
                                           const std::vector<double>& area);

}  // namespace modaltyre::contact::detail
