#include "statics/static_solver.hpp"

#include <Eigen/SparseCholesky>

#include "core/error.hpp"
#include "statics/static_assembly.hpp"

namespace bpm {

StaticSolution solve_linear_static(const Model& model) {
  const ParticleStore& p = model.particles;
  const std::size_t n_dof = 6 * p.size();
  // Map free global DOFs to reduced indices.
  std::vector<Eigen::Index> reduced(n_dof, -1);
  Eigen::Index n_free = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    for (int k = 0; k < 6; ++k) {
      const bool free = k < 3 ? p.translation_free[i][k] != 0.0 : p.rotation_free[i][k - 3] != 0.0;
      if (free) reduced[6 * i + k] = n_free++;
    }
  }
  Eigen::VectorXd f = Eigen::VectorXd::Zero(n_free);
  auto add_load = [&](std::size_t particle, const Vec3& force, const Vec3& moment) {
    for (int k = 0; k < 6; ++k) {
      const Eigen::Index r = reduced[6 * particle + k];
      if (r >= 0) f[r] += k < 3 ? force[k] : moment[k - 3];
    }
  };
  for (const Load& load : model.loads) {
    for (const auto i : load.particles) add_load(i, load.force, load.moment);
  }
  for (std::size_t i = 0; i < p.size(); ++i) add_load(i, p.mass[i] * model.gravity, {});

  const Eigen::SparseMatrix<double> K(assemble_stiffness(model, 6, {}));
  std::vector<Eigen::Triplet<double>> triplets;
  for (int col = 0; col < K.outerSize(); ++col) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(K, col); it; ++it) {
      const Eigen::Index r = reduced[it.row()], c = reduced[it.col()];
      if (r >= 0 && c >= 0) triplets.emplace_back(r, c, it.value());
    }
  }
  Eigen::SparseMatrix<double> K_free(n_free, n_free);
  K_free.setFromTriplets(triplets.begin(), triplets.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(K_free);
  const Eigen::VectorXd u = solver.solve(f);
  const bool singular = solver.info() != Eigen::Success || (solver.vectorD().array() <= 0.0).any();
  if (singular) {
    throw InputError("boundary_conditions",
                     "the linearised structure is singular (a rigid-body mode is unconstrained)",
                     "fix enough degrees of freedom so that no part can move freely");
  }
  StaticSolution s;
  s.displacement.assign(p.size(), {});
  s.rotation.assign(p.size(), {});
  for (std::size_t i = 0; i < p.size(); ++i) {
    for (int k = 0; k < 6; ++k) {
      const Eigen::Index r = reduced[6 * i + k];
      if (r < 0) continue;
      if (k < 3)
        s.displacement[i][k] = u[r];
      else
        s.rotation[i][k - 3] = u[r];
    }
  }
  return s;
}

}  // namespace bpm
