#pragma once
/// Boundary conditions of the direct stiffness method as prescribed degrees of freedom, and their
/// symmetric elimination from K u = f.
///
/// - Kinematic platens (the linear DSM, Jarolin section 4.2: "a fixed lower wall and a fixed
///   displacement of the upper wall"): the particles of the bottom set are held along the axis, the
///   top set moved by -displacement; with a frictional platen also held across it.
/// - Across a frictionless platen the sample may slide and spin about the axis; these three
///   rigid-body modes are removed by pinning two bottom particles: the one nearest the set's centre
///   in both lateral directions, the one farthest from it in the lateral direction that spin moves
///   most. The pins carry no force (the loads are axial and balanced), so the solution is unchanged.
/// - DOFs the scenario fixes (boundary_conditions: fix) are held at zero as well; where it holds
///   some translation, no pins are added (its constraints must then remove the rigid modes).
/// - Particles not bonded to the largest bonded cluster (loose particles, fragments) carry no load
///   and have no defined position in a static solution: they are held and counted.
#include <cstdint>
#include <vector>

#include "model/model.hpp"
#include "compress/platen_loading.hpp"
#include "dsm/sparse_solver.hpp"

namespace bpm {

struct DofConstraints {
  int dofs = 6;                      ///< per particle
  int axial_dof = 2;                 ///< index of the loading axis among x, y, z
  std::vector<std::uint8_t> fixed;   ///< per global DOF (dofs p + k)
  std::vector<double> value;         ///< prescribed displacement of a fixed DOF, m or rad
  std::size_t detached_particles = 0;
  bool pinned = false;               ///< the lateral rigid-body modes were pinned (frictionless)
};

/// kinematic_platens: hold and move the platen sets (linear DSM); otherwise only the pins and the
/// detached particles (the nonlinear DSM, whose wall springs carry the platens).
DofConstraints platen_constraints(const Model& model, const PlatenLoading& load, int dofs, bool kinematic_platens);

/// Eliminates the fixed DOFs symmetrically in place: their columns move to the right-hand side,
/// their rows become c u_i = c g_i with c the original diagonal (which keeps the conditioning).
/// Entries that end up exactly zero (the eliminated ones, and the zeros the assembly sets) are
/// removed from K. K may be the rows of one rank (dsm_assembly.hpp: ParticleRange): its row r is
/// K's row first_row + r, and f holds those rows' entries.
void apply_constraints(SparseMatrixRM& K, Eigen::VectorXd& f, const DofConstraints& constraints,
                       std::size_t first_row = 0);

}  // namespace bpm
