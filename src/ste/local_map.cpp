#include "ste/local_map.hpp"

#include <algorithm>

#include "core/parallel.hpp"
#include "ste/elastic_constants.hpp"
#include "spatial/cell_grid.hpp"

namespace bpm::ste {

LocalMap local_stiffness_map(const ParticleStore& p, const ParticleTensors& tensors, const std::vector<double>& volume,
                             double diameter_factor, bool own_diameter) {
  const std::size_t n_particles = p.size();
  const auto n = static_cast<std::int64_t>(n_particles);
  LocalMap map;
  map.modulus.assign(n_particles, {});
  map.valid.assign(n_particles, 0);
  map.excess.assign(n_particles, {});
  if (n_particles == 0) return map;
  double mean_radius = 0.0, max_radius = 0.0;
  Aabb box{p.position[0], p.position[0]};
  for (std::size_t i = 0; i < n_particles; ++i) {
    mean_radius += p.radius[i];
    max_radius = std::max(max_radius, p.radius[i]);
    for (int d = 0; d < 3; ++d) {
      box.min[d] = std::min(box.min[d], p.position[i][d]);
      box.max[d] = std::max(box.max[d], p.position[i][d]);
    }
  }
  mean_radius /= static_cast<double>(n_particles);
  map.sphere_diameter = diameter_factor * 2.0 * mean_radius;
  // Sphere radius factor * d / 2 (d = 2 R): factor * R.
  auto sphere_radius = [&](std::size_t i) { return diameter_factor * (own_diameter ? p.radius[i] : mean_radius); };
  const double reach = diameter_factor * (own_diameter ? max_radius : mean_radius);
  CellGrid grid(box, reach, 2 * n_particles + 1);
  grid.build(p.position);

#pragma omp parallel for schedule(static) if (n >= kParallelMinItems)
  for (std::int64_t k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(k);
    const Vec3 xi = p.position[i];
    const double r2 = sphere_radius(i) * sphere_radius(i);
    Voigt6 sum = Voigt6::Zero();
    double weight = 0.0;
    grid.for_each_near(xi, [&](std::int32_t j) {
      const auto m = static_cast<std::size_t>(j);
      if (tensors.use[m] != ParticleUse::used || norm2(p.position[m] - xi) > r2) return;
      sum += volume[m] * tensors.stiffness[m];
      weight += volume[m];
    });
    if (weight > 0.0) {
      map.modulus[i] = axis_moduli(sum / weight);
      map.valid[i] = 1;
    }
  }
  // The mean in particle order (a fixed order, whatever the threads).
  Vec3 total;
  for (std::size_t i = 0; i < n_particles; ++i) {
    if (!map.valid[i]) continue;
    total += map.modulus[i];
    ++map.valid_count;
  }
  if (map.valid_count == 0) return map;
  map.mean = total / static_cast<double>(map.valid_count);
  for (std::size_t i = 0; i < n_particles; ++i) {
    if (!map.valid[i]) continue;
    for (int d = 0; d < 3; ++d) {
      map.excess[i][d] = map.mean[d] != 0.0 ? (map.modulus[i][d] - map.mean[d]) / map.mean[d] : 0.0;
    }
  }
  return map;
}

}  // namespace bpm::ste
