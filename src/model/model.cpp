#include "model/model.hpp"

namespace bpm {

void Model::fix(std::int32_t p, const Vec3& translation_fixed, const Vec3& rotation_fixed) {
  for (int d = 0; d < 3; ++d) {
    if (translation_fixed[d] != 0.0) {
      particles.translation_free[p][d] = 0.0;
      particles.velocity[p][d] = 0.0;
    }
    if (rotation_fixed[d] != 0.0) {
      particles.rotation_free[p][d] = 0.0;
      particles.angular_velocity[p][d] = 0.0;
    }
  }
}

}  // namespace bpm
