#pragma once
// Samples for the STE tests: a simple cubic lattice with bond stiffnesses given directly (k_n, k_s
// per bond, so the analytic lattice tensor is known), and a relaxed random packing in a box bonded
// within a contact radius (a small Jarolin case 1), plus tensor helpers.
#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <functional>
#include <random>

#include "bonds/bond_model.hpp"
#include "model/model.hpp"
#include "ste/voigt.hpp"
#include "structure/bonding.hpp"
#include "structure/container.hpp"
#include "structure/packing.hpp"

namespace bpm::test {

struct Lattice {
  int nx = 0, ny = 0, nz = 0;
  double spacing = 0.0;  ///< L, m (radius L/2: neighbours touch)
  std::int32_t index(int i, int j, int k) const { return static_cast<std::int32_t>((i * ny + j) * nz + k); }
};

/// Stiffness of the bond between (i,j,k) and the next particle along `direction` (0 x, 1 y, 2 z).
using LatticeBondRule = std::function<BondStiffness(int i, int j, int k, int direction)>;

/// nx*ny*nz particles on a simple cubic lattice of spacing L at the origin, nearest neighbours
/// bonded with the stiffness the rule gives (k_tor, k_ben do not enter the STE), finalised.
inline Model lattice_model(const Lattice& g, const LatticeBondRule& rule) {
  Model model;
  for (int i = 0; i < g.nx; ++i)
    for (int j = 0; j < g.ny; ++j)
      for (int k = 0; k < g.nz; ++k) model.particles.add(g.index(i, j, k), {g.spacing * i, g.spacing * j, g.spacing * k}, 0.5 * g.spacing, 2500.0);
  auto bond = [&](std::int32_t a, std::int32_t b, const BondStiffness& k) {
    model.bonds.add(a, b, BondConstants{k, 0.0}, 0.25 * g.spacing, g.spacing);
  };
  for (int i = 0; i < g.nx; ++i)
    for (int j = 0; j < g.ny; ++j)
      for (int k = 0; k < g.nz; ++k) {
        if (i + 1 < g.nx) bond(g.index(i, j, k), g.index(i + 1, j, k), rule(i, j, k, 0));
        if (j + 1 < g.ny) bond(g.index(i, j, k), g.index(i, j + 1, k), rule(i, j, k, 1));
        if (k + 1 < g.nz) bond(g.index(i, j, k), g.index(i, j, k + 1), rule(i, j, k, 2));
      }
  model.finalize();
  return model;
}

inline Model lattice_model(const Lattice& g, double k_n, double k_s) {
  return lattice_model(g, [&](int, int, int, int) { return BondStiffness{k_n, k_s, 1e-3, 1e-3}; });
}

/// A relaxed random packing of about `count` particles (R = 0.1 mm +- 5 %, porosity 0.45) in a cube,
/// bonded where the contact radii 1.12 R touch (coordination ~8), TBBM bonds with E_b = 1 GPa.
inline Model random_packing(std::int64_t count, std::uint64_t seed) {
  const double r = 1e-4, porosity = 0.45;
  const double side = std::cbrt(static_cast<double>(count) * (4.0 / 3.0) * 3.14159265358979 * r * r * r / (1.0 - porosity));
  const BoxContainer box({0, 0, 0}, {side, side, side});
  std::mt19937_64 rng(seed);
  Packing packing = insert_random(box, RadiusDistribution::normal(r, 0.05 * r), {porosity, 0}, rng);
  relax(packing, box, {0.01, 20000});
  BondCriterion criterion;
  criterion.contact_radius_multiplier = 1.12;
  const auto pairs = find_bond_pairs(packing, box.bounds(), criterion);
  Model model;
  for (std::size_t i = 0; i < packing.size(); ++i) {
    model.particles.add(static_cast<std::int64_t>(i), packing.position[i], packing.radius[i], 2500.0);
  }
  BondMaterial material;
  material.model = "tbbm";
  material.youngs_modulus = 1e9;
  material.poisson_ratio = 0.25;
  for (const auto& [a, b] : pairs) {
    const double ra = packing.radius[static_cast<std::size_t>(a)], rb = packing.radius[static_cast<std::size_t>(b)];
    const double length = norm(packing.position[static_cast<std::size_t>(b)] - packing.position[static_cast<std::size_t>(a)]);
    const BondGeometry geometry{std::min(ra, rb), length, ra, rb};
    model.bonds.add(a, b, make_bond_constants(material, geometry), geometry.radius, length);
  }
  model.finalize();
  return model;
}

/// The Voigt stiffness as a fourth-order tensor (engineering-shear Voigt: C_ijkl = C_IJ) rotated by
/// Q (x' = Q x) and written back in Voigt form.
inline ste::Voigt6 rotate_voigt(const ste::Voigt6& c, const Eigen::Matrix3d& q) {
  static constexpr int kVoigt[3][3] = {{0, 5, 4}, {5, 1, 3}, {4, 3, 2}};
  ste::Voigt6 out = ste::Voigt6::Zero();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l) {
          double sum = 0.0;
          for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b)
              for (int c2 = 0; c2 < 3; ++c2)
                for (int d = 0; d < 3; ++d) sum += q(i, a) * q(j, b) * q(k, c2) * q(l, d) * c(kVoigt[a][b], kVoigt[c2][d]);
          out(kVoigt[i][j], kVoigt[k][l]) = sum;
        }
  return out;
}

}  // namespace bpm::test
