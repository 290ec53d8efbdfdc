#include "compress/strain_gauge.hpp"

#include <cmath>

namespace bpm {

StrainGauge::StrainGauge(const std::vector<Vec3>& position, const Vec3& axis,
                         const SampleGeometry& sample)
    : axis_(axis) {
  const double from = sample.bottom + sample.length / 3.0, to = sample.top - sample.length / 3.0;
  Vec3 centre{};
  for (std::size_t p = 0; p < position.size(); ++p) {
    const double height = dot(position[p], axis);
    if (height < from || height > to) continue;
    members_.push_back(static_cast<std::int32_t>(p));
    centre += position[p];
  }
  if (members_.size() < 4) return;
  centre = (1.0 / static_cast<double>(members_.size())) * centre;
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
  double spread = 0.0;
  for (const std::int32_t p : members_) {
    const Vec3 x = position[static_cast<std::size_t>(p)] - centre;
    offset_.push_back(x);
    spread += norm2(x);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) second(i, j) += x[i] * x[j];
  }
  // All in a plane or on a line: the smallest principal second moment vanishes against the sum.
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> principal(second);
  if (!(principal.eigenvalues()[0] > 1e-6 * spread)) return;
  inverse_ = second.inverse();
  valid_ = true;
}

GaugeStrain StrainGauge::strain(const Eigen::Matrix3d& gradient) const {
  const Eigen::Matrix3d eps = 0.5 * (gradient + gradient.transpose());
  const Eigen::Vector3d a{axis_[0], axis_[1], axis_[2]};
  const double axial = a.dot(eps * a);
  return {axial, 0.5 * (eps.trace() - axial)};
}

BodyModuli body_moduli(double stiffness, double area, double axial_per_travel,
                       double lateral_per_travel) {
  BodyModuli m;
  m.axial_per_travel = axial_per_travel;
  m.lateral_per_travel = lateral_per_travel;
  if (!(axial_per_travel < 0.0) || !(area > 0.0) || !std::isfinite(stiffness)) return m;
  m.youngs_modulus = stiffness / area / -axial_per_travel;
  m.poissons_ratio = -lateral_per_travel / axial_per_travel;
  m.valid = true;
  return m;
}

}  // namespace bpm
