#include "ste/stiffness_tensor_estimation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "core/error.hpp"
#include "ste/cell_volumes.hpp"
#include "ste/neighbour_stiffness.hpp"

namespace bpm::ste {
namespace {

constexpr const char* kWhere = "stiffness tensor estimation";

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

void validate(const Model& model, const SteOptions& o) {
  if (model.particles.size() == 0) throw InputError(kWhere, "the model has no particles", "load or generate a structure");
  if (!(norm(o.axis) > 0.0) || !std::isfinite(norm(o.axis))) throw InputError(kWhere, "the axis is zero or not finite", "give a direction, e.g. [0, 0, 1]");
  if (o.hull_planes < 3) throw InputError(kWhere, "hull_planes must be >= 3");
  if (o.geometry_directions < 3) throw InputError(kWhere, "geometry_directions must be >= 3");
  if (!(o.singular_tolerance > 0.0 && o.singular_tolerance < 1.0)) throw InputError(kWhere, "singular_tolerance must lie in (0, 1)");
  if (o.share.parts < 1 || o.share.part < 0 || o.share.part >= o.share.parts || (o.share.parts > 1 && !o.sum_over_shares)) {
    throw std::invalid_argument("ste: a work share needs 0 <= part < parts and the sum over the shares");
  }
  if (o.layered && !(o.layer_height_diameters > 0.0)) throw InputError(kWhere, "the layer height must be > 0", "2 diameters as Jarolin");
  if (o.local_map && !(o.local_diameter_factor > 0.0)) throw InputError(kWhere, "the local sphere diameter must be > 0", "3 diameters as Jarolin");
}

/// sum V^n C^n over the used particles in blocks of fixed size, then the blocks in order: the same
/// sums for any thread count.
void volume_average(const ParticleTensors& t, const std::vector<double>& volume, Voigt6& weighted, double& total) {
  constexpr std::size_t kBlock = 4096;
  const std::size_t n = volume.size(), blocks = (n + kBlock - 1) / kBlock;
  std::vector<Voigt6> block_sum(blocks, Voigt6::Zero());
  std::vector<double> block_volume(blocks, 0.0);
#pragma omp parallel for schedule(static) if (blocks > 1)
  for (std::int64_t b = 0; b < static_cast<std::int64_t>(blocks); ++b) {
    const auto k = static_cast<std::size_t>(b);
    for (std::size_t i = k * kBlock; i < std::min(n, (k + 1) * kBlock); ++i) {
      if (t.use[i] != ParticleUse::used) continue;
      block_sum[k] += volume[i] * t.stiffness[i];
      block_volume[k] += volume[i];
    }
  }
  weighted.setZero();
  total = 0.0;
  for (std::size_t k = 0; k < blocks; ++k) {
    weighted += block_sum[k];
    total += block_volume[k];
  }
}

}  // namespace

VolumeMethod parse_volume_method(std::string_view name, std::string_view where) {
  if (name == "voronoi") return VolumeMethod::voronoi;
  if (name == "solid_fraction" || name == "solid-fraction") return VolumeMethod::solid_fraction;
  throw InputError(std::string(where), "unknown volume method '" + std::string(name) + "'",
                   "use voronoi or solid_fraction");
}

SteResult estimate_stiffness(const Model& model, const SteOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  validate(model, o);
  const ParticleStore& p = model.particles;
  SteResult r;
  r.axis = o.axis / norm(o.axis);
  r.particles = p.size();
  r.sample = measure_sample(p, r.axis, o.geometry_directions);
  r.solid_fraction = solid_fraction(p, r.sample.length * r.sample.area);

  // 1. Volumes.
  auto t = std::chrono::steady_clock::now();
  if (o.volumes == VolumeMethod::voronoi) {
    r.particle_volume = voronoi_volumes(p, sample_hull(p, r.axis, o.hull_planes), o.share);
    if (o.share.parts > 1) o.sum_over_shares(r.particle_volume);
  } else {
    r.particle_volume = solid_fraction_volumes(p, r.sample.length * r.sample.area);
  }
  for (const double v : r.particle_volume) r.volume_total += v;
  r.parts.volumes = seconds_since(t);

  // 2. Per-particle tensors.
  t = std::chrono::steady_clock::now();
  const NeighbourStiffness neighbours(model, o.include_contacts.value_or(model.contacts.active()));
  r.bonds = neighbours.intact_bonds();
  r.contacts = neighbours.contacts();
  ParticleTensors tensors = particle_stiffness_tensors(neighbours, r.particle_volume, o.fluctuation, o.singular_tolerance);
  r.used = tensors.used;
  r.excluded_singular = tensors.singular;
  r.excluded_no_volume = tensors.no_volume;
  r.parts.tensors = seconds_since(t);

  // 3-4. The average, its constants and the sample stiffness.
  t = std::chrono::steady_clock::now();
  Voigt6 weighted;
  volume_average(tensors, r.particle_volume, weighted, r.volume_used);
  const Voigt6 raw = r.volume_used > 0.0 ? Voigt6(weighted / r.volume_used) : Voigt6::Zero();
  r.stiffness = 0.5 * (raw + raw.transpose());
  const double largest = raw.cwiseAbs().maxCoeff();
  r.asymmetry = largest > 0.0 ? (raw - raw.transpose()).cwiseAbs().maxCoeff() / largest : 0.0;
  r.constants = engineering_constants(r.stiffness);
  r.youngs_modulus_axis = directional_modulus(r.stiffness, r.axis);
  r.stiffness_uniform = r.youngs_modulus_axis * r.sample.area / r.sample.length;
  if (o.layered) {
    double mean_radius = 0.0;
    for (const double radius : p.radius) mean_radius += radius;
    mean_radius /= static_cast<double>(p.size());
    r.layered = layered_stiffness(p, tensors, r.particle_volume, r.axis, r.sample,
                                  o.layer_height_diameters * 2.0 * mean_radius);
  }
  if (o.walls) {
    r.walls = wall_series(p, r.axis, r.sample, r.layered ? r.layered->stiffness : r.stiffness_uniform, *o.walls);
  }
  r.parts.average = seconds_since(t);

  // 5. Local map.
  if (o.local_map) {
    t = std::chrono::steady_clock::now();
    r.local = local_stiffness_map(p, tensors, r.particle_volume, o.local_diameter_factor, o.local_own_diameter);
    r.parts.local_map = seconds_since(t);
  }
  r.particle_stiffness = std::move(tensors.stiffness);
  r.particle_use = std::move(tensors.use);
  r.coordination = std::move(tensors.coordination);
  r.seconds = seconds_since(start);
  return r;
}

}  // namespace bpm::ste
