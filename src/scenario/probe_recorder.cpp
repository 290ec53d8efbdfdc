#include "scenario/probe_recorder.hpp"

#include <fmt/core.h>

namespace bpm {

ProbeRecorder::ProbeRecorder(std::vector<Probe> probes) : probes_(std::move(probes)) {
  header_ = "time";
  for (const Probe& probe : probes_) {
    for (const char* quantity : {"u", "v", "f"}) {
      for (const char* axis : {"x", "y", "z"}) header_ += fmt::format(",{}_{}{}", probe.name, quantity, axis);
    }
  }
  header_ += '\n';
}

std::string ProbeRecorder::row(double t, const ParticleStore& p) const {
  std::string s = fmt::format("{:.12g}", t);
  for (const Probe& probe : probes_) {
    Vec3 u, v, f;
    for (const std::int32_t i : probe.particles) {
      u += p.position[i] - p.reference_position[i];
      v += p.velocity[i];
      f += p.force[i];
    }
    // Probes are never empty (the reader refuses empty sets), so the mean is defined.
    const double inv = 1.0 / static_cast<double>(probe.particles.size());
    for (const Vec3& q : {u * inv, v * inv, f}) s += fmt::format(",{:.12g},{:.12g},{:.12g}", q.x, q.y, q.z);
  }
  s += '\n';
  return s;
}

}  // namespace bpm
