#pragma once
/// The stability limit of the explicit integrator for a bonded system.
///
/// Velocity Verlet is stable for dt < 2 / omega_max, omega_max the highest natural frequency of the
/// linearised system M^-1 K. We bound omega_max^2 from above with Gershgorin's theorem on
/// M^-1/2 K M^-1/2, assembled from the same bond elements the static solver uses (translational
/// and rotational modes together, fixed DOFs removed). The limit is therefore never optimistic:
/// any dt below it is stable. Viscous bond damping (Chen Eq. 9-10) is bounded the same way, by
/// Gershgorin on the dashpot matrix C built from the same element, and the step solves
/// (omega dt)^2 + 2 c dt = 4; particle (local) damping gamma scales omega by sqrt(1 + gamma).
#include "model/model.hpp"

namespace bpm {

struct TimeStepLimit {
  double critical = 0.0;       ///< s, guaranteed stable below this
  double omega_max_bound = 0.0;  ///< rad/s, Gershgorin bound on the highest frequency
  std::int64_t stiffest_bond = -1;  ///< bond contributing most to the limiting row
};

/// Throws InputError if there is nothing to bound (no bond with a free end).
TimeStepLimit critical_time_step(const Model& model);

}  // namespace bpm
