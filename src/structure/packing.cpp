#include "structure/packing.hpp"

#include <algorithm>
#include <array>
#include <numeric>
#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "core/parallel.hpp"
#include "spatial/cell_grid.hpp"

namespace bpm {
namespace {

double sphere_volume(double r) { return 4.0 / 3.0 * std::numbers::pi * r * r * r; }

/// A unit direction for two particles at the same centre, fixed by the pair so the two get
/// opposite pushes and every run the same.
Vec3 tie_direction(std::int64_t i, std::int64_t j) {
  const auto lo = static_cast<std::uint64_t>(std::min(i, j)), hi = static_cast<std::uint64_t>(std::max(i, j));
  std::uint64_t h = lo * 0x9E3779B97F4A7C15ull ^ (hi + 0x632BE59BD9B4E019ull);
  auto next = [&h] {
    h ^= h >> 33;
    h *= 0xFF51AFD7ED558CCDull;
    h ^= h >> 33;
    return static_cast<double>(h >> 11) * 0x1.0p-53 * 2.0 - 1.0;
  };
  Vec3 v{next(), next(), next() + 1e-3};
  v = v / norm(v);
  return i < j ? v : -v;
}

/// Reorders the particles by grid cell, so that neighbours are close in memory: the relaxation's
/// neighbour loop then reads from cache. Deterministic (stable sort by cell index).
void sort_by_cell(Packing& p, const Aabb& box) {
  if (p.size() == 0) return;
  const double r_max = *std::max_element(p.radius.begin(), p.radius.end());
  const Vec3 size = box.size();
  const double h = std::max(2.0 * r_max, 1e-12 * max_abs(size));
  std::array<std::uint64_t, 3> n{};
  for (int d = 0; d < 3; ++d) n[static_cast<std::size_t>(d)] = static_cast<std::uint64_t>(std::ceil(size[d] / h)) + 1;
  std::vector<std::uint64_t> key(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    std::array<std::uint64_t, 3> c{};
    for (int d = 0; d < 3; ++d) {
      const double x = std::floor((p.position[i][d] - box.min[d]) / h);
      c[static_cast<std::size_t>(d)] = static_cast<std::uint64_t>(std::clamp(x, 0.0, static_cast<double>(n[static_cast<std::size_t>(d)] - 1)));
    }
    key[i] = (c[0] * n[1] + c[1]) * n[2] + c[2];
  }
  std::vector<std::size_t> order(p.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return key[a] < key[b]; });
  Packing sorted;
  sorted.position.reserve(p.size());
  sorted.radius.reserve(p.size());
  for (const std::size_t i : order) {
    sorted.position.push_back(p.position[i]);
    sorted.radius.push_back(p.radius[i]);
  }
  p = std::move(sorted);
}

}  // namespace

Packing insert_random(const Container& container, const RadiusDistribution& radii, const PackingTarget& target,
                      std::mt19937_64& rng) {
  Packing p;
  RadiusSampler draw(radii);
  if (target.count > 0) {
    p.radius.resize(static_cast<std::size_t>(target.count));
    for (double& r : p.radius) r = draw(rng);
  } else {
    // Fill the solid volume; stop at the radius that brings the sum closest to it.
    const double solid = (1.0 - target.porosity) * container.volume();
    double sum = 0.0;
    while (sum < solid) {
      const double r = draw(rng);
      const double v = sphere_volume(r);
      if (sum + v - solid > solid - sum) break;
      p.radius.push_back(r);
      sum += v;
    }
  }
  const Aabb box = container.bounds();
  std::uniform_real_distribution<double> ux(box.min.x, box.max.x), uy(box.min.y, box.max.y), uz(box.min.z, box.max.z);
  p.position.resize(p.radius.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    Vec3 c;
    int attempt = 0;
    do {
      c = {ux(rng), uy(rng), uz(rng)};
    } while (!container.contains(c) && ++attempt < 100000);
    if (attempt == 100000) {
      throw InputError(container.describe(), "no random point fell inside the container in 100000 tries",
                       "check the container's shape (is the STL inside out or flat?)");
    }
    p.position[i] = container.keep_inside(c, p.radius[i]);
  }
  sort_by_cell(p, box);
  return p;
}

RelaxationReport relax(Packing& p, const Container& container, const RelaxationSettings& settings) {
  RelaxationReport report;
  const auto n = static_cast<std::int64_t>(p.size());
  if (n == 0) {
    report.converged = true;
    return report;
  }
  const double r_max = *std::max_element(p.radius.begin(), p.radius.end());
  // Overlapping pairs are closer than 2 R_max, so cells of that size hold every candidate in the
  // 27 cells around a particle.
  CellGrid grid(container.bounds(), 2.0 * r_max * (1.0 + 1e-9), 2 * p.size() + 1);
  std::vector<Vec3> force(p.size()), velocity(p.size());
  const std::vector<double> r3 = [&] {
    std::vector<double> v(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) v[i] = p.radius[i] * p.radius[i] * p.radius[i];
    return v;
  }();

  // FIRE (Bitzek et al. 2006) on the overlap energy; these are its recommended constants.
  constexpr double kDtStart = 0.1, kDtMax = 0.5, kIncrease = 1.1, kDecrease = 0.5, kAlphaStart = 0.1, kAlphaShrink = 0.99;
  constexpr int kMinPositive = 5;
  double dt = kDtStart, alpha = kAlphaStart;
  int positive = 0;

  for (;;) {
    // Forces: each overlap pushes its two particles apart (Jarolin §2, force-biased shifting), the
    // lighter one more (weight R_j^3 / (R_i^3 + R_j^3)).
    grid.build(p.position);
    double max_overlap = 0.0;
#pragma omp parallel for schedule(static) reduction(max : max_overlap) if (n >= kParallelMinItems)
    for (std::int64_t i = 0; i < n; ++i) {
      const auto si = static_cast<std::size_t>(i);
      const Vec3 xi = p.position[si];
      const double ri = p.radius[si];
      Vec3 f{};
      double worst = 0.0;
      grid.for_each_near(xi, [&](std::int32_t j) {
        const auto sj = static_cast<std::size_t>(j);
        if (sj == si) return;
        const Vec3 dx = xi - p.position[sj];
        const double sum = ri + p.radius[sj];
        const double dist2 = norm2(dx);
        if (dist2 >= sum * sum) return;
        const double dist = std::sqrt(dist2);
        const double delta = sum - dist;  // overlap, m
        worst = std::max(worst, delta / std::min(ri, p.radius[sj]));
        const Vec3 dir = dist > 0.0 ? dx / dist : tie_direction(i, j);
        f += (2.0 * r3[sj] / (r3[si] + r3[sj]) * delta) * dir;
      });
      force[si] = f;
      max_overlap = std::max(max_overlap, worst);
    }
    report.max_overlap = max_overlap;
    if (max_overlap <= settings.overlap_tolerance) {
      report.converged = true;
      break;
    }
    if (report.iterations >= settings.max_iterations) break;

    // FIRE step: mix the velocity towards the force while going downhill, stop when going uphill.
    const double power = fixed_order_sum(n, [&](std::size_t i) { return dot(force[i], velocity[i]); });
    if (power > 0.0) {
      const double v_norm = std::sqrt(fixed_order_sum(n, [&](std::size_t i) { return norm2(velocity[i]); }));
      const double f_norm = std::sqrt(fixed_order_sum(n, [&](std::size_t i) { return norm2(force[i]); }));
      const double mix = f_norm > 0.0 ? alpha * v_norm / f_norm : 0.0;
#pragma omp parallel for schedule(static) if (n >= kParallelMinItems)
      for (std::int64_t i = 0; i < n; ++i) {
        const auto si = static_cast<std::size_t>(i);
        velocity[si] = (1.0 - alpha) * velocity[si] + mix * force[si];
      }
      if (++positive > kMinPositive) {
        dt = std::min(dt * kIncrease, kDtMax);
        alpha *= kAlphaShrink;
      }
    } else {
      std::fill(velocity.begin(), velocity.end(), Vec3{});
      dt *= kDecrease;
      alpha = kAlphaStart;
      positive = 0;
    }
#pragma omp parallel for schedule(static) if (n >= kParallelMinItems)
    for (std::int64_t i = 0; i < n; ++i) {
      const auto si = static_cast<std::size_t>(i);
      velocity[si] += dt * force[si];
      Vec3 step = dt * velocity[si];
      // Never jump more than a fifth of the radius in one step (large initial overlaps).
      const double limit = 0.2 * p.radius[si], len = norm(step);
      if (len > limit) step *= limit / len;
      // The wall is hard: the sphere is put back inside and loses its velocity into the wall.
      const Vec3 next = container.keep_inside(p.position[si] + step, p.radius[si]);
      velocity[si] = (next - p.position[si]) / dt;
      p.position[si] = next;
    }
    ++report.iterations;
  }
  return report;
}

double largest_overlap(const Packing& p, const Container& container) {
  if (p.size() == 0) return 0.0;
  const double r_max = *std::max_element(p.radius.begin(), p.radius.end());
  const auto overlapping = find_pairs(p.position, container.bounds(), 2.0 * r_max * (1.0 + 1e-9),
                                      [&](std::int32_t i, std::int32_t j, double d) {
                                        return d < p.radius[static_cast<std::size_t>(i)] + p.radius[static_cast<std::size_t>(j)];
                                      });
  double worst = 0.0;
  for (const auto& [i, j] : overlapping) {
    const auto si = static_cast<std::size_t>(i), sj = static_cast<std::size_t>(j);
    const double delta = p.radius[si] + p.radius[sj] - norm(p.position[sj] - p.position[si]);
    worst = std::max(worst, delta / std::min(p.radius[si], p.radius[sj]));
  }
  return worst;
}

}  // namespace bpm
