// The linear DSM with its platen walls (dsm_linear.hpp: solve_dsm_linear): the static core's
// operating points at the nodes of the fit window and its tangent there
// (statics/static_problem.hpp).
#include <algorithm>
#include <chrono>
#include <cmath>

#include <Eigen/Dense>

#include "dsm/dsm_linear.hpp"
#include "dsm/fit_window.hpp"
#include "dsm/platen_constraints.hpp"
#include "dsm/platen_springs.hpp"
#include "statics/static_contact.hpp"
#include "statics/static_problem.hpp"

namespace bpm {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

std::vector<StaticContact> touching_contacts(const Model& model) {
  std::vector<StaticContact> out;
  if (!model.contacts.active() || model.particles.size() < 2) return out;
  const double r_max =
      *std::max_element(model.particles.radius.begin(), model.particles.radius.end());
  for (const StaticContact& c : list_static_contacts(model, 1e-9 * r_max)) {
    if (c.overlap > 0.0) out.push_back(c);
  }
  return out;
}

namespace {

/// The nodes of the tangent rule (fit_window.hpp). A platen that touches few particles makes F'
/// kinked: each particle that reaches it adds a Hertz spring whose stiffness starts at zero, and a
/// Gauss rule converges slowly across such kinks. On three of the validation study's 2,000-particle
/// agglomerates (6-8 particles in each platen zone; seeds 2009, 2019, 2022) the slope from 257
/// equally spaced tangents was 2160.1, 1951.8 and 2111.8 N/m; eight nodes gave 2131.9, 1954.6 and
/// 2123.3 (-1.3 %, +0.14 %, +0.54 %), 24 nodes were within 0.2 % on all three (2026-12-03). On the
/// 1,000-particle cylinders (~78 in each zone) eight nodes moved K by 0.03-0.1 % from two
/// (docs/validation.md, 2026-12-02).
int window_points(const DsmOptions& options, const PlatenLoading& load) {
  constexpr std::size_t kFewPlatenParticles = 50;
  if (options.window_points > 0) return options.window_points;
  return std::min(load.bottom.size(), load.top.size()) < kFewPlatenParticles ? 24 : 2;
}

}  // namespace

/// The coarse space of the solves (ShiftedSpdSolver::set_coarse_space): the sample's six
/// rigid-body modes (u = t + a x X, rotation a; Jarolin's rotational DOFs turn by a as well) and
/// the uniform axial strain, the loading's shape, zero on the held DOFs. Held only by the platen
/// springs, the rigid modes are the softest, and the V-cycle of hypre's unknown-by-unknown
/// hierarchy misses the rotations (they couple translations and rotations). On the 1e5-particle
/// cylinder the second Newton step of the first operating point took 21 CG iterations without
/// them, 8 with the rigid modes and 7 with the strain as well; all the solves 45 -> 26 CG
/// iterations with hypre's nodal coarsening (2026-12-03).
Eigen::MatrixXd dsm_coarse_space(const Model& model, const DofConstraints& c) {
  const std::size_t particles = model.particles.size();
  const int dofs = c.dofs;
  Vec3 centre{};
  for (const Vec3& p : model.particles.position) centre += p;
  centre = (1.0 / static_cast<double>(std::max<std::size_t>(particles, 1))) * centre;
  Eigen::MatrixXd Z = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(dofs * particles), 7);
  for (std::size_t p = 0; p < particles; ++p) {
    const Vec3 X = model.particles.position[p] - centre;
    const auto at = static_cast<Eigen::Index>(dofs * p);
    for (int k = 0; k < 3; ++k) {
      Z(at + k, k) = 1.0;
      Vec3 a{};
      a[k] = 1.0;
      const Vec3 u = cross(a, X);
      for (int q = 0; q < 3; ++q) Z(at + q, 3 + k) = u[q];
      if (dofs == 6) Z(at + 3 + k, 3 + k) = 1.0;
    }
    Z(at + c.axial_dof, 6) = X[c.axial_dof];
  }
  for (Eigen::Index i = 0; i < Z.rows(); ++i) {
    if (c.fixed[static_cast<std::size_t>(i)] != 0) Z.row(i).setZero();
  }
  for (Eigen::Index k = 0; k < Z.cols(); ++k) {  // unit columns: Z^T A Z's entries alike in size
    if (const double length = Z.col(k).norm(); length > 0.0) Z.col(k) /= length;
  }
  return Z;
}

namespace {

/// The DSM with walls, the particle pairs listed within `band` of each other.
DsmResult solve_with_pair_band(const Model& model, const PlatenLoading& load,
                               const DsmOptions& options, double band) {
  const auto start = std::chrono::steady_clock::now();
  DsmResult r;
  r.loading = load;
  r.pair_band = band;
  const int dofs = options.dofs;
  const DofConstraints c = platen_constraints(model, load, dofs, /*kinematic_platens=*/false);
  r.detached_particles = c.detached_particles;
  // The particle pairs that touch, or may touch within the platen travel (as the nonlinear DSM
  // lists them): a pair that closes carries load at the operating point like one that touched. And
  // every particle that can reach a platen before the end of its travel.
  std::vector<StaticContact> contacts = list_static_contacts(model, band);
  const std::size_t pairs = contacts.size();
  r.potential_contacts = pairs;
  const std::vector<StaticContact> walls = platen_contacts(model, load, c, load.displacement);
  r.potential_wall_contacts = walls.size();
  contacts.insert(contacts.end(), walls.begin(), walls.end());
  StaticProblemOptions core{dofs, options.solver, options.slip, options.bond_axes};
  StaticProblem problem(model, c, std::move(contacts), core, dsm_coarse_space(model, c));
  r.unknowns = problem.unknowns();
  r.nonzeros = problem.nonzeros();

  // The DEM's least-squares slope over its fit window as the weighted mean of the tangents dF/dw
  // at the nodes of fit_window.hpp's rule.
  const WindowRule rule = tangent_rule(window_points(options, load), load.fit_from, load.fit_to);
  std::vector<double> travels;
  for (double t : rule.travel) travels.push_back(t * load.displacement);

  // Start: the uniform axial strain, offset so that the outermost particles overlap each platen
  // by a quarter of the travel (a zero overlap would give Newton's first step no wall stiffness).
  const double start_overlap = 0.25 * travels[0];
  Eigen::VectorXd& x = problem.field();
  for (std::size_t p = 0; p < model.particles.size(); ++p) {
    const double height =
        (dot(model.particles.position[p], load.axis) - load.sample.bottom) / load.sample.length;
    const auto dof = static_cast<Eigen::Index>(dofs * p + static_cast<std::size_t>(c.axial_dof));
    if (!c.fixed[static_cast<std::size_t>(dof)]) {
      x[dof] =
          -load.axis[c.axial_dof] * (start_overlap + (travels[0] - 2.0 * start_overlap) * height);
    }
  }
  // v = dx/dw; from the second point on the previous tangent starts its solve (the first: x/w).
  Eigen::VectorXd v, previous;
  r.stiffness = 0.0;
  // The body's strains per unit travel by the same rule (strain_gauge.hpp), from the tangents v.
  const StrainGauge gauge(model.particles.position, load.axis, load.sample);
  GaugeStrain per_travel;
  for (std::size_t k = 0; k < travels.size(); ++k) {
    // Each point after the first starts on the previous one's tangent: x(w1) + (w2 - w1) dx/dw,
    // a Newton predictor (the contacts that close between the points are already partly in it).
    if (k > 0) x += (travels[k] - travels[k - 1]) * v;
    problem.solve(travels[k], options.operating_point_tolerance, "dsm");
    previous = v;
    r.stiffness += rule.weight[k] *
                   problem.tangent_stiffness(travels[k], options.tangent_tolerance, v, previous);
    if (gauge.valid()) {
      const GaugeStrain g = gauge.measure_field(v, dofs);
      per_travel.axial += rule.weight[k] * g.axial;
      per_travel.lateral += rule.weight[k] * g.lateral;
    }
    problem.commit();  // the nodes in order: the slip history of the path through them
  }
  const double w = travels.back();
  r.force_top = problem.wall_force(w, /*moving=*/true);
  r.force_bottom = problem.wall_force(w, /*moving=*/false);
  r.residual = problem.relative_residual();
  r.secant_stiffness = r.force_top / w;
  r.youngs_modulus = r.stiffness * load.sample.length / load.sample.area;
  r.gauge_particles = gauge.size();
  if (gauge.valid())
    r.body = body_moduli(r.stiffness, load.sample.area, per_travel.axial, per_travel.lateral);
  const StaticWork& work = problem.work();
  r.newton_iterations = work.newton_iterations;
  r.krylov_iterations = work.krylov_iterations;
  r.solve = work.setup;
  r.solve.seconds = work.solve_seconds;
  r.assembly_seconds = work.assembly_seconds;
  // The field at the full travel, on the tangent line through the upper operating point.
  const Eigen::VectorXd u = x + (load.displacement - w) * v;
  // How far the listed pairs closed (contact_listing_band).
  for (std::size_t k = 0; k < pairs; ++k) {
    r.max_pair_approach = std::max(r.max_pair_approach, problem.approach(k, u));
  }
  set_fields(model, c, u, r);
  r.seconds = seconds_since(start);
  return r;
}

}  // namespace

DsmResult solve_with_listed_pairs(const Model& model, const PlatenLoading& load,
                                  const DsmOptions& options,
                                  DsmResult (*solve)(const Model&, const PlatenLoading&,
                                                     const DsmOptions&, double)) {
  const double widest = platen_listing_band(model, load);
  const double band =
      options.pair_band > 0.0 ? options.pair_band : contact_listing_band(model, load);
  DsmResult r = solve(model, load, options, band);
  const double margin = band - listing_slack(model);
  if (band < widest && r.max_pair_approach > 0.5 * margin) {
    const double seconds = r.seconds;
    r = solve(model, load, options, widest);
    r.seconds += seconds;
  }
  return r;
}

DsmResult solve_dsm_linear(const Model& model, const PlatenLoading& load,
                           const DsmOptions& options) {
  return solve_with_listed_pairs(model, load, options, solve_with_pair_band);
}

}  // namespace bpm
