#pragma once
/// Prescribed degrees of freedom of a static problem (held at a value) and their symmetric
/// elimination from K u = f. Who holds what is the method's business (dsm/platen_constraints.hpp).
#include <cstdint>
#include <vector>

#include "solvers/sparse_solver.hpp"

namespace bpm {

struct DofConstraints {
  int dofs = 6;                     ///< per particle
  int axial_dof = 2;                ///< index of the loading axis among x, y, z
  std::vector<std::uint8_t> fixed;  ///< per global DOF (dofs p + k)
  std::vector<double> value;        ///< prescribed displacement of a fixed DOF, m or rad
  std::size_t detached_particles = 0;
  bool pinned = false;  ///< the lateral rigid-body modes were pinned (frictionless)
};

/// Eliminates the fixed DOFs symmetrically in place: their columns move to the right-hand side,
/// their rows become c u_i = c g_i with c the original diagonal (which keeps the conditioning).
/// Entries that end up exactly zero (the eliminated ones, and the zeros the assembly sets) are
/// removed from K. K may be the rows of one rank (static_assembly.hpp: ParticleRange): its row r is
/// K's row first_row + r, and f holds those rows' entries.
void apply_constraints(SparseMatrixRM& K, Eigen::VectorXd& f, const DofConstraints& constraints,
                       std::size_t first_row = 0);

}  // namespace bpm
