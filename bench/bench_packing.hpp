#pragma once
// A generated bonded cylinder for the benchmarks, its rows in a chosen order (issue 12: real inputs
// are not stored in lattice order). `bpmkit generate`'s recipe: normal radii R = 0.1 mm +- 5 %,
// porosity 0.4, bonds where 1.12 R touch (~4 bonds per particle), TBBM bonds (E = 2e8 Pa,
// r_b = min(R_i, R_j)), density 1500 kg/m^3. Orders:
//   generated - as the generator writes it (insertion order: random in space)
//   shuffled  - particle and bond rows in a fixed random permutation, as another code might write
//               them
//   morton    - particles sorted along a Morton (Z-order) curve, bonds by their first particle:
//               what a spatially sorted file gives
// The particle ids are the generated indices in every order, so the three are the same model.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "bonds/bond_model.hpp"
#include "dem/model.hpp"
#include "structure/generate.hpp"

namespace bench {

enum class RowOrder { generated = 0, shuffled = 1, morton = 2 };

inline const char* to_string(RowOrder o) {
  return o == RowOrder::generated ? "generated" : o == RowOrder::shuffled ? "shuffled" : "morton";
}

/// The generate spec for `count` particles in a cylinder (height = diameter) at porosity 0.4.
inline std::string cylinder_spec(int count) {
  const double r = 1e-4, solid = count * 4.0 / 3.0 * std::numbers::pi * r * r * r;
  const double radius = std::cbrt(solid / 0.6 / (2.0 * std::numbers::pi));  // V = pi rc^2 * 2 rc
  return "seed: 2020\n"
         "container:\n  cylinder: {radius: " + std::to_string(radius) + ", height: " + std::to_string(2 * radius) +
         "}\n"
         "radii:\n  normal: {mean: 1.0e-4, std: 5.0e-6}\n"
         "packing:\n  count: " + std::to_string(count) + "\n  overlap_tolerance: 0.01\n"
         "bonds:\n  contact_radius_multiplier: 1.12\n  radius_multiplier: 1.0\n"
         "output:\n  vtk: false\n  scenario: false\n";
}

inline bpm::GeneratedStructure generate_cylinder(int count) {
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("bpmkit_bench_" + std::to_string(count) + ".yml");
  std::ofstream(path) << cylinder_spec(count);
  bpm::GeneratedStructure g = bpm::generate_structure(bpm::load_generate_spec(path.string()));
  std::filesystem::remove(path);
  return g;
}

/// Spreads the low 21 bits of v to every third bit (the Morton code's interleave).
inline std::uint64_t spread_bits(std::uint64_t v) {
  v &= 0x1fffff;
  v = (v | v << 32) & 0x1f00000000ffffULL;
  v = (v | v << 16) & 0x1f0000ff0000ffULL;
  v = (v | v << 8) & 0x100f00f00f00f00fULL;
  v = (v | v << 4) & 0x10c30c30c30c30c3ULL;
  v = (v | v << 2) & 0x1249249249249249ULL;
  return v;
}

/// new_of[old]: the row each generated particle takes in `order`.
inline std::vector<std::int32_t> particle_rows(const bpm::GeneratedStructure& g, RowOrder order) {
  const std::size_t n = g.packing.size();
  std::vector<std::int32_t> old_at(n);  // old_at[row] = generated index
  std::iota(old_at.begin(), old_at.end(), 0);
  if (order == RowOrder::shuffled) {
    std::shuffle(old_at.begin(), old_at.end(), std::mt19937_64(12));
  } else if (order == RowOrder::morton) {
    bpm::Vec3 lo = g.packing.position[0], hi = lo;
    for (const bpm::Vec3& p : g.packing.position) {
      for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
    }
    std::vector<std::uint64_t> key(n);
    for (std::size_t i = 0; i < n; ++i) {
      std::uint64_t code = 0;
      for (int k = 0; k < 3; ++k) {
        const double t = (g.packing.position[i][k] - lo[k]) / std::max(hi[k] - lo[k], 1e-300);
        code |= spread_bits(static_cast<std::uint64_t>(t * 2097151.0)) << k;
      }
      key[i] = code;
    }
    std::stable_sort(old_at.begin(), old_at.end(), [&](std::int32_t a, std::int32_t b) { return key[a] < key[b]; });
  }
  std::vector<std::int32_t> new_of(n);
  for (std::size_t row = 0; row < n; ++row) new_of[old_at[row]] = static_cast<std::int32_t>(row);
  return new_of;
}

/// The bonded cylinder as a model (no contacts, walls or damping yet), its rows in `order`.
inline bpm::Model bonded_model(const bpm::GeneratedStructure& g, RowOrder order) {
  const std::vector<std::int32_t> new_of = particle_rows(g, order);
  std::vector<std::int32_t> old_at(new_of.size());
  for (std::size_t i = 0; i < new_of.size(); ++i) old_at[new_of[i]] = static_cast<std::int32_t>(i);
  bpm::Model m;
  for (const std::int32_t i : old_at) {
    m.particles.add(i, g.packing.position[i], g.packing.radius[i], 1500.0, 0);
  }
  std::vector<std::pair<std::int32_t, std::int32_t>> bonds;
  for (const auto& [i, j] : g.bonds) bonds.emplace_back(new_of[i], new_of[j]);
  if (order == RowOrder::shuffled) {
    std::shuffle(bonds.begin(), bonds.end(), std::mt19937_64(13));
  } else if (order == RowOrder::morton) {
    for (auto& b : bonds) b = {std::min(b.first, b.second), std::max(b.first, b.second)};
    std::sort(bonds.begin(), bonds.end());
  }
  bpm::BondMaterial bond;
  bond.model = "tbbm";
  bond.youngs_modulus = 2e8;
  bond.poisson_ratio = 0.25;
  for (const auto& [i, j] : bonds) {
    const double length = bpm::norm(m.particles.position[j] - m.particles.position[i]);
    const double r_i = m.particles.radius[i], r_j = m.particles.radius[j];
    const double r_b = std::min(r_i, r_j);
    m.bonds.add(i, j, bpm::make_bond_constants(bond, {r_b, length, r_i, r_j}), r_b, length);
  }
  return m;
}

}  // namespace bench
