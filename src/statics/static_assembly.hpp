#pragma once
/// The one assembly of the global stiffness (Jarolin Eq. 7-8) that every static method uses: the
/// bonds, assembled from the same linearised bond
/// element the DEM's bond law gives (linear/bond_element.hpp): the 12x12 element with 6 DOF per
/// particle (translation, rotation; DOF 6p+k), or its translational block with 3 DOF per particle,
/// rotations neglected as in Jarolin section 3.1.1; plus linearised contacts (static_contact.hpp).
/// Broken bonds (BondStore::intact == 0) carry nothing and are left out; so are contacts with
/// k_n = k_t = 0 only in value (their pattern stays).
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
#include "solvers/sparse_solver.hpp"
#include "statics/static_contact.hpp"

namespace bpm {

/// K (dofs N x dofs N, both triangles) of the intact bonds at the particles' current positions.
/// dofs_per_particle is 6 or 3.
SparseMatrixRM assemble_bond_stiffness(const Model& model, int dofs_per_particle);

/// The particles [first, last) (clamped to the model): the row blocks one MPI rank assembles
/// (distributed_solver.hpp).
struct ParticleRange {
  std::size_t first = 0;
  std::size_t last = std::numeric_limits<std::size_t>::max();
};

/// The same plus the given contacts, each linearised at its k_n, k_t (static_contact.hpp), in
/// parallel to the bonds (a pair may have both: bonds superimposed on contacts); a wall contact
/// adds to its particle's diagonal block only. With `rows`, only those particles' rows (dofs (last
/// - first) rows, all dofs N columns): a rank's part of K, equal to those rows of the whole.
SparseMatrixRM assemble_stiffness(const Model& model, int dofs_per_particle,
                                  const std::vector<StaticContact>& contacts,
                                  ParticleRange rows = {});

/// The first row of K (dofs per particle) of each of `ranks` contiguous ranges of particles with
/// about equal shares of K's entries (partition_particles in solvers/distributed_solver.hpp): a
/// particle weighs 1 + its bonds + its ends among contact_ends. Then the row count.
std::vector<int> row_partition(const Model& model, const std::vector<std::int32_t>& contact_ends,
                               int dofs, int ranks);

}  // namespace bpm
