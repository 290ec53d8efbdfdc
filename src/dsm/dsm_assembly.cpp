#include "dsm/dsm_assembly.hpp"

#include <algorithm>
#include <limits>
#include <vector>

#include "core/error.hpp"
#include "linear/bond_element.hpp"

namespace bpm {
namespace {

/// The translation-rotation coupling blocks of a bond element are k [n]x: skew, with a zero
/// diagonal that the element (probed from the bond law with unit motions) holds as round-off,
/// ~1e-16 of the block. Set to exact zeros, these entries (1/6 of K) are dropped by
/// apply_constraints, which saves their share of every product and smoother sweep.
void drop_round_off(ElementMatrix& k) {
  for (int bi = 0; bi < 12; bi += 3) {
    for (int bj = 0; bj < 12; bj += 3) {
      auto block = k.block<3, 3>(bi, bj);
      const double floor = 1e-12 * block.cwiseAbs().maxCoeff();
      block = (block.array().abs() <= floor).select(0.0, block);
    }
  }
}

/// The element of bond i in the chosen DOF layout: the 12x12 element, or in its leading 6x6 block
/// [Kt -Kt; -Kt Kt] with Kt the translational stiffness (rotations held, Jarolin Eq. 6-8).
ElementMatrix element(const Model& model, std::size_t i, int dofs) {
  if (dofs == 6) {
    ElementMatrix k = bond_element_stiffness(model.particles, model.bonds, i);
    drop_round_off(k);
    return k;
  }
  const auto& b = model.bonds;
  const Vec3 d = model.particles.position[b.beta[i]] - model.particles.position[b.alpha[i]];
  const Eigen::Matrix3d kt = bond_translational_stiffness(b.stiffness[i], d / norm(d));
  ElementMatrix k = ElementMatrix::Zero();
  k.block<3, 3>(0, 0) = kt;
  k.block<3, 3>(0, 3) = -kt;
  k.block<3, 3>(3, 0) = -kt;
  k.block<3, 3>(3, 3) = kt;
  return k;
}

}  // namespace

SparseMatrixRM assemble_bond_stiffness(const Model& model, int dofs) {
  if (dofs != 6 && dofs != 3) throw InputError("dsm.dofs", "must be 6 or 3", "6: translation and rotation; 3: translation only");
  const ParticleStore& p = model.particles;
  const BondStore& b = model.bonds;
  if (b.adjacency_start.size() != p.size() + 1) throw InputError("dsm", "the model is not finalised", "call Model::finalize()");
  const std::size_t n = p.size();

  // Row-block pattern: each particle and its bonded partners, ascending.
  std::vector<std::vector<std::int32_t>> neighbours(n);
#pragma omp parallel for schedule(static)
  for (std::size_t q = 0; q < n; ++q) {
    auto& list = neighbours[q];
    list.push_back(static_cast<std::int32_t>(q));
    for (auto e = b.adjacency_start[q]; e < b.adjacency_start[q + 1]; ++e) {
      const auto bond = static_cast<std::size_t>(b.adjacency[e] / 2);
      if (!b.intact[bond]) continue;
      list.push_back(b.adjacency[e] % 2 == 0 ? b.beta[bond] : b.alpha[bond]);
    }
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  std::vector<std::int64_t> block_start(n + 1, 0);
  for (std::size_t q = 0; q < n; ++q) block_start[q + 1] = block_start[q] + dofs * dofs * static_cast<std::int64_t>(neighbours[q].size());
  if (block_start[n] > std::numeric_limits<int>::max()) {
    throw InputError("dsm", "the stiffness matrix has more than 2^31 entries", "use the 3-DOF variant (--dofs 3) or the stiffness tensor estimation");
  }

  const auto rows = static_cast<Eigen::Index>(dofs * n);
  SparseMatrixRM K(rows, rows);
  K.resizeNonZeros(static_cast<Eigen::Index>(block_start[n]));
  int* outer = K.outerIndexPtr();
  int* inner = K.innerIndexPtr();
  double* value = K.valuePtr();
  outer[rows] = static_cast<int>(block_start[n]);

#pragma omp parallel for schedule(dynamic, 256)
  for (std::size_t q = 0; q < n; ++q) {
    const auto& list = neighbours[q];
    const auto width = static_cast<std::int64_t>(dofs * list.size());
    for (int k = 0; k < dofs; ++k) {
      const std::int64_t start = block_start[q] + k * width;
      outer[dofs * q + static_cast<std::size_t>(k)] = static_cast<int>(start);
      for (std::size_t j = 0; j < list.size(); ++j) {
        for (int c = 0; c < dofs; ++c) {
          inner[start + static_cast<std::int64_t>(dofs * j) + c] = dofs * list[j] + c;
          value[start + static_cast<std::int64_t>(dofs * j) + c] = 0.0;
        }
      }
    }
    auto position = [&](std::int32_t particle) {
      return static_cast<std::int64_t>(std::lower_bound(list.begin(), list.end(), particle) - list.begin());
    };
    for (auto e = b.adjacency_start[q]; e < b.adjacency_start[q + 1]; ++e) {
      const auto bond = static_cast<std::size_t>(b.adjacency[e] / 2);
      if (!b.intact[bond]) continue;
      const int side = b.adjacency[e] % 2;  // 0: q is alpha
      const ElementMatrix ke = element(model, bond, dofs);
      const std::int64_t column_block[2] = {position(b.alpha[bond]), position(b.beta[bond])};
      for (int k = 0; k < dofs; ++k) {
        const std::int64_t start = block_start[q] + k * width;
        for (int end = 0; end < 2; ++end) {
          for (int c = 0; c < dofs; ++c) {
            value[start + dofs * column_block[end] + c] += ke(side * dofs + k, end * dofs + c);
          }
        }
      }
    }
  }
  return K;
}

}  // namespace bpm
