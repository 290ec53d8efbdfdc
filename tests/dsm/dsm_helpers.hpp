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

}  // namespace bpm::test
