#pragma once
/// Virtual strain gauges: the body's strain as a laboratory measures it, on the middle of the
/// specimen, away from the platens. A platen's travel over the sample's length also holds the
/// compliance of the Hertz contacts between the platens and the sample (on the small cylinder the
/// middle third strains about 0.4 of the platens' nominal strain), so a material's E and nu come
/// from the body, and Jarolin's K (platen force over platen travel) stays for comparing methods.
///
/// The gauge is the particles whose centre lies in the middle third of the sample's length along
/// the axis (all of them across it). Their displacements u are fitted by least squares with an
/// affine field u = H (X - X_c) + c (X the initial centres, X_c their mean); the strain is
/// eps = (H + H^T) / 2. The axial strain is a.eps.a (negative in compression), the lateral strain
/// the mean normal strain across the axis, (tr eps - a.eps.a) / 2. A uniform strain is measured
/// exactly, a rigid motion gives zero to first order. Each method measures its E and nu over the
/// fit window from these, with sigma = F / A (sample_geometry.hpp):
///   E = d sigma / d(-eps_axial),  nu = -d eps_lateral / d eps_axial.
#include <cstdint>
#include <vector>

#include <Eigen/Dense>

#include "compress/sample_geometry.hpp"
#include "core/vec3.hpp"

namespace bpm {

struct GaugeStrain {
  double axial = 0.0;    ///< a.eps.a, negative in compression
  double lateral = 0.0;  ///< (tr eps - a.eps.a) / 2
};

class StrainGauge {
 public:
  /// The particles of `position` (initial centres) in the middle third of `sample` along the
  /// unit vector `axis`.
  StrainGauge(const std::vector<Vec3>& position, const Vec3& axis, const SampleGeometry& sample);

  /// False where the middle third holds too few particles, or all in a plane or on a line, to fit
  /// a strain (a chain or a single layer of particles).
  bool valid() const { return valid_; }
  std::size_t size() const { return members_.size(); }

  /// The strain of the displacements `displacement(p)` (a Vec3 for particle p) of the gauge's
  /// particles. Requires valid().
  template <class Displacement>
  GaugeStrain measure(const Displacement& displacement) const {
    Vec3 mean{};
    for (const std::int32_t p : members_) mean += displacement(p);
    mean = (1.0 / static_cast<double>(members_.size())) * mean;
    Eigen::Matrix3d moment = Eigen::Matrix3d::Zero();  // sum (u - mean) (X - X_c)^T
    for (std::size_t k = 0; k < members_.size(); ++k) {
      const Vec3 u = displacement(members_[k]) - mean;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) moment(i, j) += u[i] * offset_[k][j];
    }
    return strain(moment * inverse_);
  }

  /// The strain of a field with `dofs` values per particle, its translation first (the DSM's).
  GaugeStrain measure_field(const Eigen::VectorXd& u, int dofs) const {
    return measure([&](std::int32_t p) {
      const Eigen::Index at = static_cast<Eigen::Index>(dofs) * p;
      return Vec3{u[at], u[at + 1], u[at + 2]};
    });
  }

 private:
  GaugeStrain strain(const Eigen::Matrix3d& gradient) const;

  std::vector<std::int32_t> members_;
  std::vector<Vec3> offset_;                           ///< X - X_c of each member
  Eigen::Matrix3d inverse_ = Eigen::Matrix3d::Zero();  ///< (sum (X - X_c)(X - X_c)^T)^-1
  Vec3 axis_;
  bool valid_ = false;
};

/// E and nu from the slopes over the fit window: K = dF/dw and the gauge's d eps/dw (w the platen
/// travel), with the sample's cross-section A. Not valid where the body does not shorten.
struct BodyModuli {
  double youngs_modulus = 0.0;      ///< E = (K / A) / (-d eps_axial / dw), Pa
  double poissons_ratio = 0.0;      ///< nu = -(d eps_lateral / dw) / (d eps_axial / dw)
  double axial_per_travel = 0.0;    ///< d eps_axial / dw, 1/m
  double lateral_per_travel = 0.0;  ///< d eps_lateral / dw, 1/m
  bool valid = false;
};
BodyModuli body_moduli(double stiffness, double area, double axial_per_travel,
                       double lateral_per_travel);

}  // namespace bpm
