#pragma once
/// What a packing achieved: porosity, coordination numbers, overlaps, radii.
///
/// Porosity = 1 - V_solid / V_container with V_solid = sum of the sphere volumes minus the lens
/// volume of every overlapping pair. The spheres are wholly inside the container (the relaxation
/// keeps them there), so no sphere is cut by the wall. Volume shared by three or more spheres is
/// subtracted more than once, so with large overlaps V_solid is slightly underestimated; at the
/// relaxation tolerance (overlaps of ~1 % of R) the lens correction itself is below 1e-4 of V_solid.
#include <cstddef>

#include "structure/container.hpp"
#include "structure/packing.hpp"

namespace bpm {

struct PackingStats {
  std::size_t particles = 0;
  double container_volume = 0.0;  ///< m^3
  double solid_volume = 0.0;      ///< m^3, overlaps (pairwise lenses) subtracted
  double porosity = 0.0;
  /// Mean number of neighbours whose contact radii eta_r R touch: 2 P / N with P the pairs with
  /// d <= eta_r (R_i + R_j) (with eta_r = 1: physical contacts).
  double coordination_number = 0.0;
  double contact_radius_multiplier = 1.0;  ///< the eta_r used for coordination_number
  double max_overlap = 0.0;                ///< largest delta / min(R_i, R_j)
  double min_radius = 0.0, mean_radius = 0.0, max_radius = 0.0;  ///< m
};

PackingStats packing_stats(const Packing& packing, const Container& container, double contact_radius_multiplier);

}  // namespace bpm
