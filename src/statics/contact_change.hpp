#pragma once
/// The change of the particle contacts' stiffness between two linearisations, as an operator:
/// y += (K_c(now) - K_c(start)) x, contact by contact (static_contact.hpp: B^T dC B with
/// dC = dk_n n n^T + dk_t (I - n n^T)), the held DOFs' rows and columns left out as
/// apply_constraints leaves them out of K. The linear DSM with walls solves its tangent systems
/// with K(start) + this, instead of assembling K again at each operating point: on the 1e5
/// cylinder that was 0.7 s and a second 365 MB matrix per point, and K(start) keeps its block
/// copy for the products. Each particle sums its own contacts in a fixed order, so the result
/// does not depend on the number of threads.
#include <cstdint>
#include <vector>

#include "statics/static_contact.hpp"

namespace bpm {

class ContactStiffnessChange {
 public:
  ContactStiffnessChange() = default;
  /// start[k] and now[k] are the same pair (particles, normal, arms) at two overlaps; fixed per
  /// global DOF (dofs per particle), nonzero where held.
  /// With walls_on_diagonal a wall's translation block (k_n n n^T + k_t (I - n n^T): diagonal for
  /// a wall normal to a coordinate axis) is left out, for the caller's diagonal shift to carry;
  /// its rotation terms stay.
  ContactStiffnessChange(std::size_t particles, int dofs, const std::vector<StaticContact>& start,
                         const std::vector<StaticContact>& now,
                         const std::vector<std::uint8_t>& fixed, bool walls_on_diagonal = false);

  /// y += (K_c(now) - K_c(start)) x; x and y hold dofs values per particle. Keeps its per-change
  /// terms in a member: one call at a time on an object.
  void add_product(const double* x, double* y) const;
  bool empty() const { return changes_.empty(); }

 private:
  /// What the product reads of a changed contact (a third of a StaticContact's bytes: on the 1e5
  /// cylinder's 4.4e5 contacts the product and the copies per Newton step were 26 % of the DSM).
  struct Change {
    std::int32_t i, j;
    Vec3 n;
    double arm_i, arm_j;
    double k_n, k_t;  ///< the changes dk_n, dk_t
    bool wall() const { return j < 0; }
  };
  std::vector<Change> changes_;
  std::vector<std::int64_t> first_;    ///< per particle: its entries in entries_
  std::vector<std::int32_t> entries_;  ///< 2 change + side (0: the particle is i)
  std::vector<std::uint8_t> fixed_;
  mutable std::vector<Vec3> g_;  ///< add_product's dC Delta per change
  int dofs_ = 6;
  bool walls_on_diagonal_ = false;
};

}  // namespace bpm
