#include "dsm/dsm_linear.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "statics/static_assembly.hpp"
#include "dsm/platen_constraints.hpp"

namespace bpm {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

void set_fields(const Model& model, const DofConstraints& c, const Eigen::VectorXd& u, DsmResult& r) {
  const std::size_t n = model.particles.size(), dofs = static_cast<std::size_t>(c.dofs);
  r.displacement.assign(n, {});
  r.rotation.assign(n, {});
  std::vector<bool> loaded(n, false);
  for (std::size_t p = 0; p < n; ++p) {
    for (std::size_t k = 0; k < dofs; ++k) {
      const double v = u[static_cast<Eigen::Index>(dofs * p + k)];
      if (k < 3) r.displacement[p][static_cast<int>(k)] = v;
      else r.rotation[p][static_cast<int>(k - 3)] = v;
      loaded[p] = loaded[p] || !c.fixed[dofs * p + k];
    }
  }
  // The pins' gauge is arbitrary; report the field with the centre of mass held laterally and no
  // mean spin (a rigid mode: the loads do not change).
  if (c.pinned) {
    const double spin = remove_lateral_rigid_modes(model.particles, r.loading.axis, r.displacement, loaded);
    for (std::size_t p = 0; p < n; ++p) {
      if (loaded[p] && dofs == 6) r.rotation[p] -= spin * r.loading.axis;
    }
  }
}

double remove_lateral_rigid_modes(const ParticleStore& p, const Vec3& axis, std::vector<Vec3>& u,
                                  const std::vector<bool>& include) {
  const Vec3 a = axis / norm(axis);
  double mass = 0.0;
  Vec3 centre, mean;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!include[i]) continue;
    mass += p.mass[i];
    centre += p.mass[i] * p.position[i];
    mean += p.mass[i] * u[i];
  }
  if (!(mass > 0.0)) return 0.0;
  centre = centre / mass;
  mean = mean / mass;
  mean -= dot(mean, a) * a;  // only the lateral translation is free
  double moment = 0.0, inertia = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!include[i]) continue;
    const Vec3 arm = cross(a, p.position[i] - centre);
    moment += p.mass[i] * dot(arm, u[i] - mean);
    inertia += p.mass[i] * norm2(arm);
  }
  const double spin = inertia > 0.0 ? moment / inertia : 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (include[i]) u[i] -= mean + spin * cross(a, p.position[i] - centre);
  }
  return spin;
}

double max_relative_difference(const Model& model, const PlatenLoading& load, const std::vector<Vec3>& a,
                               const std::vector<Vec3>& b) {
  std::vector<Vec3> difference(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) difference[i] = a[i] - b[i];
  if (load.frictionless) remove_lateral_rigid_modes(model.particles, load.axis, difference, std::vector<bool>(a.size(), true));
  double worst = 0.0;
  for (const Vec3& d : difference) worst = std::max(worst, norm(d));
  return worst / load.displacement;
}

DsmResult solve_dsm_kinematic(const Model& model, const PlatenLoading& load, const DsmOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  DsmResult r;
  r.loading = load;
  const int dofs = options.dofs;
  const std::vector<StaticContact> contacts = touching_contacts(model);
  r.potential_contacts = contacts.size();
  SparseMatrixRM K = assemble_stiffness(model, dofs, contacts);
  r.assembly_seconds = seconds_since(start);
  const DofConstraints c = platen_constraints(model, load, dofs, /*kinematic_platens=*/true);
  r.detached_particles = c.detached_particles;
  r.unknowns = static_cast<std::size_t>(K.rows());

  // The platen rows before elimination give the reactions.
  const int ax = c.axial_dof;
  std::vector<std::int32_t> platen_particles = load.bottom;
  platen_particles.insert(platen_particles.end(), load.top.begin(), load.top.end());
  SparseMatrixRM platen_rows(static_cast<Eigen::Index>(platen_particles.size()), K.cols());
  {
    std::vector<Eigen::Triplet<double, int>> entries;
    for (std::size_t s = 0; s < platen_particles.size(); ++s) {
      for (SparseMatrixRM::InnerIterator it(K, dofs * platen_particles[s] + ax); it; ++it) {
        entries.emplace_back(static_cast<int>(s), static_cast<int>(it.col()), it.value());
      }
    }
    platen_rows.setFromTriplets(entries.begin(), entries.end());
  }

  Eigen::VectorXd f = Eigen::VectorXd::Zero(K.rows());
  apply_constraints(K, f, c);
  r.nonzeros = static_cast<std::size_t>(K.nonZeros());
  // Initial guess for the iterative solver: the uniform axial strain of the sample (Poisson
  // contraction and rotations zero), with the prescribed values on the held DOFs.
  Eigen::VectorXd u = Eigen::VectorXd::Zero(K.rows());
  for (std::size_t p = 0; p < model.particles.size(); ++p) {
    const double height = (dot(model.particles.position[p], load.axis) - load.sample.bottom) / load.sample.length;
    u[static_cast<Eigen::Index>(dofs * p + static_cast<std::size_t>(ax))] = -load.displacement * height * load.axis[ax];
  }
  for (Eigen::Index i = 0; i < u.size(); ++i) {
    if (c.fixed[static_cast<std::size_t>(i)]) u[i] = c.value[static_cast<std::size_t>(i)];
  }
  SparseSolverOptions solver = options.solver;
  solver.block_size = dofs;
  r.solve = solve_spd(K, f, u, solver);

  const Eigen::VectorXd reactions = platen_rows * u;
  const double sign = load.axis[ax];  // axis is +-e_ax
  for (std::size_t s = 0; s < platen_particles.size(); ++s) {
    // External platen force on a particle = K u; the lower platen pushes along +axis, the upper along -axis.
    const double along_axis = sign * reactions[static_cast<Eigen::Index>(s)];
    if (s < load.bottom.size()) r.force_bottom += along_axis;
    else r.force_top -= along_axis;
  }
  r.stiffness = r.force_top / load.displacement;
  r.youngs_modulus = r.stiffness * load.sample.length / load.sample.area;

  set_fields(model, c, u, r);
  r.seconds = seconds_since(start);
  return r;
}

}  // namespace bpm
