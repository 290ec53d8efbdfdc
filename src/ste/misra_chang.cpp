#include "ste/misra_chang.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include "core/parallel.hpp"

namespace bpm::ste {
namespace {

using Matrix3 = Eigen::Matrix3d;

/// (sum_m K^nm)^-1, the pseudo-inverse when singular; returns whether it is regular.
bool invert_sum(const Matrix3& k_sum, double tolerance, Matrix3& inverse) {
  Eigen::SelfAdjointEigenSolver<Matrix3> values;
  values.computeDirect(k_sum, Eigen::EigenvaluesOnly);
  const double largest = values.eigenvalues()(2), smallest = values.eigenvalues()(0);
  if (largest > 0.0 && smallest > tolerance * largest) {
    inverse = k_sum.inverse();
    return true;
  }
  inverse.setZero();
  if (!(largest > 0.0)) return false;
  const Eigen::SelfAdjointEigenSolver<Matrix3> eigen(k_sum);
  const double cut = tolerance * eigen.eigenvalues()(2);
  for (int k = 0; k < 3; ++k) {
    const double l = eigen.eigenvalues()(k);
    if (l > cut) inverse += (eigen.eigenvectors().col(k) * eigen.eigenvectors().col(k).transpose()) / l;
  }
  return false;
}

}  // namespace

ParticleTensors particle_stiffness_tensors(const NeighbourStiffness& nb, const std::vector<double>& volume,
                                           Fluctuation fluctuation, double tolerance) {
  const std::size_t n_particles = nb.particle_count();
  const auto n = static_cast<std::int64_t>(n_particles);
  const bool fluctuating = fluctuation != Fluctuation::affine, paper = fluctuation == Fluctuation::paper;
  ParticleTensors out;
  out.stiffness.assign(n_particles, Voigt6::Zero());
  out.use.assign(n_particles, ParticleUse::used);
  out.coordination.assign(n_particles, 0);

  // Pass 1: P^n = sum_m K D, (sum K)^-1 and Gamma^n = (sum K)^-1 P^n (Jarolin Eq. 23).
  std::vector<StrainMap> p_sum(fluctuating ? n_particles : 0), gamma(fluctuating ? n_particles : 0);
  std::vector<Matrix3> inverse(paper ? n_particles : 0);
  std::vector<std::uint8_t> regular(n_particles, 0);
#pragma omp parallel for schedule(static) if (n >= kParallelMinItems)
  for (std::int64_t i = 0; i < n; ++i) {
    const auto p = static_cast<std::size_t>(i);
    Matrix3 k_sum = Matrix3::Zero();
    StrainMap k_d = StrainMap::Zero();
    std::int32_t count = 0;
    nb.for_each(p, [&](std::int32_t, const Vec3& d, const Matrix3& k) {
      k_sum += k;
      if (fluctuating) k_d += times_affine_map(k, d);
      ++count;
    });
    out.coordination[p] = count;
    Matrix3 inv;
    regular[p] = invert_sum(k_sum, tolerance, inv) ? 1 : 0;
    if (fluctuating) {
      p_sum[p] = k_d;
      gamma[p].noalias() = inv * k_d;
    }
    if (paper) inverse[p] = inv;
  }

  // Pass 2: C^n = 1/(2 V^n) sum_m D^T K (D - Gamma^n - Gamma^n_hat + Gamma^m) (Jarolin Eq. 32),
  // as sum_m D^T M_m - P^T (Gamma^n + Gamma^n_hat) with M_m = K (D + Gamma^m), since
  // sum_m D^T K Gamma^n = P^T Gamma^n; and Gamma^n_hat = (sum K)^-1 Q, Q = sum_m K Gamma^m
  // = sum_m M_m - P.
#pragma omp parallel for schedule(static) if (n >= kParallelMinItems)
  for (std::int64_t i = 0; i < n; ++i) {
    const auto p = static_cast<std::size_t>(i);
    if (!regular[p]) {
      out.use[p] = ParticleUse::singular;
      continue;
    }
    if (!(volume[p] > 0.0)) {
      out.use[p] = ParticleUse::no_volume;
      continue;
    }
    Voigt6 x = Voigt6::Zero();
    StrainMap m_sum = StrainMap::Zero();
    nb.for_each(p, [&](std::int32_t m, const Vec3& d, const Matrix3& k) {
      if (paper) {
        const StrainMap km = times_affine_map(k, d) + k * gamma[static_cast<std::size_t>(m)];
        x += affine_map_transpose_times(d, km);
        m_sum += km;
      } else {
        x += affine_map_transpose_times(d, times_affine_map(k, d));
      }
    });
    if (fluctuating) {
      StrainMap g = gamma[p];
      if (paper) g.noalias() += inverse[p] * (m_sum - p_sum[p]);
      x.noalias() -= p_sum[p].transpose() * g;
    }
    out.stiffness[p] = x / (2.0 * volume[p]);
  }
  for (const ParticleUse u : out.use) {
    out.used += u == ParticleUse::used;
    out.singular += u == ParticleUse::singular;
    out.no_volume += u == ParticleUse::no_volume;
  }
  return out;
}

}  // namespace bpm::ste
