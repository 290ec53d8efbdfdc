#include "compress/platen_loading.hpp"

#include <cmath>

#include "model/contact_material.hpp"
#include "core/error.hpp"

namespace bpm {

PlatenLoading make_platen_loading(const Model& model, const UniaxialCompression& s) {
  PlatenLoading load;
  load.axis = s.axis / norm(s.axis);
  load.sample = measure_sample(model.particles, load.axis);
  load.displacement = s.target_strain * load.sample.length;
  load.platen_material = s.platen_material;
  load.fit_from = s.fit_from;
  load.fit_to = s.fit_to;
  const auto& materials = model.contacts.materials;
  if (s.platen_material < 0 || static_cast<std::size_t>(s.platen_material) >= materials.size()) {
    throw InputError("compression.platen_material", "is not a contact material",
                     "name one of the particle materials with contact properties");
  }
  // What the DEM's walls apply is the grain-platen pair's friction (its mixing rule), not the
  // platen material's own: steel with friction 0 against grains with 0.3 slides with 0.15.
  const ContactTable table(model.contacts);
  load.frictionless = true;
  for (const std::int32_t material : model.particles.material) {
    if (table(material, s.platen_material).friction != 0.0) load.frictionless = false;
  }

  // A particle belongs to a platen's set when its gap closes before the middle of the DEM's fit
  // window; the band never falls below a round-off tolerance, so the extreme particles always count.
  const double band = std::max(0.5 * (s.fit_from + s.fit_to) * load.displacement, 1e-9 * load.sample.length);
  const ParticleStore& p = model.particles;
  load.gap_bottom.resize(p.size());
  load.gap_top.resize(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double centre = dot(p.position[i], load.axis);
    load.gap_bottom[i] = centre - p.radius[i] - load.sample.bottom;
    load.gap_top[i] = load.sample.top - (centre + p.radius[i]);
    const auto index = static_cast<std::int32_t>(i);
    if (load.gap_bottom[i] <= band) load.bottom.push_back(index);
    if (load.gap_top[i] <= band) load.top.push_back(index);
  }
  return load;
}

}  // namespace bpm
