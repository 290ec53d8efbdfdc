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
  changes_.reserve(start.size());
  for (std::size_t k = 0; k < start.size(); ++k) {
    const StaticContact& s = start[k];
    const double dk_n = now[k].k_n - s.k_n, dk_t = now[k].k_t - s.k_t;
    if (dk_n != 0.0 || dk_t != 0.0)
      changes_.push_back({s.i, s.j, s.n, s.arm_i, s.arm_j, dk_n, dk_t});
  }
  g_.resize(changes_.size());
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
  const std::ptrdiff_t d = dofs_;
  // x with the held DOFs read as zero (their columns are eliminated from K).
  auto value = [&](std::int32_t p, int k) {
    const std::ptrdiff_t at = d * p + k;
    return fixed_[static_cast<std::size_t>(at)] ? 0.0 : x[at];
  };
  auto vec = [&](std::int32_t p, int k0) {
    return Vec3{value(p, k0), value(p, k0 + 1), value(p, k0 + 2)};
  };
  auto dC = [](const Change& c, const Vec3& v) {
    return c.k_t * v + (c.k_n - c.k_t) * dot(c.n, v) * c.n;
  };
  // Each change's g = dC Delta once (Delta = u_j + a_j n x theta_j - u_i + a_i n x theta_i; a
  // wall: no u_j, theta_j), then each particle sums its own changes in a fixed order, so the
  // result does not depend on the number of threads.
  parallel_for(static_cast<std::int64_t>(changes_.size()), [&](std::int64_t k) {
    const Change& c = changes_[static_cast<std::size_t>(k)];
    const bool wall = c.wall();
    Vec3 delta = (wall ? Vec3{} : vec(c.j, 0)) - vec(c.i, 0);
    if (d == 6) {
      delta += cross(c.arm_i * c.n, vec(c.i, 3));
      if (!wall) delta += cross(c.arm_j * c.n, vec(c.j, 3));
    }
    g_[static_cast<std::size_t>(k)] = dC(c, delta);
  });
  // B^T g: -g and -(a_i n) x g on i's rows, +g and -(a_j n) x g on j's.
  parallel_for(static_cast<std::int64_t>(first_.size()) - 1, [&](std::int64_t q) {
    Vec3 force, torque;
    for (std::int64_t e = first_[static_cast<std::size_t>(q)];
         e < first_[static_cast<std::size_t>(q) + 1]; ++e) {
      const std::int32_t entry = entries_[static_cast<std::size_t>(e)];
      const Change& c = changes_[static_cast<std::size_t>(entry / 2)];
      const Vec3& g = g_[static_cast<std::size_t>(entry / 2)];
      if (entry % 2 == 1) {
        force += g;
        torque -= cross(c.arm_j * c.n, g);
        continue;
      }
      // With walls_on_diagonal the caller's diagonal carries a wall's translation block: i's
      // force rows take only the rotation part of Delta (g - dC(-u_i)), its torque rows all of it.
      force -= c.wall() && walls_on_diagonal_ ? g + dC(c, vec(c.i, 0)) : g;
      torque -= cross(c.arm_i * c.n, g);
    }
    for (int k = 0; k < d; ++k) {
      const std::ptrdiff_t at = d * q + k;
      if (!fixed_[static_cast<std::size_t>(at)]) y[at] += k < 3 ? force[k] : torque[k - 3];
    }
  });
}

}  // namespace bpm
