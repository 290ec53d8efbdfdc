#include "compress/kinematic_compression.hpp"

#include <chrono>
#include <cmath>

#include "core/error.hpp"
#include "dem/contact_time_step.hpp"

namespace bpm {

KinematicCompressionResult run_kinematic_compression(const Model& original, const PlatenLoading& load,
                                                     const KinematicCompressionSettings& s) {
  const auto start = std::chrono::steady_clock::now();
  Model model = original;
  model.walls.clear();
  model.contacts.particle_particle = false;  // the bonds only, as the linear DSM
  model.damping.particle = s.particle_damping;
  const Vec3 lateral_mask = load.frictionless ? Vec3{} : Vec3{1.0, 1.0, 1.0};
  Vec3 axial_mask;
  for (int k = 0; k < 3; ++k) axial_mask[k] = load.axis[k] != 0.0 ? 1.0 : 0.0;
  for (const auto p : load.bottom) model.fix(p, axial_mask + lateral_mask, {});
  const double speed = s.strain_rate * load.sample.length;
  for (const auto p : load.top) {
    model.fix(p, axial_mask + lateral_mask, {});
    model.particles.velocity[p] = -speed * load.axis;
  }

  KinematicCompressionResult r;
  r.time_step = s.safety_factor * stability_limit(model);
  Simulation sim(model, r.time_step);
  const auto ramp_steps = static_cast<std::int64_t>(std::ceil(load.displacement / speed / r.time_step));
  // The last ramp step lands exactly on the platen displacement.
  const double last_speed = (load.displacement - speed * r.time_step * static_cast<double>(ramp_steps - 1)) / r.time_step;
  for (std::int64_t k = 0; k < ramp_steps; ++k) {
    if (k == ramp_steps - 1) {
      for (const auto p : load.top) model.particles.velocity[p] = -last_speed * load.axis;
    }
    sim.step();
  }
  for (const auto p : load.top) model.particles.velocity[p] = {};
  while (sim.steps() < s.max_steps) {
    sim.step();
    if (sim.max_speed() < s.rest_speed) {
      r.at_rest = true;
      break;
    }
  }
  const ParticleStore& p = model.particles;
  // The platens' forces are the opposite of what the sample exerts on its end particles.
  for (const auto i : load.top) r.force_top += dot(p.force[i], load.axis);
  for (const auto i : load.bottom) r.force_bottom -= dot(p.force[i], load.axis);
  r.stiffness = r.force_top / load.displacement;
  r.youngs_modulus = r.stiffness * load.sample.length / load.sample.area;
  r.displacement.resize(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) r.displacement[i] = p.position[i] - p.reference_position[i];
  r.max_speed = sim.max_speed();
  r.steps = sim.steps();
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace bpm
