#include "dem/simulation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>
#include <utility>

#include "bonds/bond_law.hpp"
#include "core/error.hpp"
#include "core/parallel.hpp"
#include "dem/bond_forces.hpp"
#include "dem/step_monitor.hpp"

namespace bpm {

std::string_view to_string(StopReason reason) {
  switch (reason) {
    case StopReason::end_time: return "end_time";
    case StopReason::max_steps: return "max_steps";
    case StopReason::rest: return "rest";
    case StopReason::interrupted: return "interrupted";
  }
  return "unknown";
}

Simulation::Simulation(Model& model, double dt) : model_(model), dt_(dt) {
  contacts_on_ = model_.contacts.active();
  walls_on_ = !model_.walls.empty();
  if (contacts_on_ || walls_on_) {
    if (model_.contacts.materials.empty()) {
      throw InputError("walls", "walls need contact materials", "give the particles and walls contact materials");
    }
    const ContactTable table(model_.contacts);
    if (contacts_on_) contacts_ = ContactForces(table, model_.particles, model_.contacts.skin);
    if (walls_on_) wall_forces_ = WallForces(table, model_.walls, model_.particles);
  }
  // The initial state: forces of the initial overlaps, springs not advanced.
  evaluate_contacts(0.0);
  gather_loads();
  const bool gravity_on = norm2(model_.gravity) > 0.0;
  parallel_for(static_cast<std::int64_t>(model_.particles.size()),
               [&](std::int64_t i) { add_body_loads(i, gravity_on); });
  if (walls_on_) control_walls(model_.walls);
}

void Simulation::evaluate_contacts(double increment_dt) {
  if (contacts_on_) {
    contacts_.update_list(model_.particles, model_.bonds);
    contacts_.compute(model_.particles, model_.bonds, increment_dt, dt_);
  }
  if (walls_on_) wall_forces_.compute(model_.walls, model_.particles, increment_dt, dt_);
}

namespace {
/// Chen Eq. 11-12: a damping force opposing the velocity of each DOF, of magnitude gamma_b times
/// the unbalanced load on that DOF.
Vec3 particle_damping(const Vec3& load, const Vec3& velocity, double gamma) {
  Vec3 d;
  for (int k = 0; k < 3; ++k) {
    const double sign = (velocity[k] > 0.0) - (velocity[k] < 0.0);
    d[k] = -gamma * std::abs(load[k]) * sign;
  }
  return d;
}
}  // namespace

void Simulation::sum_loads(std::int64_t i, bool contacts) {
  ParticleStore& p = model_.particles;
  // Bonds, then contacts, then walls, each summed on its own first.
  Vec3 force, torque;
  sum_bond_loads(model_.bonds, i, force, torque);
  if (contacts) {
    Vec3 contact_force, contact_torque;
    contacts_.sum_loads(i, contact_force, contact_torque);
    force += contact_force;
    torque += contact_torque;
  }
  if (walls_on_) {
    force += wall_forces_.force_on(i);
    torque += wall_forces_.torque_on(i);
  }
  p.force[i] = force;
  p.torque[i] = torque;
}

void Simulation::gather_loads() {
  ParticleStore& p = model_.particles;
  const auto n = static_cast<std::int64_t>(p.size());
  const bool contacts = contact_loads_ready();
  parallel_for(n, [&](std::int64_t i) { sum_loads(i, contacts); });
  for (const Load& load : model_.loads) {
    const double f = load.factor(time_);
    for (const std::int32_t i : load.particles) {
      p.force[i] += f * load.force;
      p.torque[i] += f * load.moment;
    }
  }
}

void Simulation::add_body_loads(std::int64_t i, bool gravity_on) {
  ParticleStore& p = model_.particles;
  if (gravity_on) p.force[i] += p.mass[i] * model_.gravity;
  const double gamma = model_.damping.particle;
  if (gamma > 0.0) {
    // On the free DOFs only: a prescribed particle (a tension test's grip) keeps the force its
    // bonds and contacts exert, which is what its reaction reports; its motion is the same.
    p.force[i] += hadamard(particle_damping(p.force[i], p.velocity[i], gamma), p.translation_free[i]);
    p.torque[i] += hadamard(particle_damping(p.torque[i], p.angular_velocity[i], gamma), p.rotation_free[i]);
  }
}

void Simulation::half_kick(std::int64_t i) {
  ParticleStore& p = model_.particles;
  const double h = 0.5 * dt_;
  p.velocity[i] += hadamard(p.force[i], p.translation_free[i]) * (h / p.mass[i]);
  p.angular_velocity[i] += hadamard(p.torque[i], p.rotation_free[i]) * (h / p.inertia[i]);
}

void Simulation::step() {
  ParticleStore& p = model_.particles;
  const auto n = static_cast<std::int64_t>(p.size());
  // Velocity Verlet, with the per-particle loops of a step fused into two passes (each particle
  // does the same arithmetic in the same order as in separate loops): kick and drift here; body
  // loads, kick and speed after the forces.
  const bool finite_positions = parallel_reduce(
      n, true,
      [&](std::int64_t i) {
        half_kick(i);
        p.position[i] += p.velocity[i] * dt_;
        p.orientation[i] = advance(p.orientation[i], p.angular_velocity[i] * dt_);
        return std::isfinite(p.position[i].x + p.position[i].y + p.position[i].z);
      },
      std::logical_and<>());
  if (walls_on_) advance_walls(model_.walls, dt_);
  time_ += dt_;
  ++steps_;
  // Before the contacts: the neighbour list would turn a non-finite position into a cell number.
  if (!finite_positions) {
    throw DivergenceError("the simulation diverged (non-finite position) at step " + std::to_string(steps_) +
                          ", t = " + std::to_string(time_) + " s: reduce integrator.time_step or the loads");
  }
  update_bond_loads(p, model_.bonds, dt_);
  evaluate_contacts(dt_);
  if (walls_on_) control_walls(model_.walls);  // from the walls' forces: no particle state
  // Without external loads the gather shares the last pass (the particle's loads are summed, then
  // body loads, kick and speed, as in two passes); external loads are added between the two.
  const bool fused = model_.loads.empty();
  if (!fused) gather_loads();
  const bool contacts = contact_loads_ready();
  // NaN propagates through the max as NaN (fmax would drop it); the check below catches it.
  const bool gravity_on = norm2(model_.gravity) > 0.0;
  const double vmax = parallel_reduce(
      n, 0.0,
      [&](std::int64_t i) {
        if (fused) sum_loads(i, contacts);
        add_body_loads(i, gravity_on);
        half_kick(i);
        return std::max(norm(p.velocity[i]), p.radius[i] * norm(p.angular_velocity[i]));
      },
      [](double a, double b) { return std::isnan(a) || a > b ? a : b; });
  max_speed_ = vmax;
  if (!std::isfinite(vmax)) {
    throw DivergenceError("the simulation diverged (non-finite velocity) at step " + std::to_string(steps_) +
                          ", t = " + std::to_string(time_) + " s: reduce integrator.time_step or the loads");
  }
  // The progress line (dem/step_monitor.hpp): a load and a compare on most steps.
  if (installed_step_monitor != nullptr && steps_ >= next_monitor_step_) {
    next_monitor_step_ = installed_step_monitor->after_step(*this);
  }
}

RunSummary Simulation::run(const StopCriteria& stop,
                           const std::function<void(const Simulation&)>& observer,
                           std::int64_t observe_every, const RunHooks& hooks) {
  const auto start = std::chrono::steady_clock::now();
  const std::int64_t first_step = steps_;
  RunSummary summary;
  // Half a step of slack so that an end time that is a multiple of dt is not overshot by round-off.
  while (true) {
    if (time_ + 0.5 * dt_ > stop.end_time) { summary.reason = StopReason::end_time; break; }
    if (steps_ >= stop.max_steps) { summary.reason = StopReason::max_steps; break; }
    step();
    if (observer && observe_every > 0 && steps_ % observe_every == 0) observer(*this);
    if (stop.rest_speed > 0.0 && time_ >= stop.rest_after && max_speed_ < stop.rest_speed) {
      summary.reason = StopReason::rest;
      break;
    }
    const bool checkpointed = hooks.checkpoint && hooks.checkpoint_every > 0 && steps_ % hooks.checkpoint_every == 0;
    if (checkpointed) hooks.checkpoint(*this);
    if (hooks.interrupted && hooks.interrupted(*this)) {
      summary.reason = StopReason::interrupted;
      if (hooks.checkpoint && !checkpointed) hooks.checkpoint(*this);
      break;
    }
  }
  if (observer && summary.reason != StopReason::interrupted) observer(*this);
  notify_run_ended(*this);
  summary.steps = steps_;
  summary.time = time_;
  summary.max_speed = max_speed_;
  summary.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double updates = static_cast<double>(steps_ - first_step) * static_cast<double>(model_.bonds.size());
  summary.bond_updates_per_second = summary.wall_seconds > 0.0 ? updates / summary.wall_seconds : 0.0;
  return summary;
}

void Simulation::restore(double time, std::int64_t steps, double max_speed, ContactForces::History contacts) {
  time_ = time;
  steps_ = steps;
  max_speed_ = max_speed;
  if (contacts_on_) contacts_.restore(std::move(contacts), model_.particles, model_.bonds);
}

Energies Simulation::energies() const {
  const ParticleStore& p = model_.particles;
  const BondStore& b = model_.bonds;
  Energies e;
  for (std::size_t i = 0; i < p.size(); ++i) {
    e.kinetic += 0.5 * p.mass[i] * norm2(p.velocity[i]) + 0.5 * p.inertia[i] * norm2(p.angular_velocity[i]);
  }
  for (std::size_t i = 0; i < b.size(); ++i) {
    e.elastic += bond_law::elastic_energy(b.stiffness[i], b.axis[i], b.force[i], b.moment[i]);
  }
  if (contacts_on_) e.contact += contacts_.elastic_energy();
  if (walls_on_) e.contact += wall_forces_.elastic_energy(model_.walls, p);
  return e;
}

}  // namespace bpm
