#include "structure/generate.hpp"

#include <fmt/core.h>
#include <omp.h>

#include <chrono>
#include <random>

#include "core/error.hpp"
#include "structure/bonding.hpp"

namespace bpm {
namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

GeneratedStructure generate_structure(const GenerateSpec& spec) {
  GeneratedStructure g;
  g.threads = omp_get_max_threads();
  const auto t_start = std::chrono::steady_clock::now();
  const Container& container = *spec.container;

  // Jarolin §2: random placement (overlaps allowed), then force-biased shifting.
  std::mt19937_64 rng(spec.seed);
  g.packing = insert_random(container, spec.radii, spec.target, rng);
  g.insert_seconds = seconds_since(t_start);

  auto t0 = std::chrono::steady_clock::now();
  g.relaxation = relax(g.packing, container, spec.relaxation);
  g.relax_seconds = seconds_since(t0);
  if (!g.relaxation.converged && spec.fail_if_not_relaxed) {
    throw InputError(spec.relaxation_where,
                     fmt::format("the relaxation did not reach the overlap tolerance {} in {} iterations (largest "
                                 "overlap {:.4g} of the smaller radius)",
                                 spec.relaxation.overlap_tolerance, g.relaxation.iterations, g.relaxation.max_overlap),
                     "raise max_iterations or overlap_tolerance, lower the packing density (higher porosity), or set "
                     "on_failure: warn to keep the structure anyway");
  }

  t0 = std::chrono::steady_clock::now();
  if (spec.bonds) {
    g.bonds = find_bond_pairs(g.packing, container.bounds(), spec.bond_criterion);
    std::vector<double> fractions;
    for (const auto& m : spec.bond_materials) fractions.push_back(m.fraction);
    // A separate stream, so that the bond materials do not shift when the packing changes length.
    std::mt19937_64 material_rng(spec.seed ^ 0x9E3779B97F4A7C15ull);
    g.bond_material = assign_bond_materials(g.bonds.size(), fractions, material_rng);
    if (spec.bond_radius_multiplier) {
      g.bond_radius.reserve(g.bonds.size());
      for (const auto& [i, j] : g.bonds) {
        g.bond_radius.push_back(*spec.bond_radius_multiplier *
                                std::min(g.packing.radius[static_cast<std::size_t>(i)], g.packing.radius[static_cast<std::size_t>(j)]));
      }
    }
  }
  g.bond_seconds = seconds_since(t0);
  g.stats = packing_stats(g.packing, container, spec.bond_criterion.contact_radius_multiplier.value_or(1.0));
  g.total_seconds = seconds_since(t_start);
  return g;
}

}  // namespace bpm
