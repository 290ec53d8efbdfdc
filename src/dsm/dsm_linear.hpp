#pragma once
/// The direct stiffness method (Jarolin section 3.1): the static response of the bonded sample to
/// the platen displacement, K u = f (Eq. 7, 9), with the bonds and contacts linearised at the
/// current positions.
/// Output: the displacement (and rotation) of every particle, the platen reactions, the sample
/// stiffness K = F / displacement and E = K l / A.
#include <cstddef>
#include <vector>

#include "compress/platen_loading.hpp"
#include "compress/strain_gauge.hpp"
#include "solvers/sparse_solver.hpp"
#include "statics/static_contact.hpp"

namespace bpm {

struct DsmOptions {
  int dofs = 6;  ///< per particle: 6 (translation, rotation) or 3 (translation only, Jarolin 3.1.1)
  SparseSolverOptions solver;
  /// The DSM with walls (solve_dsm_linear): the relative residual of its tangent solves. K is
  /// taken from their solution v as 2 b^T v - v^T A v, whose error is the square of v's (in A's
  /// norm; b^T v alone, used until 2026-12-03, is first order). On the 1e5-particle cylinder,
  /// against 1e-8: 1e-3 is 3.0e-6 off (6 + 6 CG iterations; 4 + 3 since the rigid-body deflation of
  /// dsm_walls.cpp), b^T v at 1e-4 was 4.4e-6 off (11 + 10), 2 b^T v - v^T A v at 3e-3 is 9e-6 off
  /// (5 + 5). --tolerance sets both.
  double tangent_tolerance = 1e-3;
  /// The DSM with walls: Newton stops at ||R|| <= this ||h|| (h: the platen loads) for the
  /// operating points. 1e-3 moved K by at most 9e-5 against 1e-4 (dsm_walls.cpp).
  double operating_point_tolerance = 1e-3;
  /// The DSM with walls: the tangents' nodes in the fit window (fit_window.hpp: tangent_rule);
  /// 0: by the platen contacts (dsm_walls.cpp: window_points).
  int window_points = 0;
  /// The DSM with walls: particle pairs within this surface gap (m) are listed as potential
  /// contacts; 0: contact_listing_band (platen_springs.hpp). Widened to the platen travel when the
  /// listed pairs close by more than half of it (dsm_walls.cpp: solve_dsm_linear).
  double pair_band = 0.0;
  /// Nonlinear DSM (dsm_nonlinear.hpp): Newton stops at each step of the path when ||R|| <= this
  /// ||h|| (h: the platen contact forces).
  double nonlinear_tolerance = 1e-5;
  /// The DSM with walls and the nonlinear DSM: Coulomb slip at the contacts with the DEM's history
  /// (statics/static_problem.hpp); false: the paper's no slip (Jarolin 3.1.2).
  bool slip = true;
  /// The DSM with walls and the nonlinear DSM: the bonds' normal forces along their current axes
  /// with their current length, as in the DEM (statics/static_problem.hpp); false: Jarolin's
  /// small displacements.
  bool bond_axes = true;
  /// Nonlinear DSM: equal steps of the platen travel along the loading path.
  int load_steps = 10;
};

struct DsmResult {
  std::vector<Vec3> displacement;  ///< per particle, m
  std::vector<Vec3> rotation;      ///< per particle, rad (zero with 3 DOF)
  double force_top = 0.0;          ///< compressive force of the upper platen on the sample, N
  double force_bottom = 0.0;  ///< ... of the lower platen, N (equal to force_top in equilibrium)
  /// K, N/m: the kinematic DSM's force_top / displacement; the DSM with walls and the nonlinear DSM
  /// give the least-squares slope of F over the DEM's fit window, as the DEM reports it (each by
  /// a Gauss rule: dsm_linear.hpp, dsm_nonlinear.cpp).
  double stiffness = 0.0;
  double youngs_modulus = 0.0;  ///< E = K l / A, Pa
  BodyModuli body;              ///< E and nu of the middle third (compress/strain_gauge.hpp)
  std::size_t gauge_particles = 0;
  PlatenLoading loading;
  std::size_t unknowns = 0;  ///< rows of K
  std::size_t nonzeros = 0;  ///< stored entries of K after the constraints (zeros dropped)
  std::size_t detached_particles = 0;
  SparseSolveReport solve;  ///< the (last) linear solve
  double assembly_seconds = 0.0;
  double seconds = 0.0;  ///< everything, wall clock
  // Nonlinear DSM only.
  int newton_iterations = 0;
  int krylov_iterations = 0;
  std::size_t potential_contacts = 0;       ///< particle pairs listed once (Jarolin 3.1.2)
  std::size_t potential_wall_contacts = 0;  ///< particles near a platen
  double residual = 0.0;                    ///< the largest ||R|| / ||h|| Newton stopped at
  /// force_top / travel at the last node of the fit window's rule, N/m
  double secant_stiffness = 0.0;
  // The DSM with walls only.
  double pair_band = 0.0;          ///< pairs listed within this gap, m (contact_listing_band)
  double max_pair_approach = 0.0;  ///< the most any listed pair closed at the full travel, m
};

struct DofConstraints;
/// Copies the solution u (all DOFs) into r's per-particle fields; where pins held the free rigid
/// modes, in the centre-of-mass gauge (remove_lateral_rigid_modes). r.loading must be set.
void set_fields(const Model& model, const DofConstraints& constraints, const Eigen::VectorXd& u,
                DsmResult& r);

/// The linear DSM of Jarolin section 4.2 with the platen walls (section 3.1.3): the static core's
/// (statics/static_problem.hpp) tangent at operating points of the platen travel.
/// - Particle-particle contacts: the pairs within the approach they can reach of each other
///   (platen_springs.hpp: contact_listing_band), listed once (the paper's "list of contact partners
///   ... nearly the same during the deformation"), constant normal. The platens are walls with the
///   grain-platen contact law and friction.
/// - The DEM fits a least-squares line to F(w) over its window [a, b]: the average of dF/dw
///   weighted by 6 (w - a)(b - w) / (b - a)^3. A Gauss rule of that weight (fit_window.hpp:
///   tangent_rule) takes the tangents at its nodes; K is their weighted mean. Two nodes (w = m -+
///   (b - a) / (2 sqrt 5), m the window's middle) are exact for dF/dw up to cubic; a platen that
///   touches few particles gets 24 (DsmOptions::window_points), which follow the kinks of F'.
/// - Each operating point is found by the core's Newton driver (a few linear solves with the same
///   preconditioner), the nodes in order of travel: with DsmOptions::slip the contacts' tangential
///   springs carry the slip of the path through the nodes (the first reached in one step), and a
///   sliding contact adds no tangential stiffness to the loading tangent; without, the paper's no
///   slip. One linear solve with the tangents then gives dx/dw and dF_top/dw there.
/// - The reported field is the tangent line's at the full travel, through the upper operating
///   point; force_top, force_bottom and secant_stiffness (force_top / w) are that point's.
DsmResult solve_dsm_linear(const Model& model, const PlatenLoading& load,
                           const DsmOptions& options = {});

/// The kinematic variant (dsm_constraints.hpp): the particles next to the platens held and moved,
/// no walls; the bonds and touching contacts as in solve_dsm_linear. Jarolin's "neglecting
/// particle-wall interactions": faster, but stiffer than the DEM by the platen contacts'
/// compliance; the twin of the DEM's dem-kinematic.
DsmResult solve_dsm_kinematic(const Model& model, const PlatenLoading& load,
                              const DsmOptions& options = {});

struct DofConstraints;
/// The coarse space of the DSM's AMG solves: the sample's six rigid-body modes and its uniform
/// axial strain, zero on the held DOFs (dsm_walls.cpp).
Eigen::MatrixXd dsm_coarse_space(const Model& model, const DofConstraints& constraints);

/// Runs `solve` (a DSM with walls) with the particle pairs listed within contact_listing_band
/// (platen_springs.hpp; DsmOptions::pair_band if set), and again with every pair within the platen
/// travel if the listed pairs closed by more than half of the band's margin (a pair beyond the band
/// may have closed too).
DsmResult solve_with_listed_pairs(const Model& model, const PlatenLoading& load,
                                  const DsmOptions& options,
                                  DsmResult (*solve)(const Model&, const PlatenLoading&,
                                                     const DsmOptions&, double));

/// The particle-particle contacts touching at the start, linearised at their overlap (the kinematic
/// DSM's contacts).
std::vector<StaticContact> touching_contacts(const Model& model);

/// Between frictionless platens the sample may slide and spin about the axis without load; the
/// DSM pins these modes, the DEM's local damping lets them drift. This removes from u the lateral
/// translation and spin about the axis (through the centre of mass) that fit it best, mass-weighted
/// over the particles with include[i], and returns the spin removed (rad).
double remove_lateral_rigid_modes(const ParticleStore& particles, const Vec3& axis,
                                  std::vector<Vec3>& u, const std::vector<bool>& include);

/// The particle-by-particle difference of two displacement fields: max |u_a - u_b| over the
/// particles, relative to the platen displacement, after removing the free rigid modes of the
/// difference when the platens are frictionless.
double max_relative_difference(const Model& model, const PlatenLoading& load,
                               const std::vector<Vec3>& a, const std::vector<Vec3>& b);

}  // namespace bpm
