#pragma once
/// The change of the particle contacts' stiffness between two linearisations, as an operator:
/// y += (K_c(now) - K_c(start)) x, contact by contact (contact_element.hpp: B^T dC B with
/// dC = dk_n n n^T + dk_t (I - n n^T)), the held DOFs' rows and columns left out as
/// apply_constraints leaves them out of K. The linear DSM with walls solves its tangent systems
/// with K(start) + this, instead of assembling K again at each operating point: on the 1e5
/// cylinder that was 0.7 s and a second 365 MB matrix per point, and K(start) keeps its block
/// copy for the products. Each particle sums its own contacts in a fixed order, so the result
/// does not depend on the number of threads.
#include <cstdint>
#include <vector>

#include "dsm/contact_element.hpp"

namespace bpm {

class ContactStiffnessChange {
 public:
  ContactStiffnessChange() = default;
  /// start[k] and now[k] are the same pair (particles, normal, arms) at two overlaps; fixed per
  /// global DOF (dofs per particle), nonzero where held.
  ContactStiffnessChange(std::size_t particles, int dofs, const std::vector<ContactElement>& start,
                         const std::vector<ContactElement>& now,
                         const std::vector<std::uint8_t>& fixed);

  /// y += (K_c(now) - K_c(start)) x; x and y hold dofs values per particle.
  void add_product(const double* x, double* y) const;
  bool empty() const { return changes_.empty(); }

 private:
  std::vector<ContactElement> changes_;  ///< k_n, k_t: the changes dk_n, dk_t
  std::vector<std::int64_t> first_;      ///< per particle: its entries in entries_
  std::vector<std::int32_t> entries_;    ///< 2 change + side (0: the particle is i)
  std::vector<std::uint8_t> fixed_;
  int dofs_ = 6;
};

}  // namespace bpm
