#pragma once
/// The global stiffness of the bonds (Jarolin Eq. 7-8), assembled from the same linearised bond
/// element the DEM's bond law gives (linear/bond_element.hpp): the 12x12 element with 6 DOF per
/// particle (translation, rotation; DOF 6p+k), or its translational block with 3 DOF per particle,
/// rotations neglected as in Jarolin section 3.1.1.
///
/// The matrix is written straight into compressed rows: the row block of particle p holds p and its
/// bonded partners in ascending order, and only p's own rows are written while p is assembled, so
/// the particles are assembled in parallel without locks and the result does not depend on the
/// thread count. (Each end evaluates its own six rows of a bond's element, half of the element;
/// that costs less than the memory a stored element would need at 8e6 bonds.)
#include <cstddef>
#include <limits>
#include <vector>

#include "model/model.hpp"
#include "dsm/sparse_solver.hpp"

namespace bpm {

struct ContactElement;

/// K (dofs N x dofs N, both triangles) of the intact bonds at the particles' current positions.
/// dofs_per_particle is 6 or 3.
SparseMatrixRM assemble_bond_stiffness(const Model& model, int dofs_per_particle);

/// The particles [first, last) (clamped to the model): the row blocks one MPI rank assembles
/// (distributed_solver.hpp).
struct ParticleRange {
  std::size_t first = 0;
  std::size_t last = std::numeric_limits<std::size_t>::max();
};

/// The same plus the given linearised contact elements (contact_element.hpp), in parallel to the
/// bonds (a pair may have both: bonds superimposed on contacts). With `rows`, only those particles'
/// rows (dofs (last - first) rows, all dofs N columns): a rank's part of K, equal to those rows of
/// the whole.
SparseMatrixRM assemble_stiffness(const Model& model, int dofs_per_particle, const std::vector<ContactElement>& contacts,
                                  ParticleRange rows = {});

}  // namespace bpm
