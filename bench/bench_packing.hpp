#pragma once
// A generated bonded cylinder for the benchmarks, its rows in a chosen order (issue 12: real inputs
// are not stored in lattice order). `bpmkit generate`'s recipe: normal radii R = 0.1 mm +- 5 %,
// porosity 0.4, bonds where 1.12 R touch (~4 bonds per particle), TBBM bonds (E = 2e8 Pa,
// r_b = min(R_i, R_j)), density 1500 kg/m^3. Orders:
//   generated - as the generator writes it (insertion order: random in space)
//   shuffled  - particle and bond rows in a fixed random permutation, as another code might write
//               them
//   morton    - particles sorted along a Morton (Z-order) curve, bonds by their first particle:
//               what a spatially sorted file gives. The particles are in bpmkit's canonical order
//               (model/spatial_order.hpp), which a scenario load gives for any row order
// The particle ids are the generated indices in every order, so the three are the same model.
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <numeric>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "bonds/bond_model.hpp"
#include "model/model.hpp"
#include "model/spatial_order.hpp"
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

/// new_of[old]: the row each generated particle takes in `order`.
inline std::vector<std::int32_t> particle_rows(const bpm::GeneratedStructure& g, RowOrder order) {
  const std::size_t n = g.packing.size();
  std::vector<std::int32_t> old_at(n);  // old_at[row] = generated index
  std::iota(old_at.begin(), old_at.end(), 0);
  if (order == RowOrder::shuffled) {
    std::shuffle(old_at.begin(), old_at.end(), std::mt19937_64(12));
  } else if (order == RowOrder::morton) {
    // The ids are the generated indices: bpmkit's canonical order (what a scenario load gives).
    const std::vector<std::int64_t> ids(old_at.begin(), old_at.end());
    old_at = bpm::canonical_particle_order(g.packing.position, ids);
  }
  return bpm::inverse_permutation(old_at);
}

/// The rows of the packing stored in `order`: the generated particle (= its id) in each particle
/// row, and each bond row's ends as particle rows.
struct Rows {
  std::vector<std::int32_t> particle;
  std::vector<std::pair<std::int32_t, std::int32_t>> bond;
};

inline Rows rows_in(const bpm::GeneratedStructure& g, RowOrder order) {
  const std::vector<std::int32_t> new_of = particle_rows(g, order);
  Rows rows{bpm::inverse_permutation(new_of), {}};
  for (const auto& [i, j] : g.bonds) rows.bond.emplace_back(new_of[i], new_of[j]);
  if (order == RowOrder::shuffled) {
    std::shuffle(rows.bond.begin(), rows.bond.end(), std::mt19937_64(13));
  } else if (order == RowOrder::morton) {
    for (auto& b : rows.bond) b = {std::min(b.first, b.second), std::max(b.first, b.second)};
    std::sort(rows.bond.begin(), rows.bond.end());
  }
  return rows;
}

/// The bonded cylinder as a model (no contacts, walls or damping yet), its rows in `order`.
inline bpm::Model bonded_model(const bpm::GeneratedStructure& g, RowOrder order) {
  const Rows rows = rows_in(g, order);
  bpm::Model m;
  for (const std::int32_t i : rows.particle) {
    m.particles.add(i, g.packing.position[i], g.packing.radius[i], 1500.0, 0);
  }
  bpm::BondMaterial bond;
  bond.model = "tbbm";
  bond.youngs_modulus = 2e8;
  bond.poisson_ratio = 0.25;
  for (const auto& [i, j] : rows.bond) {
    const double length = bpm::norm(m.particles.position[j] - m.particles.position[i]);
    const double r_i = m.particles.radius[i], r_j = m.particles.radius[j];
    const double r_b = std::min(r_i, r_j);
    m.bonds.add(i, j, bpm::make_bond_constants(bond, {r_b, length, r_i, r_j}), r_b, length);
  }
  return m;
}

/// The same model as files, its rows in `order`: particles.csv, bonds.csv (by id) and
/// scenario.yaml in `dir`, the inputs `bpmkit run` reads. Returns the scenario's path.
inline std::string write_scenario(const bpm::GeneratedStructure& g, RowOrder order,
                                  const std::filesystem::path& dir) {
  const Rows rows = rows_in(g, order);
  std::filesystem::create_directories(dir);
  std::string particles = "id,x,y,z,radius\n";
  for (const std::int32_t i : rows.particle) {
    const bpm::Vec3& x = g.packing.position[i];
    particles +=
        fmt::format("{},{},{},{},{}\n", i, x.x, x.y, x.z, g.packing.radius[i]);  // round trip
  }
  std::ofstream(dir / "particles.csv") << particles;
  std::string bonds = "i,j\n";
  for (const auto& [i, j] : rows.bond)
    bonds += fmt::format("{},{}\n", rows.particle[i], rows.particle[j]);
  std::ofstream(dir / "bonds.csv") << bonds;
  std::ofstream(dir / "scenario.yaml") << "particle_materials: {grain: {density: 1500}}\n"
                                          "bond_materials: {beam: {model: tbbm, youngs_modulus: "
                                          "2e8, poisson_ratio: 0.25, radius_multiplier: 1.0}}\n"
                                          "particles: {file: particles.csv}\n"
                                          "bonds: {file: bonds.csv}\n"
                                          "stop: {max_steps: 1}\n";
  return (dir / "scenario.yaml").string();
}

}  // namespace bench
