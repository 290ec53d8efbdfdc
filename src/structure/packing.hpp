#pragma once
/// Random dense packings of spheres (Jarolin 2020 §2): particles are placed at random inside the
/// container, overlaps allowed, and then shifted iteratively by a force-biased relaxation until
/// the overlaps are small.
///
/// Relaxation: every overlapping pair (overlap delta_ij = R_i + R_j - |x_j - x_i|) pushes its two
/// particles apart along the line of centres, with a force proportional to delta_ij shared by
/// w_ij = R_j^3 / (R_i^3 + R_j^3) (the smaller particle moves more; 1/2 for equal radii), the
/// force-biased shifting of Jarolin §2. The particles move by FIRE (Bitzek et al. 2006, an inertial
/// descent on the overlap energy), which near jamming needs ~10x fewer iterations than plain
/// shifting. Each step uses the previous positions only (Jacobi style) and FIRE's global sums are
/// added in a fixed order, so the result is bit-for-bit the same for any number of OpenMP threads.
/// The container wall is hard: after each step a sphere that pokes out is moved back to the
/// nearest centre where it fits. It stops when the largest overlap relative to the smaller radius,
/// delta_ij / min(R_i, R_j), is at most the tolerance, or after max_iterations. Neighbours come
/// from a cell grid (O(N) per iteration).
#include <cstdint>
#include <random>
#include <vector>

#include "core/vec3.hpp"
#include "structure/container.hpp"
#include "structure/radius_distribution.hpp"

namespace bpm {

/// Particles as structure of arrays, indexed 0..size-1 (written with ids 0..size-1).
struct Packing {
  std::vector<Vec3> position;  ///< centre, m
  std::vector<double> radius;  ///< m
  std::size_t size() const { return radius.size(); }
};

/// How many particles: a target porosity (the solid volume (1 - porosity) V_container is filled by
/// drawing radii until the sum of sphere volumes reaches it) or a fixed count.
struct PackingTarget {
  double porosity = 0.0;  ///< used if count == 0; in (0, 1)
  std::int64_t count = 0;
};

/// Draws radii and uniformly random centres at which the sphere lies inside the container
/// (rejection from the bounding box, then keep_inside); overlaps are allowed.
Packing insert_random(const Container& container, const RadiusDistribution& radii, const PackingTarget& target,
                      std::mt19937_64& rng);

struct RelaxationSettings {
  double overlap_tolerance = 0.01;     ///< largest delta / min(R_i, R_j) to reach
  std::int64_t max_iterations = 20000;
};

struct RelaxationReport {
  std::int64_t iterations = 0;
  double max_overlap = 0.0;  ///< largest delta / min(R_i, R_j) at the end
  bool converged = false;
};

/// Force-biased relaxation (see above), in place.
RelaxationReport relax(Packing& packing, const Container& container, const RelaxationSettings& settings);

/// Largest overlap delta / min(R_i, R_j) over all pairs (0 if none).
double largest_overlap(const Packing& packing, const Container& container);

}  // namespace bpm
