#include "ste/elastic_constants.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <cmath>

namespace bpm::ste {
namespace {

constexpr double kZeroEigenvalue = 1e-12;  // relative to the largest |eigenvalue|
constexpr double kNullComponent = 1e-8;    // relative part of a stress in the null space

/// 1 / (u^T C^+ u) if u lies in the range of C (within kNullComponent), else 0.
struct PseudoInverse {
  Eigen::SelfAdjointEigenSolver<Voigt6> eigen;
  double tolerance = 0.0;

  explicit PseudoInverse(const Voigt6& c) : eigen(0.5 * (c + c.transpose())) {
    tolerance = kZeroEigenvalue * eigen.eigenvalues().cwiseAbs().maxCoeff();
  }
  bool kept(int k) const { return std::abs(eigen.eigenvalues()(k)) > tolerance && tolerance > 0.0; }

  Voigt6 inverse() const {
    Voigt6 s = Voigt6::Zero();
    for (int k = 0; k < 6; ++k) {
      if (!kept(k)) continue;
      const Voigt6Vector v = eigen.eigenvectors().col(k);
      s += (v * v.transpose()) / eigen.eigenvalues()(k);
    }
    return s;
  }

  double modulus(const Voigt6Vector& u) const {
    double compliance = 0.0, null_part = 0.0;
    for (int k = 0; k < 6; ++k) {
      const double p = eigen.eigenvectors().col(k).dot(u);
      if (kept(k)) {
        compliance += p * p / eigen.eigenvalues()(k);
      } else {
        null_part += p * p;
      }
    }
    if (null_part > kNullComponent * kNullComponent * u.squaredNorm() || compliance == 0.0) return 0.0;
    return 1.0 / compliance;
  }
};

Voigt6Vector unit(int i) { return Voigt6Vector::Unit(i); }

}  // namespace

Voigt6 compliance(const Voigt6& c) { return PseudoInverse(c).inverse(); }

EngineeringConstants engineering_constants(const Voigt6& c) {
  const PseudoInverse p(c);
  const Voigt6 s = p.inverse();
  EngineeringConstants e;
  e.E_x = p.modulus(unit(0));
  e.E_y = p.modulus(unit(1));
  e.E_z = p.modulus(unit(2));
  auto nu = [&](int i, int j) { return s(i, i) != 0.0 ? -s(j, i) / s(i, i) : 0.0; };
  e.nu_xy = nu(0, 1);
  e.nu_xz = nu(0, 2);
  e.nu_yx = nu(1, 0);
  e.nu_yz = nu(1, 2);
  e.nu_zx = nu(2, 0);
  e.nu_zy = nu(2, 1);
  e.G_yz = p.modulus(unit(3));
  e.G_xz = p.modulus(unit(4));
  e.G_xy = p.modulus(unit(5));
  return e;
}

double directional_modulus(const Voigt6& c, const Vec3& axis) {
  return PseudoInverse(c).modulus(uniaxial_stress(axis / norm(axis)));
}

double directional_poissons_ratio(const Voigt6& c, const Vec3& axis) {
  const Voigt6Vector sigma = uniaxial_stress(axis / norm(axis));
  const Voigt6Vector e = PseudoInverse(c).inverse() * sigma;  // gamma = 2 eps: a.eps.a = e . sigma
  const double along = e.dot(sigma);
  return along > 0.0 ? -(e(0) + e(1) + e(2) - along) / (2.0 * along) : 0.0;
}

Vec3 axis_moduli(const Voigt6& c) {
  const Voigt6 sym = 0.5 * (c + c.transpose());
  const Eigen::LLT<Voigt6> llt(sym);
  if (llt.info() == Eigen::Success) {
    const Eigen::Matrix<double, 6, 3> s = llt.solve(Voigt6::Identity().leftCols<3>());
    return {1.0 / s(0, 0), 1.0 / s(1, 1), 1.0 / s(2, 2)};
  }
  const PseudoInverse p(sym);
  return {p.modulus(unit(0)), p.modulus(unit(1)), p.modulus(unit(2))};
}

}  // namespace bpm::ste
