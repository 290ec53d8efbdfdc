#pragma once
// Small models for the DEM tests: a free bonded chain of unequal spheres along a zig-zag line and a
// bonded simple cubic lattice, plus momentum and energy measures.
#include <algorithm>
#include <cstdint>
#include <random>
#include <string>

#include "bonds/bond_model.hpp"
#include "model/model.hpp"
#include "dem/simulation.hpp"

namespace bpm::test {

inline BondMaterial steel_bond(const std::string& key) {
  BondMaterial m;
  m.name = key;
  m.model = key;
  m.youngs_modulus = 200e9;
  m.poisson_ratio = 0.3;
  return m;
}

/// Bonds particles i and j at their current distance, r_b = 0.8 min(R_i, R_j).
inline void bond(Model& model, std::int32_t i, std::int32_t j, const BondMaterial& material) {
  const ParticleStore& p = model.particles;
  const double length = norm(p.position[j] - p.position[i]);
  const BondGeometry g{0.8 * std::min(p.radius[i], p.radius[j]), length, p.radius[i], p.radius[j]};
  model.bonds.add(i, j, make_bond_constants(material, g), g.radius, length);
}

/// n touching spheres (R = 1 mm +- 30 %) along a zig-zag line starting at `origin`, consecutive ones
/// bonded, with random velocities (|v_k| <= v) and angular velocities (|omega_k| <= w); no fixed
/// DOFs, no loads, finalised.
inline Model free_chain(int n, const std::string& key, double v, double w, std::uint64_t seed,
                        const Vec3& origin = {0.02, -0.01, 0.015}) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Model model;
  Vec3 x = origin;
  double previous = 0.0;
  for (int i = 0; i < n; ++i) {
    const double radius = 1e-3 * (1.0 + 0.3 * u(rng));
    if (i > 0) {
      const Vec3 d{1.0, 0.4 * u(rng), 0.4 * u(rng)};
      x += (previous + radius) / norm(d) * d;
    }
    const std::int32_t k = model.particles.add(i, x, radius, 7850.0);
    model.particles.velocity[k] = {v * u(rng), v * u(rng), v * u(rng)};
    model.particles.angular_velocity[k] = {w * u(rng), w * u(rng), w * u(rng)};
    previous = radius;
  }
  const BondMaterial material = steel_bond(key);
  for (std::int32_t i = 0; i + 1 < n; ++i) bond(model, i, i + 1, material);
  model.finalize();
  return model;
}

/// Bonds (TBBM steel) the nearest neighbours of an nx*ny*nz lattice whose particles are numbered
/// (i * ny + j) * nz + k.
inline void bond_lattice_neighbours(Model& model, int nx, int ny, int nz) {
  auto index = [&](int i, int j, int k) { return static_cast<std::int32_t>((i * ny + j) * nz + k); };
  const BondMaterial material = steel_bond("tbbm");
  for (int i = 0; i < nx; ++i) {
    for (int j = 0; j < ny; ++j) {
      for (int k = 0; k < nz; ++k) {
        if (i + 1 < nx) bond(model, index(i, j, k), index(i + 1, j, k), material);
        if (j + 1 < ny) bond(model, index(i, j, k), index(i, j + 1, k), material);
        if (k + 1 < nz) bond(model, index(i, j, k), index(i, j, k + 1), material);
      }
    }
  }
}

/// Simple cubic lattice of nx*ny*nz spheres of radius R at spacing 2R (jittered by `jitter` * R),
/// nearest neighbours bonded (TBBM), random velocities |v_k| <= v and angular velocities <= w.
inline Model cubic_lattice(int nx, int ny, int nz, double radius, double jitter, double v, double w,
                           std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Model model;
  auto index = [&](int i, int j, int k) { return static_cast<std::int32_t>((i * ny + j) * nz + k); };
  for (int i = 0; i < nx; ++i) {
    for (int j = 0; j < ny; ++j) {
      for (int k = 0; k < nz; ++k) {
        const Vec3 x{2.0 * radius * i + jitter * radius * u(rng), 2.0 * radius * j + jitter * radius * u(rng),
                     2.0 * radius * k + jitter * radius * u(rng)};
        const std::int32_t p = model.particles.add(index(i, j, k), x, radius, 7850.0);
        model.particles.velocity[p] = {v * u(rng), v * u(rng), v * u(rng)};
        model.particles.angular_velocity[p] = {w * u(rng), w * u(rng), w * u(rng)};
      }
    }
  }
  bond_lattice_neighbours(model, nx, ny, nz);
  model.finalize();
  return model;
}

inline Vec3 linear_momentum(const ParticleStore& p) {
  Vec3 sum;
  for (std::size_t i = 0; i < p.size(); ++i) sum += p.mass[i] * p.velocity[i];
  return sum;
}

/// Sum over particles of m x cross v + I omega (spheres: isotropic inertia).
inline Vec3 angular_momentum(const ParticleStore& p) {
  Vec3 sum;
  for (std::size_t i = 0; i < p.size(); ++i) {
    sum += p.mass[i] * cross(p.position[i], p.velocity[i]) + p.inertia[i] * p.angular_velocity[i];
  }
  return sum;
}

/// Scales against which momentum round-off is judged: sum of |m v| and of |m x cross v| + |I omega|.
inline double momentum_scale(const ParticleStore& p) {
  double s = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) s += p.mass[i] * norm(p.velocity[i]);
  return s;
}
inline double angular_momentum_scale(const ParticleStore& p) {
  double s = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    s += p.mass[i] * norm(cross(p.position[i], p.velocity[i])) + p.inertia[i] * norm(p.angular_velocity[i]);
  }
  return s;
}

inline double total_energy(const Simulation& sim) {
  const Energies e = sim.energies();
  return e.kinetic + e.elastic;
}

}  // namespace bpm::test
