#include "model/particle_store.hpp"

#include <numbers>

#include "core/error.hpp"
#include "model/spatial_order.hpp"

namespace bpm {

std::int32_t ParticleStore::add(std::int64_t user_id, const Vec3& x, double r, double density,
                                std::int32_t mat) {
  const double m = density * 4.0 / 3.0 * std::numbers::pi * r * r * r;
  id.push_back(user_id);
  radius.push_back(r);
  mass.push_back(m);
  inertia.push_back(0.4 * m * r * r);
  material.push_back(mat);
  reference_position.push_back(x);
  position.push_back(x);
  velocity.push_back({});
  angular_velocity.push_back({});
  orientation.push_back({});
  force.push_back({});
  torque.push_back({});
  translation_free.push_back({1, 1, 1});
  rotation_free.push_back({1, 1, 1});
  return static_cast<std::int32_t>(radius.size() - 1);
}

void ParticleStore::reorder(const std::vector<std::int32_t>& old_at) {
  BPM_ASSERT(old_at.size() == size());
  // Every field of the store: a field left out here would silently belong to other particles.
  permute(id, old_at);
  for (auto* field : {&radius, &mass, &inertia}) permute(*field, old_at);
  permute(material, old_at);
  for (auto* field : {&reference_position, &position, &velocity, &angular_velocity, &force, &torque,
                      &translation_free, &rotation_free}) {
    permute(*field, old_at);
  }
  permute(orientation, old_at);
}

}  // namespace bpm
