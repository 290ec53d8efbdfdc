#include "contacts/neighbour_list.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/error.hpp"
#include "core/parallel.hpp"

namespace bpm {

namespace {

/// Cubic cells of side h = 2 R_max + skin, so every listed pair lies in the same or an adjacent
/// cell. The cells are hashed into about 2N buckets (spatial hashing), so memory and time stay O(N)
/// however far apart the particles are; a bucket may hold several cells, and a candidate counts
/// only if its own cell is the one visited, which also keeps each pair from being found twice.
/// Particles are counting-sorted into buckets in index order.
struct CellHash {
  struct Cell {
    std::int64_t x, y, z;
    bool operator==(const Cell&) const = default;
  };
  Vec3 origin;
  double inverse_h = 0.0;
  std::uint64_t mask = 0;
  std::vector<Cell> cell_of;
  std::vector<std::int32_t> start, particles;

  Cell cell(const Vec3& x) const {
    return {static_cast<std::int64_t>((x.x - origin.x) * inverse_h), static_cast<std::int64_t>((x.y - origin.y) * inverse_h),
            static_cast<std::int64_t>((x.z - origin.z) * inverse_h)};
  }
  std::size_t bucket(const Cell& c) const {
    const auto h = (static_cast<std::uint64_t>(c.x) * 73856093u) ^ (static_cast<std::uint64_t>(c.y) * 19349663u) ^
                   (static_cast<std::uint64_t>(c.z) * 83492791u);
    return static_cast<std::size_t>((h ^ (h >> 29)) & mask);
  }
};

CellHash make_cells(const std::vector<Vec3>& x, double h) {
  CellHash g;
  const std::size_t n = x.size();
  Vec3 lo = x[0];
  for (const Vec3& p : x) {
    lo.x = std::min(lo.x, p.x);
    lo.y = std::min(lo.y, p.y);
    lo.z = std::min(lo.z, p.z);
  }
  g.origin = lo;  // cell coordinates >= 0
  g.inverse_h = 1.0 / h;
  std::size_t buckets = 64;
  while (buckets < 2 * n) buckets *= 2;
  g.mask = buckets - 1;
  g.cell_of.resize(n);
  std::vector<std::size_t> bucket_of(n);
  g.start.assign(buckets + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    g.cell_of[i] = g.cell(x[i]);
    bucket_of[i] = g.bucket(g.cell_of[i]);
    ++g.start[bucket_of[i] + 1];
  }
  for (std::size_t b = 0; b < buckets; ++b) g.start[b + 1] += g.start[b];
  std::vector<std::int32_t> fill(g.start.begin(), g.start.end() - 1);
  g.particles.resize(n);
  for (std::size_t i = 0; i < n; ++i) g.particles[fill[bucket_of[i]]++] = static_cast<std::int32_t>(i);
  return g;
}

/// Calls visit(j) for every j > i with gap < skin, scanning the 27 cells around i's.
template <class Visit>
void for_each_candidate(const CellHash& g, const std::vector<Vec3>& x, const std::vector<double>& r, double skin,
                        std::int32_t i, Visit&& visit) {
  const Vec3 xi = x[i];
  const double ri = r[i];
  const CellHash::Cell c = g.cell_of[i];
  for (std::int64_t dx = -1; dx <= 1; ++dx) {
    for (std::int64_t dy = -1; dy <= 1; ++dy) {
      for (std::int64_t dz = -1; dz <= 1; ++dz) {
        const CellHash::Cell visited{c.x + dx, c.y + dy, c.z + dz};
        const std::size_t b = g.bucket(visited);
        for (std::int32_t e = g.start[b]; e < g.start[b + 1]; ++e) {
          const std::int32_t j = g.particles[e];
          if (j <= i || !(g.cell_of[j] == visited)) continue;
          const double reach = ri + r[j] + skin;
          if (norm2(x[j] - xi) < reach * reach) visit(j);
        }
      }
    }
  }
}

}  // namespace

void NeighbourList::build(const std::vector<Vec3>& position, const std::vector<double>& radius, double skin) {
  if (!(skin > 0.0)) throw InputError("contacts", "the Verlet skin must be positive");
  const std::size_t n = position.size();
  skin_ = skin;
  ++builds_;
  position_at_build_ = position;
  row_start_.assign(n + 1, 0);
  first_.clear();
  second_.clear();
  if (n == 0) return;
  const double r_max = *std::max_element(radius.begin(), radius.end());
  const CellHash grid = make_cells(position, 2.0 * r_max + skin);
  const auto count = static_cast<std::int64_t>(n);

  // One pass over fixed chunks of consecutive particles: each chunk collects its rows (each row
  // sorted) into its own buffer, then the buffers are concatenated in chunk order. The chunks do
  // not depend on the thread count, so neither does the list.
  constexpr std::int64_t kChunk = 512;
  const std::int64_t chunks = (count + kChunk - 1) / kChunk;
  std::vector<std::vector<std::int32_t>> found(static_cast<std::size_t>(chunks));
#pragma omp parallel for schedule(dynamic, 1) if (count > kParallelMinItems)
  for (std::int64_t c = 0; c < chunks; ++c) {
    std::vector<std::int32_t>& out = found[c];
    for (std::int64_t i = c * kChunk; i < std::min(count, (c + 1) * kChunk); ++i) {
      const std::size_t begin = out.size();
      for_each_candidate(grid, position, radius, skin, static_cast<std::int32_t>(i),
                         [&](std::int32_t j) { out.push_back(j); });
      std::sort(out.begin() + static_cast<std::ptrdiff_t>(begin), out.end());
      row_start_[i + 1] = static_cast<std::int32_t>(out.size() - begin);
    }
  }
  for (std::size_t i = 0; i < n; ++i) row_start_[i + 1] += row_start_[i];
  first_.resize(static_cast<std::size_t>(row_start_[n]));
  second_.resize(static_cast<std::size_t>(row_start_[n]));
#pragma omp parallel for schedule(static) if (count > kParallelMinItems)
  for (std::int64_t c = 0; c < chunks; ++c) {
    std::copy(found[c].begin(), found[c].end(), second_.begin() + row_start_[c * kChunk]);
    for (std::int64_t i = c * kChunk; i < std::min(count, (c + 1) * kChunk); ++i) {
      std::fill(first_.begin() + row_start_[i], first_.begin() + row_start_[i + 1], static_cast<std::int32_t>(i));
    }
  }
}

void NeighbourList::restore(State state) {
  row_start_ = std::move(state.row_start);
  first_ = std::move(state.first);
  second_ = std::move(state.second);
  position_at_build_ = std::move(state.position_at_build);
  skin_ = state.skin;
  builds_ = state.builds;
}

bool NeighbourList::needs_rebuild(const std::vector<Vec3>& position) const {
  if (builds_ == 0 || position.size() != position_at_build_.size()) return true;
  const auto n = static_cast<std::int64_t>(position.size());
  const double limit = 0.25 * skin_ * skin_;  // (skin/2)^2
  const double moved = parallel_reduce(
      n, 0.0,
      [&](std::int64_t i) {
        return norm2(position[static_cast<std::size_t>(i)] - position_at_build_[static_cast<std::size_t>(i)]);
      },
      [](double a, double b) { return std::max(a, b); });
  return moved > limit;
}

}  // namespace bpm
