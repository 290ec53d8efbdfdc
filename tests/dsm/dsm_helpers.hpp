#pragma once
// A bonded cubic lattice set up for a compression along z between frictionless steel platens, as
// the DSM and the DEM see it.
#include "compress/platen_loading.hpp"
#include "dem/dem_helpers.hpp"

namespace bpm::test {

/// Contact materials: 0 = the particles' (E = 1e9 Pa), 1 = steel platens (E = 200 GPa); no
/// particle-particle contacts.
inline void add_platen_materials(Model& model) {
  ContactMaterial grain{"grain", ContactLaw::hertz_mindlin, 1e9, 0.25};
  ContactMaterial steel{"steel", ContactLaw::hertz_mindlin, 200e9, 0.3};
  model.contacts.materials = {grain, steel};
}

inline UniaxialCompression compression_along_z(double strain) {
  UniaxialCompression s;
  s.platen_material = 1;
  s.strain_rate = 1.0;
  s.target_strain = strain;
  s.fit_from = 0.2;
  return s;
}

/// The platen loading with the whole bottom and top layers (z index 0 and nz - 1) as the sets.
inline PlatenLoading layer_loading(const Model& model, int nz, double strain) {
  PlatenLoading load = make_platen_loading(model, compression_along_z(strain));
  load.bottom.clear();
  load.top.clear();
  for (std::size_t i = 0; i < model.particles.size(); ++i) {
    const auto k = static_cast<int>(i) % nz;  // cubic_lattice numbers particles (i * ny + j) * nz + k
    if (k == 0) load.bottom.push_back(static_cast<std::int32_t>(i));
    if (k == nz - 1) load.top.push_back(static_cast<std::int32_t>(i));
  }
  return load;
}

/// A disordered bonded sample with flat ends: a simple cubic lattice (spacing 2R, TBBM steel bonds,
/// r_b = 0.8 R) whose particles are jittered by up to jitter * R in every direction, except along z
/// in the bottom and top layers, so that make_platen_loading finds the whole end layers.
inline Model flat_ended_lattice(int nx, int ny, int nz, double radius, double jitter, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Model model;
  auto index = [&](int i, int j, int k) { return static_cast<std::int32_t>((i * ny + j) * nz + k); };
  for (int i = 0; i < nx; ++i) {
    for (int j = 0; j < ny; ++j) {
      for (int k = 0; k < nz; ++k) {
        const double dz = (k == 0 || k == nz - 1) ? 0.0 : jitter * radius * u(rng);
        const Vec3 x{2.0 * radius * i + jitter * radius * u(rng), 2.0 * radius * j + jitter * radius * u(rng),
                     2.0 * radius * k + dz};
        model.particles.add(index(i, j, k), x, radius, 7850.0);
      }
    }
  }
  bond_lattice_neighbours(model, nx, ny, nz);
  model.finalize();
  add_platen_materials(model);
  return model;
}

}  // namespace bpm::test
