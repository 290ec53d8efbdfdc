#pragma once
/// The whole structure generation of `bpmkit generate` (Jarolin 2020 §2): random insertion into
/// the container, force-biased relaxation, bonding, bond materials, statistics. Deterministic for
/// a given spec (seed included), for any number of OpenMP threads.
#include <cstdint>
#include <utility>
#include <vector>

#include "structure/generate_spec.hpp"
#include "structure/packing.hpp"
#include "structure/packing_stats.hpp"

namespace bpm {

struct GeneratedStructure {
  Packing packing;
  std::vector<std::pair<std::int32_t, std::int32_t>> bonds;  ///< particle indices (i < j), sorted
  std::vector<std::int32_t> bond_material;                   ///< index into spec.bond_materials
  std::vector<double> bond_radius;  ///< r_b = multiplier * min(R_i, R_j), m; empty if no multiplier given
  RelaxationReport relaxation;
  PackingStats stats;
  double insert_seconds = 0.0, relax_seconds = 0.0, bond_seconds = 0.0, total_seconds = 0.0;  ///< wall time
  int threads = 1;  ///< OpenMP threads available
};

/// Runs the generation. If the relaxation misses the overlap tolerance, throws InputError naming
/// the spec's `packing` section (on_failure: error) or returns with relaxation.converged = false
/// (on_failure: warn).
GeneratedStructure generate_structure(const GenerateSpec& spec);

}  // namespace bpm
