#pragma once
/// Bonds for a packing (Jarolin 2020 §2: after the relaxation, bonds are generated between
/// neighbouring particles) and their materials (Jarolin case 2: bi-component agglomerates, two
/// bond materials mixed in a given ratio).
///
/// A pair (i, j) at centre distance d is bonded if either criterion that is set holds:
/// - contact radius multiplier eta_r (Chen 2022 §2.2): the contact radii eta_r R touch or overlap,
///   d <= eta_r (R_i + R_j);
/// - reference gap g: the surface gap is at most g, d - R_i - R_j <= g (m).
/// A relative tolerance of 1e-9 (R_i + R_j) is added, as in `bpmkit run`'s `bonds: auto`.
#include <cstdint>
#include <optional>
#include <random>
#include <utility>
#include <vector>

#include "structure/container.hpp"
#include "structure/packing.hpp"

namespace bpm {

struct BondCriterion {
  std::optional<double> contact_radius_multiplier;  ///< eta_r >= 1
  std::optional<double> max_gap;                    ///< g >= 0, m
};

/// All bonded pairs (i < j), sorted. Cell grid, parallel, independent of the thread count.
std::vector<std::pair<std::int32_t, std::int32_t>> find_bond_pairs(const Packing& packing, const Aabb& box,
                                                                   const BondCriterion& criterion);

/// A material for each of `count` bonds, drawn independently with the given probabilities
/// (`fractions`, summing to 1): material k with probability fractions[k]. With one material every
/// bond gets 0 and no random number is drawn.
std::vector<std::int32_t> assign_bond_materials(std::size_t count, const std::vector<double>& fractions,
                                                std::mt19937_64& rng);

}  // namespace bpm
