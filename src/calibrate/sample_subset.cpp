#include "calibrate/sample_subset.hpp"

#include <numbers>

#include "compress/sample_geometry.hpp"

namespace bpm {

Model model_subset(const Model& model, const std::vector<bool>& keep) {
  const ParticleStore& p = model.particles;
  Model out;
  out.gravity = model.gravity;
  out.damping = model.damping;
  out.contacts = model.contacts;
  out.walls = model.walls;
  std::vector<std::int32_t> index(p.size(), -1);
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!keep[i]) continue;
    const double volume = 4.0 / 3.0 * std::numbers::pi * p.radius[i] * p.radius[i] * p.radius[i];
    index[i] = out.particles.add(p.id[i], p.reference_position[i], p.radius[i], p.mass[i] / volume, p.material[i]);
    out.particles.translation_free.back() = p.translation_free[i];
    out.particles.rotation_free.back() = p.rotation_free[i];
  }
  const BondStore& b = model.bonds;
  for (std::size_t i = 0; i < b.size(); ++i) {
    const auto a = index[b.alpha[i]], c = index[b.beta[i]];
    if (a < 0 || c < 0 || !b.intact[i]) continue;
    out.bonds.add(a, c, {b.stiffness[i], b.arm_offset[i]}, b.radius[i], b.rest_length[i], b.material[i]);
    out.bonds.strength.back() = b.strength[i];
  }
  out.finalize();
  return out;
}

Model lower_part(const Model& model, const Vec3& axis, double fraction) {
  const Vec3 a = axis / norm(axis);
  const SampleGeometry g = measure_sample(model.particles, a);
  const double limit = g.bottom + fraction * g.length;
  std::vector<bool> keep(model.particles.size());
  for (std::size_t i = 0; i < keep.size(); ++i) keep[i] = dot(model.particles.reference_position[i], a) <= limit;
  return model_subset(model, keep);
}

}  // namespace bpm
