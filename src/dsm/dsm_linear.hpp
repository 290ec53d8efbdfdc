#pragma once
/// The direct stiffness method (Jarolin section 3.1): the static response of the bonded sample to
/// the platen displacement, K u = f (Eq. 7, 9), with the bonds linearised at the current positions.
/// Output: the displacement (and rotation) of every particle, the platen reactions, the sample
/// stiffness K = F / displacement and E = K l / A.
#include <cstddef>
#include <vector>

#include "compress/platen_loading.hpp"
#include "dsm/sparse_solver.hpp"

namespace bpm {

struct DsmOptions {
  int dofs = 6;  ///< per particle: 6 (translation, rotation) or 3 (translation only, Jarolin 3.1.1)
  SparseSolverOptions solver;
  /// Nonlinear DSM (dsm_nonlinear.hpp): stop when every residual force is below this fraction of the
  /// mean platen contact force (moments: times the mean radius). Jarolin: 1e-3.
  double nonlinear_tolerance = 1e-3;
  int max_newton_iterations = 50;
};

struct DsmResult {
  std::vector<Vec3> displacement;  ///< per particle, m
  std::vector<Vec3> rotation;      ///< per particle, rad (zero with 3 DOF)
  double force_top = 0.0;          ///< compressive force of the upper platen on the sample, N
  double force_bottom = 0.0;       ///< ... of the lower platen, N (equal to force_top in equilibrium)
  /// K = force_top / displacement (linear); the nonlinear DSM gives the chord over the DEM's fit
  /// window, (F(to) - F(from)) / ((to - from) displacement), as the DEM's fitted slope. N/m
  double stiffness = 0.0;
  double youngs_modulus = 0.0;     ///< E = K l / A, Pa
  PlatenLoading loading;
  std::size_t unknowns = 0;        ///< rows of K
  std::size_t nonzeros = 0;        ///< stored entries of K after the constraints (zeros dropped)
  std::size_t detached_particles = 0;
  SparseSolveReport solve;         ///< the (last) linear solve
  double assembly_seconds = 0.0;
  double seconds = 0.0;            ///< everything, wall clock
  // Nonlinear DSM only.
  int newton_iterations = 0;
  int krylov_iterations = 0;
  std::size_t potential_contacts = 0;       ///< particle pairs listed once (Jarolin 3.1.2)
  std::size_t potential_wall_contacts = 0;  ///< particles near a platen
  double residual = 0.0;  ///< KINSOL's final scaled residual, L2 norm (the stop test uses the max norm)
  double secant_stiffness = 0.0;            ///< force_top / displacement at the fit window's end, N/m
};

struct DofConstraints;
/// Copies the solution u (all DOFs) into r's per-particle fields; where pins held the free rigid
/// modes, in the centre-of-mass gauge (remove_lateral_rigid_modes). r.loading must be set.
void set_fields(const Model& model, const DofConstraints& constraints, const Eigen::VectorXd& u, DsmResult& r);

/// Linear DSM with kinematic platens (dsm_constraints.hpp).
DsmResult solve_dsm_linear(const Model& model, const PlatenLoading& load, const DsmOptions& options = {});

/// Between frictionless platens the sample may slide and spin about the axis without load; the
/// DSM pins these modes, the DEM's local damping lets them drift. This removes from u the lateral
/// translation and spin about the axis (through the centre of mass) that fit it best, mass-weighted
/// over the particles with include[i], and returns the spin removed (rad).
double remove_lateral_rigid_modes(const ParticleStore& particles, const Vec3& axis, std::vector<Vec3>& u,
                                  const std::vector<bool>& include);

/// The particle-by-particle difference of two displacement fields: max |u_a - u_b| over the
/// particles, relative to the platen displacement, after removing the free rigid modes of the
/// difference when the platens are frictionless.
double max_relative_difference(const Model& model, const PlatenLoading& load, const std::vector<Vec3>& a,
                               const std::vector<Vec3>& b);

}  // namespace bpm
