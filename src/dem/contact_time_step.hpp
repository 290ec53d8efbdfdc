#pragma once
/// Stability limit of the explicit integrator for the particle contacts, to be combined with the
/// bond limit of dem/time_step.hpp.
///
/// Velocity Verlet is stable for dt < 2/omega_max. Gershgorin's theorem on M^-1/2 K M^-1/2 bounds
/// the row of particle p (mass m_p, at most z contacts to particles of mass >= m_min or walls, each
/// of normal stiffness k_n and tangential stiffness k_t at arm R, I = 2/5 m R^2) by
///   omega_p^2 <= z (1/m_p + 1/sqrt(m_p m_min)) max(k_n + (1 + sqrt 2.5) k_t, (2.5 + sqrt 2.5) k_t),
/// the translational and rotational rows (the tangential spring couples both through R). The
/// Hertz stiffness grows with the overlap, dF_n/d delta = 2 E* sqrt(R* delta), k_t = 8 G*
/// sqrt(R* delta); it is taken at the largest overlap expected, max_overlap_ratio * R. The
/// contact dashpot of damping ratio zeta = -beta lowers the limit by sqrt(1 + zeta^2) - zeta.
///
/// Combining with the bonds: Gershgorin row sums add, so omega_max^2 <= omega_b^2 + omega_c^2 and
/// dt_crit = combine_time_steps(critical_time_step(model).critical, contact_time_step(model).critical)
/// = 1/sqrt(1/dt_b^2 + 1/dt_c^2). The Rayleigh time step (the period of the Rayleigh surface wave
/// across a particle) is returned for reference; common practice runs at 0.1-0.3 of it.
#include "model/model.hpp"

namespace bpm {

struct ContactTimeStep {
  double critical = 0.0;  ///< s, 2/omega bound above (infinity when there is nothing to bound)
  double rayleigh = 0.0;  ///< s, min over Hertz-Mindlin particles of pi R sqrt(rho/G)/(0.1631 nu + 0.8766)
  std::int64_t limiting_particle = -1;
};

/// coordination: the most contacts a particle can have (12 for equal spheres; a sphere among
/// smaller ones can touch more). Throws InputError for invalid contact materials.
ContactTimeStep contact_time_step(const Model& model, double max_overlap_ratio = 0.01, int coordination = 12);

/// 1/sqrt(1/a^2 + 1/b^2): the limit of two sets of springs acting together (see above).
double combine_time_steps(double a, double b);

/// The stability limit of a model's explicit DEM, s: the one time-step policy (dt = safety factor
/// x this, for a scenario's `time_step: auto`, the compression tests and the cantilever suite).
/// The bonds' bound (dem/time_step.hpp), combined with the contacts' when the model has contact
/// materials (particles or walls). Throws the bonds' InputError when nothing bounds the step (no
/// bond acts on a free particle and there are no contacts).
double stability_limit(const Model& model);

}  // namespace bpm
