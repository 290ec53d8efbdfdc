#include "model/particle_store.hpp"

#include <numbers>

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

}  // namespace bpm
