#include "statics/contact_change.hpp"

#include <stdexcept>

#include "core/parallel.hpp"

namespace bpm {

ContactStiffnessChange::ContactStiffnessChange(std::size_t particles, int dofs,
                                               const std::vector<StaticContact>& start,
                                               const std::vector<StaticContact>& now,
                                               const std::vector<std::uint8_t>& fixed,
                                               bool walls_on_diagonal)
    : fixed_(fixed), dofs_(dofs), walls_on_diagonal_(walls_on_diagonal) {
  if (start.size() != now.size() || fixed.size() != particles * static_cast<std::size_t>(dofs)) {
    throw std::invalid_argument("ContactStiffnessChange: sizes differ");
  }
  for (std::size_t k = 0; k < start.size(); ++k) {
    const StaticContact& s = start[k];
    const double dk_n = now[k].k_n - s.k_n, dk_t = now[k].k_t - s.k_t;
    if (dk_n != 0.0 || dk_t != 0.0)
      changes_.push_back({s.i, s.j, s.n, s.arm_i, s.arm_j, dk_n, dk_t});
  }
  first_.assign(particles + 1, 0);
  for (const Change& c : changes_) {
    ++first_[static_cast<std::size_t>(c.i) + 1];
    if (!c.wall()) ++first_[static_cast<std::size_t>(c.j) + 1];
  }
  for (std::size_t p = 0; p < particles; ++p) first_[p + 1] += first_[p];
  entries_.resize(static_cast<std::size_t>(first_[particles]));
  std::vector<std::int64_t> next(first_.begin(), first_.end() - 1);
  for (std::size_t k = 0; k < changes_.size(); ++k) {
    entries_[static_cast<std::size_t>(next[static_cast<std::size_t>(changes_[k].i)]++)] =
        static_cast<std::int32_t>(2 * k);
    if (changes_[k].wall()) continue;
    entries_[static_cast<std::size_t>(next[static_cast<std::size_t>(changes_[k].j)]++)] =
        static_cast<std::int32_t>(2 * k + 1);
  }
}

void ContactStiffnessChange::add_product(const double* x, double* y) const {
  const auto particles = static_cast<std::ptrdiff_t>(first_.size()) - 1;
  const std::ptrdiff_t d = dofs_;
  // x with the held DOFs read as zero (their columns are eliminated from K).
  auto value = [&](std::int32_t p, int k) {
    const std::ptrdiff_t at = d * p + k;
    return fixed_[static_cast<std::size_t>(at)] ? 0.0 : x[at];
  };
  auto vec = [&](std::int32_t p, int k0) {
    return Vec3{value(p, k0), value(p, k0 + 1), value(p, k0 + 2)};
  };
#pragma omp parallel for schedule(static) if (particles >= kParallelMinItems / 8)
  for (std::ptrdiff_t q = 0; q < particles; ++q) {
    Vec3 force, torque;  // this particle's rows of (K_c(now) - K_c(start)) x
    for (std::int64_t e = first_[static_cast<std::size_t>(q)];
         e < first_[static_cast<std::size_t>(q) + 1]; ++e) {
      const std::int32_t entry = entries_[static_cast<std::size_t>(e)];
      const Change& c = changes_[static_cast<std::size_t>(entry / 2)];
      // Delta = u_j + a_j n x theta_j - u_i + a_i n x theta_i (a wall: no u_j, theta_j); g = dC
      // Delta.
      const bool wall = c.wall();
      Vec3 delta = (wall ? Vec3{} : vec(c.j, 0)) - vec(c.i, 0);
      if (d == 6) {
        delta += cross(c.arm_i * c.n, vec(c.i, 3));
        if (!wall) delta += cross(c.arm_j * c.n, vec(c.j, 3));
      }
      auto dC = [&](const Vec3& v) { return c.k_t * v + (c.k_n - c.k_t) * dot(c.n, v) * c.n; };
      const Vec3 g = dC(delta);
      if (wall && walls_on_diagonal_) {
        // The caller's diagonal carries the translation block: i's force rows take only the
        // rotation part of Delta, its torque rows all of it.
        force -= g - dC(-1.0 * vec(c.i, 0));
        torque -= cross(c.arm_i * c.n, g);
        continue;
      }
      // B^T g: -g and -(a_i n) x g on i's rows, +g and -(a_j n) x g on j's.
      if (entry % 2 == 0) {
        force -= g;
        torque -= cross(c.arm_i * c.n, g);
      } else {
        force += g;
        torque -= cross(c.arm_j * c.n, g);
      }
    }
    for (int k = 0; k < d; ++k) {
      const std::ptrdiff_t at = d * q + k;
      if (!fixed_[static_cast<std::size_t>(at)]) y[at] += k < 3 ? force[k] : torque[k - 3];
    }
  }
}

}  // namespace bpm
