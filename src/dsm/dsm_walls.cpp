// The linear DSM with its platen walls (dsm_linear.hpp: solve_dsm_linear): the operating points
// of the platen and particle contacts by Newton's method, the tangent systems there.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <string>

#include <Eigen/Dense>

#include "dem/static_contacts.hpp"
#include "core/error.hpp"
#include "dsm/contact_change.hpp"
#include "dsm/contact_element.hpp"
#include "dsm/dsm_assembly.hpp"
#include "dsm/dsm_constraints.hpp"
#include "dsm/distributed_solver.hpp"
#include "dsm/dsm_linear.hpp"
#include "dsm/fit_window.hpp"
#include "dsm/mpi_world.hpp"
#include "dsm/platen_springs.hpp"

namespace bpm {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// The contact element of a pair at overlap delta (the law's tangent there; zero once apart), at
/// the contact point of the start (the DEM's: R - delta_0/2 from each centre).
ContactElement contact_element(const Model& model, const StaticContact& c, double delta) {
  const contact_law::Linearised s = contact_law::linearise(c.params, c.inertia, delta);
  const double arm_i = model.particles.radius[static_cast<std::size_t>(c.i)] - 0.5 * c.overlap;
  const double arm_j = model.particles.radius[static_cast<std::size_t>(c.j)] - 0.5 * c.overlap;
  return {c.i, c.j, c.n, arm_i, arm_j, s.normal_tangent, s.tangential};
}

/// How far the pair has closed under the displacements u (dofs per particle): -n.(u_j - u_i).
double approach(const StaticContact& p, const Eigen::VectorXd& u, int dofs) {
  const auto ui = static_cast<Eigen::Index>(dofs * static_cast<std::size_t>(p.i));
  const auto uj = static_cast<Eigen::Index>(dofs * static_cast<std::size_t>(p.j));
  return -dot(p.n, Vec3{u[uj] - u[ui], u[uj + 1] - u[ui + 1], u[uj + 2] - u[ui + 2]});
}

/// The pairs touching at the start (overlap > 0, bonded-pair rule applied).
std::vector<StaticContact> touching_pairs(const Model& model) {
  std::vector<StaticContact> out;
  if (!model.contacts.active() || model.particles.size() < 2) return out;
  const double r_max = *std::max_element(model.particles.radius.begin(), model.particles.radius.end());
  for (const StaticContact& c : list_static_contacts(model, 1e-9 * r_max)) {
    if (c.overlap > 0.0) out.push_back(c);
  }
  return out;
}

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

/// The coarse space of the solves (ShiftedSpdSolver::set_coarse_space): the sample's six
/// rigid-body modes (u = t + a x X, rotation a; Jarolin's rotational DOFs turn by a as well) and
/// the uniform axial strain, the loading's shape, zero on the held DOFs. Held only by the platen
/// springs, the rigid modes are the softest, and the V-cycle of hypre's unknown-by-unknown
/// hierarchy misses the rotations (they couple translations and rotations). On the 1e5-particle
/// cylinder the second Newton step of the first operating point took 21 CG iterations without
/// them, 8 with the rigid modes and 7 with the strain as well; all the solves 45 -> 26 CG
/// iterations with hypre's nodal coarsening (2026-12-03).
Eigen::MatrixXd coarse_space(const Model& model, const DofConstraints& c) {
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

/// K (bonds and the listed contacts) with the constraints eliminated, as the solver of its shifted
/// systems, and in rhs (whole) the constraints' right-hand side. One process: ShiftedSpdSolver.
/// Under mpirun each rank assembles the rows of its range of particles (partition_particles,
/// weighted by K's row blocks) into a DistributedShiftedSolver.
std::unique_ptr<ShiftedSystem> shifted_system(const Model& model, int dofs, const std::vector<ContactElement>& contacts,
                                              const DofConstraints& c, const SparseSolverOptions& options,
                                              Eigen::VectorXd& rhs, DsmResult& r) {
  const mpi::World world = mpi::world();
  if (!world.distributed()) {
    SparseMatrixRM K = assemble_stiffness(model, dofs, contacts);
    r.unknowns = static_cast<std::size_t>(K.rows());
    rhs = Eigen::VectorXd::Zero(K.rows());
    apply_constraints(K, rhs, c);
    r.nonzeros = static_cast<std::size_t>(K.nonZeros());
    return std::make_unique<ShiftedSpdSolver>(std::move(K), options);
  }
  std::vector<std::int32_t> contact_ends;
  for (const ContactElement& e : contacts) contact_ends.insert(contact_ends.end(), {e.i, e.j});
  std::vector<int> row_start = dsm_row_partition(model, contact_ends, dofs, world.size);
  const auto rank = static_cast<std::size_t>(world.rank);
  const auto first = static_cast<std::size_t>(row_start[rank] / dofs), last = static_cast<std::size_t>(row_start[rank + 1] / dofs);
  SparseMatrixRM K = assemble_stiffness(model, dofs, contacts, {first, last});
  Eigen::VectorXd rows = Eigen::VectorXd::Zero(K.rows());
  apply_constraints(K, rows, c, static_cast<std::size_t>(row_start[rank]));
  r.unknowns = static_cast<std::size_t>(row_start.back());
  auto solver = std::make_unique<DistributedShiftedSolver>(std::move(K), std::move(row_start), options);
  solver->gather(rows, rhs);
  r.nonzeros = solver->nonzeros();
  return solver;
}

}  // namespace

std::vector<ContactElement> touching_contact_elements(const Model& model) {
  std::vector<ContactElement> out;
  for (const StaticContact& c : touching_pairs(model)) out.push_back(contact_element(model, c, c.overlap));
  return out;
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
  // lists them): a pair that closes carries load at the operating point like one that touched.
  const std::vector<StaticContact> pairs = list_static_contacts(model, band);
  std::vector<ContactElement> start_elements;
  for (const StaticContact& p : pairs) start_elements.push_back(contact_element(model, p, p.overlap));
  std::vector<ContactElement> contacts = start_elements;
  r.potential_contacts = contacts.size();
  SparseSolverOptions solver_options = options.solver;
  solver_options.block_size = dofs;
  solver_options.nodal_coarsening = true;  // with the coarse space below (sparse_solver.hpp)
  Eigen::VectorXd rhs;
  const std::unique_ptr<ShiftedSystem> system = shifted_system(model, dofs, contacts, c, solver_options, rhs, r);
  ShiftedSystem& solver = *system;
  r.assembly_seconds = seconds_since(start);
  if (solver.kind() == SparseSolverKind::amg_pcg) solver.set_coarse_space(coarse_space(model, c));
  // Every spring that can touch before the end of the platen travel.
  const PlatenSprings walls = list_platen_springs(model, load, c, load.displacement);
  r.potential_wall_contacts = walls.springs.size();

  const Eigen::Index n = static_cast<Eigen::Index>(r.unknowns);
  auto held = [&](std::size_t dof) { return c.fixed[dof] != 0; };
  // The DEM's least-squares slope over its fit window as the weighted mean of the tangents dF/dw
  // at the nodes of fit_window.hpp's rule.
  const WindowRule rule = tangent_rule(window_points(options, load), load.fit_from, load.fit_to);
  std::vector<double> travels;
  for (double t : rule.travel) travels.push_back(t * load.displacement);

  // Start: the uniform axial strain, offset so that the outermost particles overlap each platen
  // by a quarter of the travel (a zero overlap would give Newton's first step no wall stiffness).
  const double start_overlap = 0.25 * travels[0];
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
  for (std::size_t p = 0; p < model.particles.size(); ++p) {
    const double height = (dot(model.particles.position[p], load.axis) - load.sample.bottom) / load.sample.length;
    x[static_cast<Eigen::Index>(dofs * p + static_cast<std::size_t>(c.axial_dof))] =
        -walls.sign * (start_overlap + (travels[0] - 2.0 * start_overlap) * height);
  }
  for (Eigen::Index i = 0; i < n; ++i) {
    if (held(static_cast<std::size_t>(i))) x[i] = c.value[static_cast<std::size_t>(i)];
  }
  // Platen loads h(x) on the axial DOFs and their tangent dF/d delta; `floor` keeps a spring that
  // has opened in the Jacobian (Newton's steps only; the converged field does not depend on it).
  const double floor =
      1e-3 * contact_law::linearise(walls.springs.front().params, walls.springs.front().inertia, start_overlap).normal_tangent;
  auto platen_loads = [&](const Eigen::VectorXd& u, double w, Eigen::VectorXd& h, Eigen::VectorXd& tangent, double minimum) {
    h.setZero(n);
    tangent.setZero(n);
    for (const PlatenSpring& s : walls.springs) {
      const std::size_t dof = walls.axial_dof(s);
      if (held(dof)) continue;
      const contact_law::Linearised l = contact_law::linearise(s.params, s.inertia, walls.overlap(s, u.data(), w));
      h[static_cast<Eigen::Index>(dof)] += walls.direction(s) * l.force;
      tangent[static_cast<Eigen::Index>(dof)] += std::max(l.normal_tangent, minimum);
    }
  };
  Eigen::VectorXd h, tangent, Kx, residual;
  // The particle contacts as they are: K holds them linearised at the start (C_0); the residual
  // swaps that for the contact law, minus the sum over pairs of B^T (C_0 Delta - f(Delta)) with
  // f = -(F_n(delta_0 + c) - F_n(delta_0)) n + k_t(delta_0 + c) Delta_t, c = -n.Delta (Jarolin
  // 3.1.2: constant normal, no slip, the start prestressed in equilibrium).
  auto add_contact_correction = [&](const Eigen::VectorXd& u, Eigen::VectorXd& out) {
    auto at = [&](std::int32_t p, int k) { return dofs * static_cast<Eigen::Index>(p) + k; };
    auto vec = [&](std::int32_t p, int k0) { return Vec3{u[at(p, k0)], u[at(p, k0 + 1)], u[at(p, k0 + 2)]}; };
    auto add = [&](std::int32_t p, int k0, const Vec3& v) {
      for (int k = 0; k < 3; ++k) out[at(p, k0 + k)] += v[k];
    };
    for (std::size_t k = 0; k < pairs.size(); ++k) {
      const StaticContact& p = pairs[k];
      const ContactElement& e0 = start_elements[k];
      Vec3 delta = vec(p.j, 0) - vec(p.i, 0);
      if (dofs == 6) delta += cross(e0.arm_j * p.n, vec(p.j, 3)) + cross(e0.arm_i * p.n, vec(p.i, 3));
      const double along = dot(p.n, delta);
      const Vec3 across = delta - along * p.n;
      const contact_law::Linearised now = contact_law::linearise(p.params, p.inertia, p.overlap - along);
      const double f0 = contact_law::linearise(p.params, p.inertia, p.overlap).force;
      const Vec3 linear = e0.k_n * along * p.n + e0.k_t * across;
      const Vec3 actual = -(now.force - f0) * p.n + now.tangential * across;
      const Vec3 f = linear - actual;
      add(p.i, 0, f);
      add(p.j, 0, -1.0 * f);
      if (dofs == 6) {
        add(p.i, 3, cross(e0.arm_i * p.n, f));
        add(p.j, 3, cross(e0.arm_j * p.n, f));
      }
    }
  };
  auto residual_at = [&](const Eigen::VectorXd& u, double w) {  // K u - rhs - h(u), zero on held DOFs
    platen_loads(u, w, h, tangent, floor);
    solver.multiply(u, Kx);
    residual = Kx - rhs - h;
    add_contact_correction(u, residual);
    for (Eigen::Index i = 0; i < n; ++i) {
      if (held(static_cast<std::size_t>(i))) residual[i] = 0.0;
    }
    return residual.norm();
  };
  double newton_seconds = 0.0;
  SparseSolveReport setup;  // the first solve's: the preconditioner's set-up and AMG's levels
  // The particle contacts' tangents at u less those in K (linearised at the start): their
  // overlaps have changed by -n.(u_j - u_i) (Hertz contacts stiffen as they close; those that
  // opened drop out).
  auto contact_change_at = [&](const Eigen::VectorXd& u) {
    for (std::size_t k = 0; k < pairs.size(); ++k) {
      contacts[k] =
          contact_element(model, pairs[k], pairs[k].overlap + approach(pairs[k], u, dofs));
    }
    return ContactStiffnessChange(model.particles.size(), dofs, start_elements, contacts, c.fixed);
  };

  // Newton's method for the operating point at travel w: (K + diag(dF/d delta)) dx = -R, each step
  // solved to the forcing tolerance below and damped by a line search, until
  // ||R|| <= tolerance ||h||. The defaults (DsmOptions: 1e-3 here, and 1e-4 for the tangent solves
  // then) moved K by at most 9e-5 relative against 1e-4 and 1e-6 on three case 2 agglomerates of
  // 2,000 particles and by 1.4e-5 on the 1e5-particle cylinder, 30 times below the method's error
  // against the DEM, for 39 % fewer CG iterations there (measured 2026-12-02); 2e-2 here moved K
  // by up to 1.3e-3.
  auto find_operating_point = [&](double w) {
    double norm_r = residual_at(x, w);
    constexpr int kMaxNewton = 40;
    for (int iterations = 0;; ++iterations, ++r.newton_iterations) {
      if (norm_r <= options.operating_point_tolerance * h.norm()) break;
      if (iterations == kMaxNewton || !std::isfinite(norm_r)) {
        throw InputError("dsm", "the platen contacts' operating point was not found (relative residual " +
                                    std::to_string(norm_r / h.norm()) + " after " + std::to_string(iterations) +
                                    " Newton steps)",
                         "check that the sample touches both platens; dsm-kinematic needs no contacts");
      }
      // The step's linear tolerance (Eisenstat and Walker's "forcing term"): 1e-2, or looser when
      // the residual is already near the target (a step need only take it there, with a margin).
      // On the 1e5 cylinder the last step of the second point went from 20 CG iterations at 1e-2
      // to 2 (its residual was 1.07e-3 against the target 1e-3).
      const double relative = norm_r / h.norm();
      const double forcing = std::clamp(0.3 * options.operating_point_tolerance / relative, 1e-2, 0.5);
      Eigen::VectorXd step = Eigen::VectorXd::Zero(n);
      const SparseSolveReport report = solver.solve(tangent, -residual, step, forcing);
      newton_seconds += report.seconds;
      if (report.setup_seconds > 0.0) setup = report;
      r.krylov_iterations += report.iterations;
      double lambda = 1.0;
      Eigen::VectorXd trial = x + step;
      double trial_norm = residual_at(trial, w);
      for (int halving = 0; halving < 12 && !(trial_norm < (1.0 - 1e-4 * lambda) * norm_r); ++halving) {
        lambda *= 0.5;
        trial = x + lambda * step;
        trial_norm = residual_at(trial, w);
      }
      x = trial;
      norm_r = trial_norm;
    }
    r.residual = std::max(r.residual, norm_r / h.norm());
  };

  // The linear DSM proper at an operating point: K plus the platen springs' tangents T, loaded by
  // the travel of the upper platen (Jarolin Eq. 9 with the walls of section 3.1.3). v = dx/dw
  // solves (K + T) v = dh/dw, whose only entries are the upper springs' -sign T; then
  // dF_top/dw = sum over the upper springs of T (1 + sign v) (d delta / dw = 1 + sign v).
  Eigen::VectorXd v;
  // y = (K + added + diag(tangent)) u, the operator of the tangent solves; zero on the held DOFs.
  auto tangent_product = [&](const Eigen::VectorXd& u, const AddedProduct* added, Eigen::VectorXd& y) {
    solver.multiply(u, y);
    y += tangent.cwiseProduct(u);
    if (added) (*added)(u.data(), y.data());
    for (Eigen::Index i = 0; i < n; ++i) {
      if (held(static_cast<std::size_t>(i))) y[i] = 0.0;
    }
  };
  // rho^T u for the residual rho = b - A u of a tangent solve (A: tangent_product).
  auto residual_times = [&](const Eigen::VectorXd& b, const Eigen::VectorXd& u, const AddedProduct* added) {
    tangent_product(u, added, Kx);
    return (b - Kx).dot(u);
  };
  // The combination of two guesses of A v = b with the least A-norm error (a 2 x 2 Galerkin
  // system, two products). From the second point on, the secant field x/w and the previous
  // point's tangent: on the 1e5 cylinder the second tangent solve took 3 CG iterations from
  // their combination, 5 from the previous tangent and 6 from x/w (2026-12-03).
  auto galerkin_start = [&](const Eigen::VectorXd& first, const Eigen::VectorXd& second, const Eigen::VectorXd& b,
                            const AddedProduct* added) {
    Eigen::VectorXd A1, A2;
    tangent_product(first, added, A1);
    tangent_product(second, added, A2);
    const double cross = 0.5 * (first.dot(A2) + second.dot(A1));
    Eigen::Matrix2d G;
    G << first.dot(A1), cross, cross, second.dot(A2);
    const Eigen::Vector2d weight = G.ldlt().solve(Eigen::Vector2d(first.dot(b), second.dot(b)));
    return weight.allFinite() ? Eigen::VectorXd(weight[0] * first + weight[1] * second) : first;
  };
  auto tangent_stiffness = [&](double w) {
    platen_loads(x, w, h, tangent, 0.0);
    Eigen::VectorXd b = Eigen::VectorXd::Zero(n);
    for (const PlatenSpring& s : walls.springs) {
      const std::size_t dof = walls.axial_dof(s);
      if (s.top && !held(dof)) b[static_cast<Eigen::Index>(dof)] = walls.direction(s) * tangent[static_cast<Eigen::Index>(dof)];
    }
    const Eigen::VectorXd previous = v;  // the last point's tangent (empty at the first)
    v = x / w;  // the secant field: a close initial guess
    for (Eigen::Index i = 0; i < n; ++i) {
      if (held(static_cast<std::size_t>(i))) v[i] = 0.0;
    }
    // The particle contacts' tangents at this operating point: K holds them linearised at the
    // start, the solve adds the change (contact_change.hpp).
    const auto t0 = std::chrono::steady_clock::now();
    const ContactStiffnessChange change = contact_change_at(x);
    const AddedProduct added = [&change](const double* in, double* out) { change.add_product(in, out); };
    r.assembly_seconds += seconds_since(t0);
    const AddedProduct* with = change.empty() ? nullptr : &added;
    if (previous.size() == n) v = galerkin_start(v, previous, b, with);
    r.solve = solver.solve(tangent, b, v, options.tangent_tolerance, with);
    if (r.solve.setup_seconds > 0.0) setup = r.solve;
    double slope = 0.0;
    r.force_top = r.force_bottom = 0.0;
    for (const PlatenSpring& s : walls.springs) {
      const std::size_t dof = walls.axial_dof(s);
      if (held(dof)) continue;
      const contact_law::Linearised l = contact_law::linearise(s.params, s.inertia, walls.overlap(s, x.data(), w));
      if (s.top) {
        r.force_top += l.force;
        slope += l.normal_tangent * (1.0 + walls.sign * v[static_cast<Eigen::Index>(dof)]);
      } else {
        r.force_bottom += l.force;
      }
    }
    // The slope is sum T - b^T v, first order in v's error e. With the solve's residual
    // rho = b - A v, b^T v + rho^T v = 2 b^T v - v^T A v is b^T v* - e^T A e (A symmetric): second
    // order, which lets the tangent solves stop at 1e-3 (DsmOptions::tangent_tolerance).
    return slope - residual_times(b, v, with);
  };

  double solve_seconds = 0.0;
  r.stiffness = 0.0;
  for (std::size_t k = 0; k < travels.size(); ++k) {
    // Each point after the first starts on the previous one's tangent: x(w1) + (w2 - w1) dx/dw,
    // where v = dx/dw (a Newton predictor: the contacts that close between the points are already
    // partly in it).
    if (k > 0) x += (travels[k] - travels[k - 1]) * v;
    find_operating_point(travels[k]);
    r.stiffness += rule.weight[k] * tangent_stiffness(travels[k]);
    solve_seconds += r.solve.seconds;
  }
  r.solve.seconds = solve_seconds + newton_seconds;
  r.solve.setup_seconds = setup.setup_seconds;
  r.solve.levels = setup.levels;
  r.secant_stiffness = r.force_top / travels.back();
  r.youngs_modulus = r.stiffness * load.sample.length / load.sample.area;
  // The field at the full travel, on the tangent line through the upper operating point.
  const Eigen::VectorXd u = x + (load.displacement - travels.back()) * v;
  for (const StaticContact& p : pairs) {  // how far the listed pairs closed (contact_listing_band)
    r.max_pair_approach = std::max(r.max_pair_approach, approach(p, u, dofs));
  }
  set_fields(model, c, u, r);
  r.seconds = seconds_since(start);
  return r;
}

}  // namespace

DsmResult solve_dsm_linear(const Model& model, const PlatenLoading& load,
                           const DsmOptions& options) {
  const double widest = platen_listing_band(model, load);
  const double band =
      options.pair_band > 0.0 ? options.pair_band : contact_listing_band(model, load);
  DsmResult r = solve_with_pair_band(model, load, options, band);
  // A listed pair that closed by more than half the band's margin means a pair beyond the band
  // may have closed too: list every pair within the platen travel (the bound) and solve again.
  const double margin = band - listing_slack(model);
  if (band < widest && r.max_pair_approach > 0.5 * margin) {
    const double seconds = r.seconds;
    r = solve_with_pair_band(model, load, options, widest);
    r.seconds += seconds;
  }
  return r;
}

}  // namespace bpm
