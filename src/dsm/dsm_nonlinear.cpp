#include "dsm/dsm_nonlinear.hpp"

#include <kinsol/kinsol.h>
#include <nvector/nvector_parallel.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_spgmr.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <memory>
#include <string>
#include <utility>

#include "contacts/contact_law.hpp"
#include "dem/static_contacts.hpp"
#include "core/error.hpp"
#include "dsm/contact_element.hpp"
#include "dsm/distributed_amg.hpp"
#include "dsm/distributed_solver.hpp"
#include "dsm/dsm_assembly.hpp"
#include "dsm/dsm_constraints.hpp"
#include "dsm/fit_window.hpp"
#include "dsm/mpi_world.hpp"
#include "dsm/platen_springs.hpp"
#include "dsm/sparse_solver.hpp"

namespace bpm {
namespace {

/// A listed particle pair: constant direction n (alpha -> beta), initial overlap, constants.
struct ContactPair {
  std::int32_t a = 0, b = 0;
  Vec3 n;
  double overlap0 = 0.0;
  ContactPairParameters params;
  contact_law::PairInertia inertia;
  Vec3 force0;  ///< normal force on a at the start (prestress, subtracted)
};

struct Problem {
  Problem(const Model& m, const PlatenLoading& l) : model(m), load(l) {}
  const Model& model;
  const PlatenLoading& load;
  int dofs = 6;
  int ax = 2;
  double sign = 1.0;  ///< axis = sign * e_ax
  /// Under mpirun each rank holds the rows [row_start[rank], row_start[rank + 1]) of K, of the
  /// preconditioner and of KINSOL's vectors (nvector_parallel); {0, N} on one process. The contact
  /// and wall loads are computed on the whole field, gathered on every rank.
  std::vector<int> row_start;
  bool distributed = false;
  int first = 0, rows = 0;   ///< this rank's first row and row count
  SparseMatrixRM K;     ///< this rank's rows of the bonds' K, constrained DOFs eliminated
  Eigen::VectorXd rhs;  ///< those rows of the constraints' right-hand side
  std::vector<std::uint8_t> fixed;
  const DofConstraints* constraints = nullptr;
  PlatenSprings walls;
  std::vector<ContactPair> pairs;
  double displacement = 0.0;  ///< of the upper wall, m
  SparseSolverOptions solver;  ///< picks the preconditioner (CHOLMOD or one AMG V-cycle) by size
  std::unique_ptr<SpdPreconditioner> preconditioner;          ///< one process
  std::unique_ptr<DistributedAmg> distributed_preconditioner;  ///< under mpirun
  mutable Eigen::VectorXd whole;  ///< the gathered field (under mpirun)

  /// The whole field from this rank's rows x (x itself on one process).
  const double* whole_field(const double* x) const {
    if (!distributed) return x;
    gather_rows(x, row_start, whole);
    return whole.data();
  }

  Vec3 u(const double* x, std::int32_t p) const {
    const double* v = x + static_cast<std::ptrdiff_t>(dofs) * p;
    return {v[0], v[1], v[2]};
  }
  Vec3 theta(const double* x, std::int32_t p) const {
    if (dofs == 3) return {};
    const double* v = x + static_cast<std::ptrdiff_t>(dofs) * p + 3;
    return {v[0], v[1], v[2]};
  }

  /// Overlap of a platen spring at displacement field x.
  double wall_overlap(const PlatenSpring& w, const double* x) const { return walls.overlap(w, x, displacement); }

  /// External (contact and wall) loads on every DOF, added to out with factor `scale`.
  void add_contact_loads(const double* x, double* out, double scale) const {
    auto add = [&](std::int32_t p, int k0, const Vec3& v) {
      double* o = out + static_cast<std::ptrdiff_t>(dofs) * p + k0;
      for (int k = 0; k < 3; ++k) o[k] += scale * v[k];
    };
    for (const PlatenSpring& w : walls.springs) {
      Vec3 f;
      f[ax] = walls.direction(w) * contact_law::linearise(w.params, w.inertia, wall_overlap(w, x)).force;
      add(w.particle, 0, f);
    }
    const ParticleStore& p = model.particles;
    for (const ContactPair& c : pairs) {
      const Vec3 ua = u(x, c.a), ub = u(x, c.b), ta = theta(x, c.a), tb = theta(x, c.b);
      const double overlap = c.overlap0 - dot(c.n, ub - ua);
      const contact_law::Linearised s = contact_law::linearise(c.params, c.inertia, overlap);
      // Relative displacement of b's surface point against a's at the contact.
      const Vec3 relative = (ub + cross(tb, -p.radius[c.b] * c.n)) - (ua + cross(ta, p.radius[c.a] * c.n));
      const Vec3 tangential = relative - dot(relative, c.n) * c.n;
      const Vec3 tangential_force = contact_law::coulomb_capped(c.params, s.tangential, s.force, tangential);
      const Vec3 on_a = -s.force * c.n + tangential_force - c.force0;
      add(c.a, 0, on_a);
      add(c.b, 0, -1.0 * on_a);
      if (dofs == 6) {
        add(c.a, 3, cross(p.radius[c.a] * c.n, tangential_force));
        add(c.b, 3, cross(-p.radius[c.b] * c.n, -1.0 * tangential_force));
      }
    }
  }

  /// Residual R(x) = K x - rhs - h(x), with h zero on the constrained DOFs (this rank's rows).
  void residual(const double* x, double* r) const {
    const double* field = whole_field(x);
    Eigen::Map<const Eigen::VectorXd> xv(field, K.cols());
    Eigen::Map<Eigen::VectorXd> rv(r, rows);
    rv.noalias() = K * xv - rhs;
    Eigen::VectorXd h = Eigen::VectorXd::Zero(K.cols());
    add_contact_loads(field, h.data(), 1.0);
    for (Eigen::Index i = 0; i < rows; ++i) {
      if (!fixed[static_cast<std::size_t>(first + i)]) rv[i] -= h[first + i];
    }
  }

  /// The Jacobian without the finite differences: the bonds, every listed contact as the element
  /// of its tangent at the current overlap (contact_element.hpp; off-diagonal couplings included,
  /// which a contact-dominated sample needs), and the platen springs' tangents on the diagonal.
  void set_up_preconditioner(const double* x_rows, double wall_floor) {
    const double* x = whole_field(x_rows);
    std::vector<ContactElement> elements;
    elements.reserve(pairs.size());
    const ParticleStore& p = model.particles;
    for (const ContactPair& c : pairs) {
      const double overlap = c.overlap0 - dot(c.n, u(x, c.b) - u(x, c.a));
      const contact_law::Linearised s = contact_law::linearise(c.params, c.inertia, overlap);
      elements.push_back({c.a, c.b, c.n, p.radius[static_cast<std::size_t>(c.a)], p.radius[static_cast<std::size_t>(c.b)],
                          s.normal_tangent, s.tangential});
    }
    const auto particles = [&](int row) { return static_cast<std::size_t>(row / dofs); };
    SparseMatrixRM P = assemble_stiffness(model, dofs, elements, {particles(first), particles(first + rows)});
    Eigen::VectorXd unused = Eigen::VectorXd::Zero(P.rows());
    apply_constraints(P, unused, *constraints, static_cast<std::size_t>(first));
    for (const PlatenSpring& w : walls.springs) {
      const auto dof = static_cast<Eigen::Index>(walls.axial_dof(w));
      if (fixed[static_cast<std::size_t>(dof)] || dof < first || dof >= first + rows) continue;
      const double k = std::max(contact_law::linearise(w.params, w.inertia, wall_overlap(w, x)).normal_tangent, wall_floor);
      P.coeffRef(dof - first, dof) += k;
    }
    preconditioner.reset();  // the old one's memory first
    distributed_preconditioner.reset();
    if (distributed) {
      P.makeCompressed();
      distributed_preconditioner = std::make_unique<DistributedAmg>(P, row_start, solver);
    } else {
      preconditioner = std::make_unique<SpdPreconditioner>(std::move(P), solver);
    }
  }

  /// z = M^-1 r on this rank's rows, in place.
  void precondition(double* v) const {
    Eigen::Map<Eigen::VectorXd> r(v, rows);
    if (distributed) {
      const Eigen::VectorXd in = r;
      distributed_preconditioner->apply(in.data(), v);
      return;
    }
    Eigen::VectorXd z;
    preconditioner->apply(r, z);
    r = z;
  }
};

struct KinsolData {
  Problem* problem;
  double wall_floor;
  /// An exception thrown inside a callback (e.g. a solver running out of memory); it must not cross
  /// KINSOL's C frames, so the callback returns a failure and the solve rethrows it afterwards.
  std::exception_ptr error;
};

/// Runs f for a KINSOL callback: 0 on success, -1 (unrecoverable) with the exception kept.
template <class F>
int guarded(void* data, F&& f) {
  auto* d = static_cast<KinsolData*>(data);
  try {
    f(*d);
    return 0;
  } catch (...) {
    d->error = std::current_exception();
    return -1;
  }
}

int residual_kinsol(N_Vector x, N_Vector r, void* data) {
  return guarded(data, [&](KinsolData& d) { d.problem->residual(N_VGetArrayPointer(x), N_VGetArrayPointer(r)); });
}

int setup_callback(N_Vector x, N_Vector, N_Vector, N_Vector, void* data) {
  return guarded(data, [&](KinsolData& d) { d.problem->set_up_preconditioner(N_VGetArrayPointer(x), d.wall_floor); });
}

int solve_callback(N_Vector, N_Vector, N_Vector, N_Vector, N_Vector v, void* data) {
  return guarded(data, [&](KinsolData& d) { d.problem->precondition(N_VGetArrayPointer(v)); });
}

/// Owns the SUNDIALS objects of one solve.
struct Kinsol {
  SUNContext context = nullptr;
  N_Vector x = nullptr, u_scale = nullptr, f_scale = nullptr;
  SUNLinearSolver gmres = nullptr;
  void* memory = nullptr;
  ~Kinsol() {
    if (memory) KINFree(&memory);
    if (gmres) SUNLinSolFree(gmres);
    for (N_Vector v : {x, u_scale, f_scale}) {
      if (v) N_VDestroy(v);
    }
    if (context) SUNContext_Free(&context);
  }
};

void check(int flag, const char* call) {
  if (flag < 0) throw std::runtime_error(std::string("KINSOL: ") + call + " failed with flag " + std::to_string(flag));
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

DsmResult solve_dsm_nonlinear(const Model& model, const PlatenLoading& load, const DsmOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  // The linear system first (Jarolin section 4.2: "the resulting displacement field was used as
  // initial solution"): the linear DSM with its platen walls, whose overlaps are already close.
  const DsmResult linear = solve_dsm_linear(model, load, options);

  const ParticleStore& particles = model.particles;
  const int dofs = options.dofs;
  Problem problem(model, load);
  problem.dofs = dofs;
  problem.displacement = load.displacement;
  problem.solver = options.solver;
  problem.solver.block_size = dofs;
  const DofConstraints c = platen_constraints(model, load, dofs, /*kinematic_platens=*/false);
  problem.ax = c.axial_dof;
  problem.sign = load.axis[c.axial_dof];
  problem.fixed = c.fixed;
  problem.constraints = &c;

  // Potential contacts, listed once: the pairs the linear DSM listed (its band, widened there if
  // its pairs closed by much of it; the nonlinear field is close to the linear one).
  const double mean_radius = mean_particle_radius(particles);
  const double band = linear.pair_band;

  problem.walls = list_platen_springs(model, load, c, platen_listing_band(model, load));
  for (const StaticContact& sc : list_static_contacts(model, band)) {
    ContactPair pair{sc.i, sc.j, sc.n, sc.overlap, sc.params, sc.inertia, {}};
    pair.force0 = -contact_law::linearise(sc.params, sc.inertia, sc.overlap).force * sc.n;
    problem.pairs.push_back(pair);
  }

  // This rank's rows (all of them on one process), as the linear DSM divides them.
  const mpi::World world = mpi::world();
  problem.distributed = world.distributed();
  if (problem.distributed) {
    std::vector<std::int32_t> contact_ends;
    for (const ContactPair& pair : problem.pairs) contact_ends.insert(contact_ends.end(), {pair.a, pair.b});
    problem.row_start = dsm_row_partition(model, contact_ends, dofs, world.size);
  } else {
    problem.row_start = {0, dofs * static_cast<int>(particles.size())};
  }
  const auto rank = static_cast<std::size_t>(world.rank);
  problem.first = problem.row_start[rank];
  problem.rows = problem.row_start[rank + 1] - problem.first;
  problem.K = assemble_stiffness(model, dofs, {},
                                 {static_cast<std::size_t>(problem.first / dofs),
                                  static_cast<std::size_t>((problem.first + problem.rows) / dofs)});
  problem.rhs = Eigen::VectorXd::Zero(problem.rows);
  apply_constraints(problem.K, problem.rhs, c, static_cast<std::size_t>(problem.first));

  // Scales: the mean platen contact force of the linear solution, and a floor for the wall
  // springs' tangent in the preconditioner (1e-3 of a contact carrying that force), so that a
  // spring that opens does not leave its particle without axial stiffness there.
  const double share = linear.force_top / static_cast<double>(std::max<std::size_t>(1, load.top.size()));
  double wall_floor = 0.0;
  if (share > 0.0) {
    const PlatenSpring& w = problem.walls.springs.front();
    double lo = 0.0, hi = load.displacement;  // bisection for F(delta) = share
    for (int it = 0; it < 100; ++it) {
      const double mid = 0.5 * (lo + hi);
      (contact_law::linearise(w.params, w.inertia, mid).force < share ? lo : hi) = mid;
    }
    wall_floor = 1e-3 * contact_law::linearise(w.params, w.inertia, 0.5 * (lo + hi)).normal_tangent;
  }
  // Newton-Krylov at the nodes of the fit window (below).
  const auto n = static_cast<sunindextype>(problem.rows);
  Kinsol kin;
  check(SUNContext_Create(nullptr, &kin.context), "SUNContext_Create");
  // SUNDIALS' MPI vectors under mpirun (its norms and GMRES's dot products reduce over the ranks).
  auto new_vector = [&] {
    return problem.distributed
               ? N_VNew_Parallel(MPI_COMM_WORLD, n, static_cast<sunindextype>(problem.row_start.back()), kin.context)
               : N_VNew_Serial(n, kin.context);
  };
  kin.x = new_vector();
  kin.u_scale = new_vector();
  kin.f_scale = new_vector();
  double* x = N_VGetArrayPointer(kin.x);
  double* us = N_VGetArrayPointer(kin.u_scale);
  double* fs = N_VGetArrayPointer(kin.f_scale);
  const double force_scale = std::max(share, 1e-300);
  for (sunindextype row = 0; row < n; ++row) {
    const auto i = static_cast<std::size_t>(problem.first + row);
    const std::size_t p = i / static_cast<std::size_t>(dofs);
    const int k = static_cast<int>(i % static_cast<std::size_t>(dofs));
    const Vec3& field = k < 3 ? linear.displacement[p] : linear.rotation[p];
    x[row] = c.fixed[i] ? c.value[i] : field[k % 3];
    us[row] = k < 3 ? 1.0 / load.displacement : mean_radius / load.displacement;
    fs[row] = k < 3 ? 1.0 / force_scale : 1.0 / (force_scale * mean_radius);
  }
  KinsolData data{&problem, wall_floor, nullptr};
  kin.memory = KINCreate(kin.context);
  check(KINInit(kin.memory, residual_kinsol, kin.x), "KINInit");
  check(KINSetUserData(kin.memory, &data), "KINSetUserData");
  kin.gmres = SUNLinSol_SPGMR(kin.x, SUN_PREC_RIGHT, 50, kin.context);
  check(KINSetLinearSolver(kin.memory, kin.gmres, nullptr), "KINSetLinearSolver");
  check(KINSetPreconditioner(kin.memory, setup_callback, solve_callback), "KINSetPreconditioner");
  check(KINSetFuncNormTol(kin.memory, options.nonlinear_tolerance), "KINSetFuncNormTol");
  check(KINSetScaledStepTol(kin.memory, 1e-12), "KINSetScaledStepTol");
  check(KINSetNumMaxIters(kin.memory, options.max_newton_iterations), "KINSetNumMaxIters");
  // A fresh preconditioner every second Newton step (and at the start of each KINSol call).
  // Measured on examples/04_compression/case1_cylinder (98,773 particles, 592,638 unknowns, AMG
  // preconditioner: ~4.3 s a setup, ~0.5 s a Krylov iteration with its residual evaluation; 2 cores
  // shared with another run), max setup calls -> setups, Newton / Krylov iterations, wall time:
  //   1 -> 11, 11 / 130, 145-152 s;  2 -> 5, 9 / 81, 99-108 s;  3 -> 4, 10 / 130, 124 s;
  //   5 -> 3, 13 / 228, 187 s;  10 -> 2, 13 / 228, 189 s.
  // Contacts close and stiffen during the first steps, so an older preconditioner costs more GMRES
  // iterations (and, from 5 on, backtracking line searches) than its setup saves. The small
  // cylinder (5,082 unknowns, CHOLMOD) takes 6 / 8 iterations for any of these values.
  check(KINSetMaxSetupCalls(kin.memory, 2), "KINSetMaxSetupCalls");

  DsmResult r = linear;
  auto platen_forces = [&](double& top, double& bottom) {
    const double* field = problem.whole_field(x);
    top = bottom = 0.0;
    for (const PlatenSpring& w : problem.walls.springs) {
      (w.top ? top : bottom) += contact_law::linearise(w.params, w.inertia, problem.wall_overlap(w, field)).force;
    }
  };
  // The DEM's least-squares slope over its fit window from F at the nodes of fit_window.hpp's
  // three-point rule (exact for F up to quartic; the middle node has no weight). F is smoother than
  // the linear DSM's F': on the validation study's case 2 agglomerates (6-8 particles at each
  // platen) nine points (eight nodes) moved K by at most 0.6 % for four times the work
  // (2026-12-02). Each solve starts from the last one (the first from the linear field), scaled to
  // its travel.
  const WindowRule rule = force_rule(3, load.fit_from, load.fit_to);
  const std::vector<double>& fractions = rule.travel;
  double previous = 1.0;  // the start field is for the full displacement
  r.stiffness = 0.0;
  for (std::size_t end = 0; end < fractions.size(); ++end) {
    problem.displacement = fractions[end] * load.displacement;
    for (sunindextype row = 0; row < n; ++row) {
      if (!c.fixed[static_cast<std::size_t>(problem.first + row)]) x[row] *= fractions[end] / previous;
    }
    previous = fractions[end];
    const int flag = KINSol(kin.memory, kin.x, KIN_LINESEARCH, kin.u_scale, kin.f_scale);
    if (data.error) std::rethrow_exception(data.error);
    long newton = 0, krylov = 0;
    KINGetNumNonlinSolvIters(kin.memory, &newton);
    KINGetNumLinIters(kin.memory, &krylov);
    KINGetFuncNorm(kin.memory, &r.residual);
    r.newton_iterations += static_cast<int>(newton);
    r.krylov_iterations += static_cast<int>(krylov);
    if (flag < 0) {
      throw InputError("dsm-nonlinear", "Newton-Krylov did not converge (KINSOL flag " + std::to_string(flag) +
                                            ", scaled residual " + std::to_string(r.residual) + ")",
                       "raise --nonlinear-tolerance or check that the platens touch the sample");
    }
    platen_forces(r.force_top, r.force_bottom);
    r.stiffness += rule.weight[end] * r.force_top / load.displacement;
  }
  r.potential_contacts = problem.pairs.size();
  r.potential_wall_contacts = problem.walls.springs.size();
  r.secant_stiffness = r.force_top / (fractions.back() * load.displacement);
  r.youngs_modulus = r.stiffness * load.sample.length / load.sample.area;
  // The field of the upper node, scaled to the full travel.
  Eigen::VectorXd field = Eigen::Map<const Eigen::VectorXd>(problem.whole_field(x), problem.row_start.back());
  for (Eigen::Index i = 0; i < field.size(); ++i) {
    if (!c.fixed[static_cast<std::size_t>(i)]) field[i] /= fractions.back();
  }
  set_fields(model, c, field, r);
  r.seconds = seconds_since(start);
  return r;
}

}  // namespace bpm
