#include "io/state_csv.hpp"

#include <fmt/core.h>

#include "io/atomic_file.hpp"

namespace bpm {

std::string state_csv(const ParticleStore& p) {
  std::string s = "id,x,y,z,ux,uy,uz,rx,ry,rz,vx,vy,vz,wx,wy,wz,fx,fy,fz\n";
  // 17 significant digits: the file round-trips the doubles exactly, so a deflection read back
  // from it is the simulated one. (fmt::format and append: see vtk_writer.cpp for why not format_to.)
  auto put = [&](const Vec3& v) { s += fmt::format(",{:.17g},{:.17g},{:.17g}", v.x, v.y, v.z); };
  for (std::size_t i = 0; i < p.size(); ++i) {
    s += std::to_string(p.id[i]);
    put(p.position[i]);
    put(p.position[i] - p.reference_position[i]);
    put(rotation_vector(p.orientation[i]));
    put(p.velocity[i]);
    put(p.angular_velocity[i]);
    put(p.force[i]);
    s += '\n';
  }
  return s;
}

void write_state_csv(const std::string& path, const ParticleStore& particles) {
  write_file_atomic(path, state_csv(particles));
}

}  // namespace bpm
