#pragma once
/// The explicit DEM loop: velocity Verlet for translation and rotation of spheres (isotropic
/// inertia, so no gyroscopic term), orientation kept as a unit quaternion.
///
/// One step: half kick and drift with the old loads; bond update with the half-step velocities
/// (which are exactly the displacement increments over the step divided by dt); gather, external
/// loads, gravity and particle damping (Chen Eq. 11-12, using the half-step velocity); second half
/// kick. Fixed DOFs have a zero mask and keep their (zero or prescribed) velocity.
///
/// With contacts or walls configured (Model::contacts, Model::walls) the walls move with the
/// particles in the drift; after the bond update the neighbour list is refreshed when needed and
/// the particle-particle and particle-wall contact loads are evaluated at the new positions with
/// the half-step velocities, like the bonds; they are gathered with the bond loads; then the servo
/// walls set their velocity for the next step from their force.
#include <cstdint>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string_view>

#include "contacts/contact_forces.hpp"
#include "model/model.hpp"
#include "walls/wall_forces.hpp"

namespace bpm {

struct StopCriteria {
  double end_time = std::numeric_limits<double>::infinity();   ///< s
  std::int64_t max_steps = std::numeric_limits<std::int64_t>::max();
  /// Quasi-static rest: stop once every particle's speed max(|U|, R |omega|) is below this (Chen:
  /// 1e-9 m/s); 0 switches it off. Checked only from rest_after on (e.g. after the load ramp).
  double rest_speed = 0.0;
  double rest_after = 0.0;  ///< s
};

/// interrupted: RunHooks::interrupted asked to stop (SIGINT, SIGTERM); a checkpoint was written.
enum class StopReason { end_time, max_steps, rest, interrupted };
std::string_view to_string(StopReason reason);

struct RunSummary {
  StopReason reason = StopReason::end_time;
  std::int64_t steps = 0;
  double time = 0.0;
  double wall_seconds = 0.0;
  double bond_updates_per_second = 0.0;
  double max_speed = 0.0;  ///< at the end
};

struct Energies {
  double kinetic = 0.0;  ///< translational + rotational, J
  double elastic = 0.0;  ///< stored in bonds, J
  double contact = 0.0;  ///< stored in particle and wall contacts (overlaps, tangential springs), J
};

/// Thrown by Simulation::step when the state turns non-finite (summary.json: "diverged").
class DivergenceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Simulation;

/// What a long run does besides stepping (scenario/checkpoint.hpp): periodic checkpoints and a stop
/// request from outside (a signal).
struct RunHooks {
  std::int64_t checkpoint_every = 0;  ///< steps between checkpoints; 0: none
  /// Writes a checkpoint; called every checkpoint_every steps and when interrupted.
  std::function<void(const Simulation&)> checkpoint;
  /// Checked after each step; true ends the run (StopReason::interrupted) without a final observer
  /// call, so that a resumed run continues the outputs exactly.
  std::function<bool(const Simulation&)> interrupted;
};

class Simulation {
 public:
  /// The model must be finalised. Evaluates the loads at t = 0.
  Simulation(Model& model, double dt);

  void step();
  /// Steps until a stop criterion holds; calls observer every observe_every steps (0: never) and
  /// once at the end. Per step: step, observer, rest check, checkpoint, interrupt check; so a
  /// checkpoint is never taken at a step where the run ends at rest.
  RunSummary run(const StopCriteria& stop, const std::function<void(const Simulation&)>& observer = {},
                 std::int64_t observe_every = 0, const RunHooks& hooks = {});

  /// Continues from a checkpoint (scenario/checkpoint.hpp): the caller restores the model's state; this
  /// sets the clock and the contact history.
  void restore(double time, std::int64_t steps, double max_speed, ContactForces::History contacts);

  double time() const { return time_; }
  double dt() const { return dt_; }
  std::int64_t steps() const { return steps_; }
  /// max over particles of max(|U|, R |omega|) after the last step, m/s.
  double max_speed() const { return max_speed_; }
  const Model& model() const { return model_; }
  Energies energies() const;
  /// The particle-particle contacts (empty when they are off).
  const ContactForces& contacts() const { return contacts_; }
  bool contacts_on() const { return contacts_on_; }

 private:
  /// force and torque = the particle's bond, contact and wall loads, plus the external loads.
  void gather_loads();
  /// force[i] and torque[i] = particle i's bond, contact and wall loads (gather_loads without the
  /// external loads). `contacts`: whether the contact loads are gathered (ContactForces::gathered).
  void sum_loads(std::int64_t i, bool contacts);
  /// Whether sum_loads adds contact loads: contacts on and evaluated on the current list.
  bool contact_loads_ready() const { return contacts_on_ && contacts_.gathered(model_.particles.size()); }
  /// Gravity, then Chen's local damping (Eq. 11-12) of the summed load, on particle i.
  void add_body_loads(std::int64_t i, bool gravity_on);
  /// v += F dt / (2 m) on particle i's free DOFs (and the spin likewise).
  void half_kick(std::int64_t i);
  void evaluate_contacts(double increment_dt);

  Model& model_;
  double dt_;
  double time_ = 0.0;
  std::int64_t steps_ = 0;
  std::int64_t next_monitor_step_ = 0;  ///< when to call the installed StepMonitor
  double max_speed_ = 0.0;
  bool contacts_on_ = false;
  bool walls_on_ = false;
  ContactForces contacts_;
  WallForces wall_forces_;
};

}  // namespace bpm
