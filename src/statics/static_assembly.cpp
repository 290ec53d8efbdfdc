#include "statics/static_assembly.hpp"

#include <algorithm>
#include <limits>
#include <vector>

#include "core/error.hpp"
#include "linear/bond_element.hpp"
#include "solvers/distributed_solver.hpp"

namespace bpm {
namespace {

/// The translation-rotation coupling blocks of a bond element are k [n]x: skew, with a zero
/// diagonal that the element (probed from the bond law with unit motions) holds as round-off,
/// ~1e-16 of the block. Set to exact zeros, these entries (1/6 of K) are dropped by
/// apply_constraints, which saves their share of every product and smoother sweep.
template <typename Matrix>
void drop_round_off(Matrix& k) {
  for (int bi = 0; bi < Matrix::RowsAtCompileTime; bi += 3) {
    for (int bj = 0; bj < Matrix::ColsAtCompileTime; bj += 3) {
      auto block = k.template block<3, 3>(bi, bj);
      const double floor = 1e-12 * block.cwiseAbs().maxCoeff();
      block = (block.array().abs() <= floor).select(0.0, block);
    }
  }
}

/// The rows of bond i's element that belong to its end `end` (0: alpha) in the chosen DOF layout:
/// six rows of the 12x12 element, or with 3 DOF the rows of [Kt -Kt; -Kt Kt] with Kt the
/// translational stiffness (rotations held, Jarolin Eq. 6-8), in the leading columns.
ElementRows bond_rows(const Model& model, std::size_t i, int end, int dofs) {
  if (dofs == 6) {
    ElementRows k = bond_element_rows(model.particles, model.bonds, i, end);
    drop_round_off(k);
    return k;
  }
  const auto& b = model.bonds;
  const Vec3 d = model.particles.position[b.beta[i]] - model.particles.position[b.alpha[i]];
  const Eigen::Matrix3d kt = bond_translational_stiffness(b.stiffness[i], d / norm(d));
  ElementRows k = ElementRows::Zero();
  k.block<3, 3>(0, 0) = end == 0 ? kt : Eigen::Matrix3d(-kt);
  k.block<3, 3>(0, 3) = end == 0 ? Eigen::Matrix3d(-kt) : kt;
  return k;
}

}  // namespace

SparseMatrixRM assemble_bond_stiffness(const Model& model, int dofs) {
  return assemble_stiffness(model, dofs, {});
}

SparseMatrixRM assemble_stiffness(const Model& model, int dofs,
                                  const std::vector<StaticContact>& contacts, ParticleRange range) {
  if (dofs != 6 && dofs != 3)
    throw InputError("dsm.dofs", "must be 6 or 3",
                     "6: translation and rotation; 3: translation only");
  const ParticleStore& p = model.particles;
  const BondStore& b = model.bonds;
  if (b.adjacency_start.size() != p.size() + 1)
    throw InputError("dsm", "the model is not finalised", "call Model::finalize()");
  const std::size_t n = p.size();
  const std::size_t first = std::min(range.first, n), last = std::clamp(range.last, first, n);
  const std::size_t local = last - first;  // row blocks assembled: particles first + q

  // Each particle's contact elements (2 e + side, side 0: the particle is i), in element order.
  std::vector<std::int32_t> contact_start(n + 1, 0), contact_entry(2 * contacts.size());
  for (const StaticContact& c : contacts) {
    ++contact_start[static_cast<std::size_t>(c.i) + 1];
    if (!c.wall()) ++contact_start[static_cast<std::size_t>(c.j) + 1];
  }
  for (std::size_t q = 0; q < n; ++q) contact_start[q + 1] += contact_start[q];
  {
    std::vector<std::int32_t> fill(contact_start.begin(), contact_start.end() - 1);
    for (std::size_t e = 0; e < contacts.size(); ++e) {
      const auto entry = static_cast<std::int32_t>(2 * e);
      contact_entry[static_cast<std::size_t>(fill[static_cast<std::size_t>(contacts[e].i)]++)] =
          entry;
      if (!contacts[e].wall())
        contact_entry[static_cast<std::size_t>(fill[static_cast<std::size_t>(contacts[e].j)]++)] =
            entry + 1;
    }
  }

  // Row-block pattern: each particle and its bonded and contact partners, ascending.
  std::vector<std::vector<std::int32_t>> neighbours(local);
#pragma omp parallel for schedule(static)
  for (std::size_t row = 0; row < local; ++row) {
    const std::size_t q = first + row;
    auto& list = neighbours[row];
    list.push_back(static_cast<std::int32_t>(q));
    for (auto e = b.adjacency_start[q]; e < b.adjacency_start[q + 1]; ++e) {
      const auto bond = static_cast<std::size_t>(b.adjacency[e] / 2);
      if (!b.intact[bond]) continue;
      list.push_back(b.adjacency[e] % 2 == 0 ? b.beta[bond] : b.alpha[bond]);
    }
    for (auto e = contact_start[q]; e < contact_start[q + 1]; ++e) {
      const StaticContact& c =
          contacts[static_cast<std::size_t>(contact_entry[static_cast<std::size_t>(e)] / 2)];
      if (!c.wall())
        list.push_back(contact_entry[static_cast<std::size_t>(e)] % 2 == 0 ? c.j : c.i);
    }
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  std::vector<std::int64_t> block_start(local + 1, 0);
  for (std::size_t q = 0; q < local; ++q)
    block_start[q + 1] =
        block_start[q] + dofs * dofs * static_cast<std::int64_t>(neighbours[q].size());
  if (block_start[local] > std::numeric_limits<int>::max()) {
    throw InputError("dsm", "the stiffness matrix has more than 2^31 entries",
                     "use the 3-DOF variant (--dofs 3) or the stiffness tensor estimation");
  }

  const auto rows = static_cast<Eigen::Index>(dofs * local);
  SparseMatrixRM K(rows, static_cast<Eigen::Index>(dofs * n));
  K.resizeNonZeros(static_cast<Eigen::Index>(block_start[local]));
  int* outer = K.outerIndexPtr();
  int* inner = K.innerIndexPtr();
  double* value = K.valuePtr();
  outer[rows] = static_cast<int>(block_start[local]);

#pragma omp parallel for schedule(dynamic, 256)
  for (std::size_t block = 0; block < local; ++block) {
    const std::size_t q = first + block;
    const auto& list = neighbours[block];
    const auto width = static_cast<std::int64_t>(dofs * list.size());
    for (int k = 0; k < dofs; ++k) {
      const std::int64_t start = block_start[block] + k * width;
      outer[dofs * block + static_cast<std::size_t>(k)] = static_cast<int>(start);
      for (std::size_t j = 0; j < list.size(); ++j) {
        for (int c = 0; c < dofs; ++c) {
          inner[start + static_cast<std::int64_t>(dofs * j) + c] = dofs * list[j] + c;
          value[start + static_cast<std::int64_t>(dofs * j) + c] = 0.0;
        }
      }
    }
    auto position = [&](std::int32_t particle) {
      return static_cast<std::int64_t>(std::lower_bound(list.begin(), list.end(), particle) -
                                       list.begin());
    };
    // Adds q's rows of an element joining a and b: row(k, column) is q's row k (of dofs) and
    // column `column` of the element's 2 dofs.
    // A wall (bb < 0) has no columns: only the element's first end is added.
    auto add = [&](auto&& row, std::int32_t a, std::int32_t bb) {
      const std::int64_t column_block[2] = {position(a), bb < 0 ? 0 : position(bb)};
      const int ends = bb < 0 ? 1 : 2;
      for (int k = 0; k < dofs; ++k) {
        const std::int64_t start = block_start[block] + k * width;
        for (int end = 0; end < ends; ++end) {
          for (int c = 0; c < dofs; ++c)
            value[start + dofs * column_block[end] + c] += row(k, end * dofs + c);
        }
      }
    };
    for (auto e = b.adjacency_start[q]; e < b.adjacency_start[q + 1]; ++e) {
      const auto bond = static_cast<std::size_t>(b.adjacency[e] / 2);
      if (!b.intact[bond]) continue;
      const ElementRows ke = bond_rows(model, bond, b.adjacency[e] % 2, dofs);  // end 0: q is alpha
      add([&](int k, int column) { return ke(k, column); }, b.alpha[bond], b.beta[bond]);
    }
    for (auto e = contact_start[q]; e < contact_start[q + 1]; ++e) {
      const auto entry = contact_entry[static_cast<std::size_t>(e)];
      const StaticContact& c = contacts[static_cast<std::size_t>(entry / 2)];
      const ElementMatrix ke = contact_element_stiffness(c, dofs);
      const int side = entry % 2;  // 0: q is i
      add([&](int k, int column) { return ke(side * dofs + k, column); }, c.i, c.j);
    }
  }
  return K;
}

std::vector<int> row_partition(const Model& model, const std::vector<std::int32_t>& contact_ends,
                               int dofs, int ranks) {
  const std::size_t n = model.particles.size();
  std::vector<std::size_t> weight(n, 1);
  for (std::size_t q = 0; q < n; ++q) {
    weight[q] += static_cast<std::size_t>(model.bonds.adjacency_start[q + 1] -
                                          model.bonds.adjacency_start[q]);
  }
  for (const std::int32_t end : contact_ends) ++weight[static_cast<std::size_t>(end)];
  std::vector<int> row_start;
  for (const std::size_t s : partition_particles(weight, ranks))
    row_start.push_back(dofs * static_cast<int>(s));
  return row_start;
}

}  // namespace bpm
