#include "dsm/platen_springs.hpp"

#include <algorithm>
#include <string>

#include "core/error.hpp"

namespace bpm {

double mean_particle_radius(const ParticleStore& particles) {
  double mean = 0.0;
  for (const double r : particles.radius) mean += r / static_cast<double>(particles.size());
  return mean;
}

double listing_slack(const Model& model) {
  return 0.1 * mean_particle_radius(model.particles);
}

double platen_listing_band(const Model& model, const PlatenLoading& load) {
  return load.displacement + listing_slack(model);
}

double contact_listing_band(const Model& model, const PlatenLoading& load) {
  // Two neighbours approach by about the strain times their distance, which the platen travel
  // bounds but far from tightly in a long sample: on a 777,457-particle cylinder the travel is
  // 3.9 radii, and listing every pair that close made the 6-DOF matrix exceed 2^31 entries.
  constexpr double kLocalStrainFactor = 20.0;  // local strain over the sample's, assumed at most
  const double r_max =
      *std::max_element(model.particles.radius.begin(), model.particles.radius.end());
  const double strain = load.displacement / load.sample.length;
  return std::min(load.displacement, kLocalStrainFactor * strain * 2.0 * r_max) +
         listing_slack(model);
}

std::vector<StaticContact> platen_contacts(const Model& model, const PlatenLoading& load, const DofConstraints& c,
                                           double band) {
  const ParticleStore& p = model.particles;
  std::vector<StaticContact> out;
  auto detached = [&](std::size_t i) {  // every DOF held (platen_constraints.hpp)
    const auto first = c.fixed.begin() + static_cast<std::ptrdiff_t>(c.dofs * i);
    return std::all_of(first, first + c.dofs, [](std::uint8_t f) { return f != 0; });
  };
  std::size_t bottom = 0, top = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (detached(i)) continue;
    const auto index = static_cast<std::int32_t>(i);
    if (load.gap_bottom[i] < band) {
      out.push_back(wall_contact(model, index, load.platen_material, load.axis, load.gap_bottom[i], Vec3{}));
      ++bottom;
    }
    if (load.gap_top[i] < band) {
      out.push_back(wall_contact(model, index, load.platen_material, -1.0 * load.axis, load.gap_top[i], -1.0 * load.axis));
      ++top;
    }
  }
  if (bottom == 0 || top == 0) {
    throw InputError("compression", std::string("no particle of the loaded sample comes within reach of the ") +
                                        (bottom == 0 ? "lower" : "upper") + " platen",
                     "check the structure and the compression axis: the bonded sample must touch both platens");
  }
  return out;
}

}  // namespace bpm
