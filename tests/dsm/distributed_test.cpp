// The pieces of the DSM across MPI ranks that one process can check: the particle partition, a
// rank's rows of K and of the constrained right-hand side against the whole, and the distributed
// solver (hypre's IJ matrix, BoomerAMG's own cycle, the gathered vectors) against the one-process
// solver on one rank. tests/mpi runs the whole DSM on 2 and 4 ranks under mpirun.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

#include "dsm/dsm_helpers.hpp"
#include "dsm/platen_constraints.hpp"
#include "solvers/distributed_solver.hpp"
#include "statics/static_assembly.hpp"

namespace bpm {
namespace {

constexpr double kRadius = 1e-3;

TEST(PartitionParticles, ContiguousRangesOfAboutEqualWeight) {
  std::vector<std::size_t> weight(1000);
  for (std::size_t q = 0; q < weight.size(); ++q) weight[q] = 1 + (q * 7919) % 13;
  const double total =
      static_cast<double>(std::accumulate(weight.begin(), weight.end(), std::size_t{0}));
  for (const int parts : {1, 2, 3, 7}) {
    const std::vector<std::size_t> start = partition_particles(weight, parts);
    ASSERT_EQ(start.size(), static_cast<std::size_t>(parts) + 1);
    EXPECT_EQ(start.front(), 0U);
    EXPECT_EQ(start.back(), weight.size());
    for (int k = 0; k < parts; ++k) {
      const auto a = static_cast<std::ptrdiff_t>(start[static_cast<std::size_t>(k)]);
      const auto b = static_cast<std::ptrdiff_t>(start[static_cast<std::size_t>(k) + 1]);
      ASSERT_LT(a, b);
      const double sum = static_cast<double>(
          std::accumulate(weight.begin() + a, weight.begin() + b, std::size_t{0}));
      EXPECT_LE(std::abs(sum - total / parts), 13.0)
          << "part " << k;  // within one particle's weight
    }
  }
  // More parts than particles: some are empty, none is out of order, all particles are covered.
  const std::vector<std::size_t> start = partition_particles({1, 1}, 4);
  ASSERT_EQ(start.size(), 5U);
  EXPECT_EQ(start.front(), 0U);
  EXPECT_EQ(start.back(), 2U);
  EXPECT_TRUE(std::is_sorted(start.begin(), start.end()));
}

/// A jittered lattice with bonds and a few contact elements, compressed between kinematic platens
/// (so the constraints prescribe nonzero values).
struct Sample {
  Model model = test::flat_ended_lattice(3, 3, 5, kRadius, 0.15, 21);
  std::vector<StaticContact> contacts;
  DofConstraints constraints;
  Sample() {
    for (std::int32_t i = 0; i + 4 < static_cast<std::int32_t>(model.particles.size()); i += 4) {
      const Vec3 d = model.particles.position[static_cast<std::size_t>(i + 4)] -
                     model.particles.position[static_cast<std::size_t>(i)];
      StaticContact c;
      c.i = i;
      c.j = i + 4;
      c.n = d / norm(d);
      c.arm_i = c.arm_j = 0.9 * kRadius;
      c.k_n = 2e5;
      c.k_t = 1e5;
      contacts.push_back(c);
    }
    const PlatenLoading load = test::layer_loading(model, 5, 0.01);
    constraints = platen_constraints(model, load, 6, /*kinematic_platens=*/true);
  }
};

TEST(DistributedAssembly, EachRanksRowsAreThoseOfTheWholeMatrix) {
  const Sample s;
  const std::size_t n = s.model.particles.size();
  SparseMatrixRM whole = assemble_stiffness(s.model, 6, s.contacts);
  Eigen::VectorXd whole_rhs = Eigen::VectorXd::Zero(whole.rows());
  apply_constraints(whole, whole_rhs, s.constraints);
  ASSERT_GT(whole_rhs.cwiseAbs().maxCoeff(), 0.0);  // the platen travel reaches the right-hand side
  const Eigen::MatrixXd dense = Eigen::MatrixXd(whole);
  const std::vector<std::size_t> start = {0, 7, 7, 20, n};  // one range empty
  for (std::size_t k = 0; k + 1 < start.size(); ++k) {
    SparseMatrixRM rows = assemble_stiffness(s.model, 6, s.contacts, {start[k], start[k + 1]});
    ASSERT_EQ(rows.rows(), static_cast<Eigen::Index>(6 * (start[k + 1] - start[k])));
    ASSERT_EQ(rows.cols(), whole.cols());
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(rows.rows());
    apply_constraints(rows, rhs, s.constraints, 6 * start[k]);
    const auto first = static_cast<Eigen::Index>(6 * start[k]);
    // Bit for bit: the same element rows summed in the same order.
    EXPECT_EQ(Eigen::MatrixXd(rows), dense.middleRows(first, rows.rows())) << "range " << k;
    EXPECT_EQ(rhs, whole_rhs.segment(first, rows.rows())) << "range " << k;
  }
}

TEST(DistributedShiftedSolver, OneRankSolvesAsTheOneProcessSolver) {
  // The whole machinery on MPI_COMM_WORLD of this one process (MPI starts as a singleton): hypre's
  // IJ matrix, its own V-cycle, the deflation, the gathered vectors.
  const Sample s;
  const PlatenLoading load = test::layer_loading(s.model, 5, 0.01);
  const DofConstraints pins = platen_constraints(s.model, load, 6, /*kinematic_platens=*/false);
  SparseMatrixRM K = assemble_stiffness(s.model, 6, s.contacts);
  const Eigen::Index n = K.rows();
  Eigen::VectorXd unused = Eigen::VectorXd::Zero(n);
  apply_constraints(K, unused, pins);
  SparseMatrixRM copy = K;
  const auto stored = static_cast<std::size_t>(K.nonZeros());
  // A shift on the platen layers' axial DOFs holds the sample (the platen springs' role); the
  // load pulls the top layer.
  Eigen::VectorXd shift = Eigen::VectorXd::Zero(n), f = Eigen::VectorXd::Zero(n);
  for (const auto p : load.bottom) shift[6 * p + 2] = 1e6;
  for (const auto p : load.top) {
    shift[6 * p + 2] = 1e6;
    f[6 * p + 2] = 1.0;
  }
  SparseSolverOptions options;
  options.kind = SparseSolverKind::cholmod;
  ShiftedSpdSolver reference(std::move(copy), options);
  Eigen::VectorXd expected = Eigen::VectorXd::Zero(n);
  reference.solve(shift, f, expected, 1e-12);

  options.kind = SparseSolverKind::amg_pcg;
  DistributedShiftedSolver solver(std::move(K), {0, static_cast<int>(n)}, options);
  EXPECT_EQ(solver.kind(), SparseSolverKind::amg_pcg);
  Eigen::MatrixXd Z = Eigen::MatrixXd::Zero(n, 1);
  for (Eigen::Index p = 0; p < n / 6; ++p) Z(6 * p + 2, 0) = 1.0;  // the axial translation
  solver.set_coarse_space(Z);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(n);
  const SparseSolveReport report = solver.solve(shift, f, u, 1e-10);
  EXPECT_GT(report.iterations, 0);
  EXPECT_LE(report.relative_residual, 1e-10);
  EXPECT_LE((u - expected).norm(), 1e-8 * expected.norm());
  // A second shift reuses the hierarchy of the first.
  shift *= 2.0;
  reference.solve(shift, f, expected, 1e-12);
  const SparseSolveReport second = solver.solve(shift, f, u, 1e-10);
  EXPECT_EQ(second.setup_seconds, 0.0);
  EXPECT_LE((u - expected).norm(), 1e-8 * expected.norm());
  // multiply() is K's product without the shift.
  Eigen::VectorXd Ku, Ku_reference;
  solver.multiply(u, Ku);
  reference.multiply(u, Ku_reference);
  EXPECT_LE((Ku - Ku_reference).norm(), 1e-12 * Ku_reference.norm());
  EXPECT_EQ(solver.nonzeros(), stored);
}

}  // namespace
}  // namespace bpm
