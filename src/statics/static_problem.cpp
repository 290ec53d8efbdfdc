#include "statics/static_problem.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/error.hpp"
#include "core/parallel.hpp"
#include "solvers/distributed_solver.hpp"
#include "solvers/mpi_world.hpp"
#include "statics/static_assembly.hpp"

namespace bpm {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// K_0 with the constraints eliminated as the solver of its shifted systems, and in rhs (whole) the
/// constraints' right-hand side. One process: ShiftedSpdSolver. Under mpirun each rank assembles
/// the rows of its range of particles (row_partition, weighted by K's row blocks) into a
/// DistributedShiftedSolver.
std::unique_ptr<ShiftedSystem> shifted_system(const Model& model, int dofs,
                                              const std::vector<StaticContact>& pairs,
                                              const DofConstraints& c,
                                              const SparseSolverOptions& options,
                                              Eigen::VectorXd& rhs, std::size_t& nonzeros) {
  const mpi::World world = mpi::world();
  if (!world.distributed()) {
    SparseMatrixRM K = assemble_stiffness(model, dofs, pairs);
    rhs = Eigen::VectorXd::Zero(K.rows());
    apply_constraints(K, rhs, c);
    nonzeros = static_cast<std::size_t>(K.nonZeros());
    return std::make_unique<ShiftedSpdSolver>(std::move(K), options);
  }
  std::vector<std::int32_t> contact_ends;
  for (const StaticContact& e : pairs) {
    contact_ends.push_back(e.i);
    if (!e.wall()) contact_ends.push_back(e.j);
  }
  std::vector<int> row_start = row_partition(model, contact_ends, dofs, world.size);
  const auto rank = static_cast<std::size_t>(world.rank);
  const auto first = static_cast<std::size_t>(row_start[rank] / dofs);
  const auto last = static_cast<std::size_t>(row_start[rank + 1] / dofs);
  SparseMatrixRM K = assemble_stiffness(model, dofs, pairs, {first, last});
  Eigen::VectorXd rows = Eigen::VectorXd::Zero(K.rows());
  apply_constraints(K, rows, c, static_cast<std::size_t>(row_start[rank]));
  auto solver =
      std::make_unique<DistributedShiftedSolver>(std::move(K), std::move(row_start), options);
  solver->gather(rows, rhs);
  nonzeros = solver->nonzeros();
  return solver;
}

}  // namespace

StaticProblem::StaticProblem(const Model& model, const DofConstraints& constraints,
                             std::vector<StaticContact> contacts,
                             const StaticProblemOptions& options, const Eigen::MatrixXd& coarse)
    : model_(model),
      c_(constraints),
      options_(options),
      dofs_(options.dofs),
      contacts_(std::move(contacts)) {
  const auto start = std::chrono::steady_clock::now();
  const BondStore& b = model.bonds;
  for (std::size_t k = 0; options.bond_axes && k < b.size(); ++k) {
    if (!b.intact[k]) continue;  // the assembly's rule: K_b holds the intact bonds only
    const Vec3 d = model.particles.position[static_cast<std::size_t>(b.beta[k])] -
                   model.particles.position[static_cast<std::size_t>(b.alpha[k])];
    const double length = norm(d);
    bond_axes_.push_back({b.alpha[k], b.beta[k], d / length, length, b.stiffness[k].k_n});
  }
  start_ = contacts_;
  for (StaticContact& s : start_) {
    if (s.wall()) s.k_n = s.k_t = 0.0;  // the walls are the shift and the added product, not K_0
  }
  for (const StaticContact& s : contacts_) {
    force0_.push_back(s.overlap > 0.0 ? contact_law::linearise(s.params, s.inertia, s.overlap).force
                                      : 0.0);
  }
  spring_.assign(contacts_.size(), Vec3{});
  trial_ = slide_from_ = slide_trial_ = spring_;
  SparseSolverOptions solver = options.solver;
  solver.block_size = dofs_;
  solver.nodal_coarsening = coarse.cols() > 0;  // with the deflated rigid modes (sparse_solver.hpp)
  system_ = shifted_system(model, dofs_, start_, constraints, solver, rhs_, nonzeros_);
  if (system_->kind() == SparseSolverKind::amg_pcg && coarse.cols() > 0)
    system_->set_coarse_space(coarse);
  x_ = Eigen::VectorXd::Zero(rhs_.size());
  for (Eigen::Index i = 0; i < x_.size(); ++i) {
    if (c_.fixed[static_cast<std::size_t>(i)]) x_[i] = c_.value[static_cast<std::size_t>(i)];
  }
  work_.assembly_seconds = seconds_since(start);
}

StaticProblem::~StaticProblem() = default;

double StaticProblem::approach(std::size_t k, const Eigen::VectorXd& u) const {
  const StaticContact& p = contacts_[k];
  auto at = [&](std::int32_t q) { return static_cast<Eigen::Index>(dofs_) * q; };
  const Vec3 ui{u[at(p.i)], u[at(p.i) + 1], u[at(p.i) + 2]};
  const Vec3 uj = p.wall() ? Vec3{} : Vec3{u[at(p.j)], u[at(p.j) + 1], u[at(p.j) + 2]};
  return -dot(p.n, uj - ui);
}

double StaticProblem::evaluate(const Eigen::VectorXd& x, double w) {
  system_->multiply(x, residual_);
  residual_ -= rhs_;
  shift_.setZero(x.size());
  auto at = [&](std::int32_t q, int k) { return static_cast<Eigen::Index>(dofs_) * q + k; };
  auto vec = [&](std::int32_t q, int k0) {
    return Vec3{x[at(q, k0)], x[at(q, k0 + 1)], x[at(q, k0 + 2)]};
  };
  auto add = [&](std::int32_t q, int k0, const Vec3& v) {
    for (int k = 0; k < 3; ++k) residual_[at(q, k0 + k)] += v[k];
  };
  // Each bond's and each contact's force is computed on its own (in parallel) and then added to
  // its particles in their fixed order: the residual does not depend on the number of threads.
  // The bonds' normal forces along their current axes: K_b x holds k_n a n_0 on alpha (a = n_0 .
  // du), the DEM's is k_n s n with s = L - L_0, n = (L_0 n_0 + du) / L. Their difference is of
  // second order in du; it is written so (s = (2 L_0 a + |du|^2) / (L + L_0), and the n_0 part's
  // first-order terms cancelled by hand) that no first-order terms cancel in round-off, which a
  // stiff bond would multiply.
  bond_force_.resize(bond_axes_.size());
  parallel_for(static_cast<std::int64_t>(bond_axes_.size()), [&](std::int64_t k) {
    const BondAxis& b = bond_axes_[static_cast<std::size_t>(k)];
    const Vec3 du = vec(b.beta, 0) - vec(b.alpha, 0);
    const double a = dot(b.n, du), du2 = norm2(du), l0 = b.length;
    const double length = norm(l0 * b.n + du);
    const double s = (2.0 * l0 * a + du2) / (length + l0);
    const double along = (l0 * (du2 - a * s - 2.0 * a * a) - a * du2) / (length * (length + l0));
    bond_force_[static_cast<std::size_t>(k)] =
        b.k_n * (along * b.n + (s / length) * du);  // on alpha
  });
  for (std::size_t k = 0; k < bond_axes_.size(); ++k) {
    add(bond_axes_[k].alpha, 0, -1.0 * bond_force_[k]);
    add(bond_axes_[k].beta, 0, bond_force_[k]);
  }
  contact_force_.resize(contacts_.size());
  parallel_for(static_cast<std::int64_t>(contacts_.size()), [&](std::int64_t index) {
    const auto k = static_cast<std::size_t>(index);
    StaticContact& c = contacts_[k];
    const StaticContact& c0 = start_[k];
    const bool wall = c.wall();
    // Delta = u_j + [a_j n]x theta_j - u_i + [a_i n]x theta_i (static_contact.hpp).
    Vec3 delta = (wall ? w * c.wall_motion : vec(c.j, 0)) - vec(c.i, 0);
    if (dofs_ == 6) {
      delta += cross(c.arm_i * c.n, vec(c.i, 3));
      if (!wall) delta += cross(c.arm_j * c.n, vec(c.j, 3));
    }
    const double along = dot(c.n, delta);
    const Vec3 across = delta - along * c.n;
    const double overlap = c.overlap - along;
    const contact_law::Linearised l = contact_law::linearise(c.params, c.inertia, overlap);
    const double k_t = c.params.friction > 0.0 ? l.tangential : 0.0;
    Vec3 f_t;
    double ratio = 1.0;
    trial_[k] = {};
    slide_trial_[k] = across;
    if (overlap > 0.0 && k_t > 0.0) {
      // The DEM's spring: what the last state held plus the tangential motion since (zero when the
      // contact was apart then: spring_ is dropped on opening).
      trial_[k] = spring_[k] + (across - slide_from_[k]);
      f_t = k_t * trial_[k];
      const double limit = c.params.friction * std::max(l.force, 0.0);
      const double size = norm(f_t);
      if (options_.slip && size > limit) {  // sliding: the Coulomb force, the spring holds it
        ratio = size > 0.0 ? limit / size : 0.0;
        f_t = ratio * f_t;
        trial_[k] = (1.0 / k_t) * f_t;
      }
    }
    c.k_n = l.normal_tangent;
    // Newton's matrix: a sliding contact's secant; the loading tangent: nothing (below).
    c.k_t = ratio < 1.0 && loading_tangent_ ? 0.0 : ratio * k_t;
    const Vec3 on_i = -(l.force - force0_[k]) * c.n + f_t;  // the contact's force on i
    // R = K_0 x - f + (C_0 Delta - f_i) on i, the opposite on j (K_0 holds the pairs as C_0).
    contact_force_[k] = {c0.k_t * delta + (c0.k_n - c0.k_t) * along * c.n - on_i, norm2(on_i)};
  });
  double load2 = 0.0;
  for (std::size_t k = 0; k < contacts_.size(); ++k) {
    const StaticContact& c = contacts_[k];
    const Vec3& g = contact_force_[k].g;
    add(c.i, 0, g);
    if (dofs_ == 6) add(c.i, 3, cross(c.arm_i * c.n, g));
    if (!c.wall()) {
      add(c.j, 0, -1.0 * g);
      if (dofs_ == 6) add(c.j, 3, cross(c.arm_j * c.n, g));
      continue;
    }
    load2 += contact_force_[k].on_i2;
    // The wall's translation block k_n n n^T + k_t (I - n n^T) is diagonal (n along an axis).
    for (int q = 0; q < 3; ++q) {
      const double nn = c.n[q] * c.n[q];
      shift_[at(c.i, q)] += std::max(c.k_n, floor_) * nn + c.k_t * (1.0 - nn);
    }
  }
  for (Eigen::Index i = 0; i < residual_.size(); ++i) {
    if (c_.fixed[static_cast<std::size_t>(i)]) residual_[i] = shift_[i] = 0.0;
  }
  load_ = Eigen::VectorXd::Constant(1, std::sqrt(load2));
  return residual_.norm();
}

ContactStiffnessChange StaticProblem::tangent_change() const {
  return ContactStiffnessChange(model_.particles.size(), dofs_, start_, contacts_, c_.fixed,
                                /*walls_on_diagonal=*/true);
}

void StaticProblem::tangent_product(const Eigen::VectorXd& u, const AddedProduct* added,
                                    Eigen::VectorXd& y) const {
  system_->multiply(u, y);
  y += shift_.cwiseProduct(u);
  if (added) (*added)(u.data(), y.data());
  for (Eigen::Index i = 0; i < y.size(); ++i) {
    if (c_.fixed[static_cast<std::size_t>(i)]) y[i] = 0.0;
  }
}

void StaticProblem::solve(double w, double tolerance, const char* method) {
  if (floor_ == 0.0) {
    // Keeps a wall spring that has opened in Newton's matrix (its steps only; the converged field
    // does not depend on it): 1e-3 of a wall's tangent at a quarter of the travel.
    for (const StaticContact& c : contacts_) {
      if (!c.wall()) continue;
      const double travel = w * norm(c.wall_motion);
      if (travel > 0.0) {
        floor_ = 1e-3 * contact_law::linearise(c.params, c.inertia, 0.25 * travel).normal_tangent;
        break;
      }
    }
  }
  double norm_r = evaluate(x_, w);
  constexpr int kMaxNewton = 40;
  for (int iterations = 0;; ++iterations, ++work_.newton_iterations) {
    const double scale = load_[0] > 0.0 ? load_[0] : 1.0;
    if (norm_r <= tolerance * scale) break;
    if (iterations == kMaxNewton || !std::isfinite(norm_r)) {
      char relative[32];
      std::snprintf(relative, sizeof relative, "%.3g", norm_r / scale);
      throw InputError(
          method,
          std::string("the static equilibrium was not found at platen travel ") +
              std::to_string(w) + " m (relative residual " + relative + " after " +
              std::to_string(iterations) + " Newton steps)",
          "check that the sample touches both platens; dsm-kinematic needs no contacts");
    }
    // The step's linear tolerance (Eisenstat and Walker's "forcing term"): 0.1, or looser when
    // the residual is already near the target (a step need only take it there, with a margin).
    // 0.1 instead of 1e-2 took 8-24 % fewer CG iterations on the study's samples and the 1e5
    // cylinder (a Newton step more here and there), K within 3e-5.
    const double forcing = std::clamp(0.3 * tolerance * scale / norm_r, 0.1, 0.5);
    const ContactStiffnessChange change = tangent_change();
    const AddedProduct added = [&change](const double* in, double* out) {
      change.add_product(in, out);
    };
    Eigen::VectorXd step = Eigen::VectorXd::Zero(x_.size());
    const Eigen::VectorXd rhs = -residual_;
    const SparseSolveReport report =
        system_->solve(shift_, rhs, step, forcing, change.empty() ? nullptr : &added);
    work_.solve_seconds += report.seconds;
    if (report.setup_seconds > 0.0) work_.setup = report;
    work_.krylov_iterations += report.iterations;
    double lambda = 1.0;
    Eigen::VectorXd trial = x_ + step;
    double trial_norm = evaluate(trial, w);
    for (int halving = 0; halving < 12 && !(trial_norm < (1.0 - 1e-4 * lambda) * norm_r);
         ++halving) {
      lambda *= 0.5;
      trial = x_ + lambda * step;
      trial_norm = evaluate(trial, w);
    }
    x_ = trial;
    norm_r = trial_norm;
  }
  relative_residual_ = std::max(relative_residual_, norm_r / (load_[0] > 0.0 ? load_[0] : 1.0));
}

void StaticProblem::commit() {
  spring_ = trial_;
  slide_from_ = slide_trial_;
}

double StaticProblem::tangent_stiffness(double w, double tolerance, Eigen::VectorXd& v,
                                        const Eigen::VectorXd& guess) {
  const double floor = floor_;
  floor_ = 0.0;  // the exact tangent
  loading_tangent_ = true;
  evaluate(x_, w);
  loading_tangent_ = false;
  floor_ = floor;
  const auto start = std::chrono::steady_clock::now();
  const ContactStiffnessChange change = tangent_change();
  const AddedProduct added = [&change](const double* in, double* out) {
    change.add_product(in, out);
  };
  const AddedProduct* with = change.empty() ? nullptr : &added;
  work_.assembly_seconds += seconds_since(start);
  // b = dh/dw at fixed x: each moving wall's spring C (its motion m) on its particle, and the
  // moving walls' force grows by sum k_n (n.m)^2 at fixed x (they approach: n.m = -1).
  Eigen::VectorXd b = Eigen::VectorXd::Zero(x_.size());
  double slope = 0.0;
  for (const StaticContact& c : contacts_) {
    if (!c.wall() || norm2(c.wall_motion) == 0.0) continue;
    const double nm = dot(c.n, c.wall_motion);
    const Vec3 f = c.k_n * nm * c.n + c.k_t * (c.wall_motion - nm * c.n);
    slope += c.k_n * nm * nm;
    for (int k = 0; k < 3; ++k) b[dofs_ * c.i + k] += f[k];
    if (dofs_ == 6) {
      const Vec3 t = cross(c.arm_i * c.n, f);
      for (int k = 0; k < 3; ++k) b[dofs_ * c.i + 3 + k] += t[k];
    }
  }
  for (Eigen::Index i = 0; i < b.size(); ++i) {
    if (c_.fixed[static_cast<std::size_t>(i)]) b[i] = 0.0;
  }
  v = guess.size() == x_.size() ? guess : Eigen::VectorXd(x_ / w);
  for (Eigen::Index i = 0; i < v.size(); ++i) {
    if (c_.fixed[static_cast<std::size_t>(i)]) v[i] = 0.0;
  }
  const SparseSolveReport report = system_->solve(shift_, b, v, tolerance, with);
  work_.solve_seconds += report.seconds;
  work_.krylov_iterations += report.iterations;
  if (report.setup_seconds > 0.0) work_.setup = report;
  // dF/dw = sum k_n - b^T v*; with the solve's residual rho = b - A v, 2 b^T v - v^T A v is b^T v*
  // less e^T A e (A symmetric): second order in v's error e, so the solve may stop early.
  Eigen::VectorXd Av;
  tangent_product(v, with, Av);
  return slope - (2.0 * b.dot(v) - v.dot(Av));
}

double StaticProblem::wall_force(double w, bool moving) const {
  double force = 0.0;
  auto at = [&](std::int32_t q) { return static_cast<Eigen::Index>(dofs_) * q; };
  for (const StaticContact& c : contacts_) {
    if (!c.wall() || (norm2(c.wall_motion) > 0.0) != moving) continue;
    const Vec3 u{x_[at(c.i)], x_[at(c.i) + 1], x_[at(c.i) + 2]};
    const double overlap = c.overlap - dot(c.n, w * c.wall_motion - u);
    force += contact_law::linearise(c.params, c.inertia, overlap).force;
  }
  return force;
}

}  // namespace bpm
