#pragma once
/// Bonds as structure of arrays, contiguous by bond index: the constants fixed at creation, the
/// incremental state carried from step to step, and the per-step end loads that the particle
/// gather reads. A particle-to-bond adjacency (CSR) lets each particle sum its own bonds in a fixed
/// order, so the result is the same for any thread count.
#include <cstdint>
#include <vector>

#include "bonds/bond_material.hpp"
#include "bonds/bond_model.hpp"
#include "bonds/bond_strength.hpp"
#include "core/vec3.hpp"

namespace bpm {

struct ParticleStore;

struct BondStore {
  // Constants, set at creation.
  std::vector<std::int32_t> alpha, beta;  ///< particle indices
  /// The bond's position in the order it was added (for a scenario: its row in the user's bond
  /// list, from 0), kept through reorder() so that outputs name bonds as the user does.
  std::vector<std::int32_t> input_row;
  std::vector<BondStiffness> stiffness;   ///< k_n, k_s, k_tor, k_ben
  std::vector<double> arm_offset;         ///< contact point at L/2 + offset from alpha
  std::vector<double> radius;             ///< r_b, m
  std::vector<double> rest_length;        ///< L_b at creation, m
  std::vector<std::int32_t> material;     ///< index into the scenario's bond materials
  std::vector<double> damping_force;      ///< 2 eta_b sqrt(k_n m_bar), N s/m (Chen Eq. 9)
  std::vector<double> damping_moment;     ///< 2 eta_b sqrt(2 k_tor I_bar), N m s (Chen Eq. 10)

  std::vector<StrengthLimits> strength;   ///< sigma_t A_b and tau_s A_b, N (bond_strength.hpp)

  /// 1 while the bond holds, 0 once it has broken (irreversible); 2 for one moment, between the
  /// kernel that broke it and the log that records it. A broken bond carries no load and hands its
  /// pair over to the particle contact law.
  std::vector<std::uint8_t> intact;
  std::vector<std::uint8_t> break_mode;  ///< BreakMode of a broken bond, 0 while intact

  // Incremental state: elastic load on alpha at the contact point (global frame) and the bond axis
  // it was last expressed for.
  std::vector<Vec3> force, moment, axis;

  // End loads of the last evaluation (elastic plus damping), read by the gather.
  std::vector<Vec3> end_force_alpha, end_moment_alpha, end_moment_beta;

  // Particle -> bonds adjacency: entries adjacency[adjacency_start[p] .. adjacency_start[p+1]) hold
  // 2 * bond + side (side 0: p is alpha, 1: p is beta), in bond order.
  std::vector<std::int32_t> adjacency_start, adjacency;

  /// Every break so far, in the order the kernel found them (by bond index within one update).
  struct Break {
    std::int32_t bond;
    std::int64_t update;  ///< number of the update_bond_loads call that broke it (1 = first)
    BreakMode mode;
    Vec3 position;  ///< contact point at the break, m
  };
  std::vector<Break> breaks;
  std::int64_t updates = 0;  ///< update_bond_loads calls so far
  bool breakable = false;    ///< some bond has a finite strength (set by finalize)

  std::size_t size() const { return alpha.size(); }
  std::size_t intact_count() const;

  /// Appends an unloaded bond; call finalize() before simulating.
  void add(std::int32_t a, std::int32_t b, const BondConstants& constants, double bond_radius,
           double length, std::int32_t mat = 0);

  /// Puts bond old_at[k] at index k with its constants (model/spatial_order.hpp); call before
  /// finalize(), which derives the state, the adjacency and the break log from this order.
  void reorder(const std::vector<std::int32_t>& old_at);

  /// Draws each bond's strengths from its material's distributions (StrengthDistribution), in bond
  /// order from one generator seeded with `seed`, so the same seed gives the same strengths.
  void draw_strengths(const std::vector<BondMaterial>& materials, std::uint64_t seed);

  /// Sets the initial axes from the particle positions, the damping coefficients for bond damping
  /// ratio eta_b, and builds the adjacency.
  void finalize(const ParticleStore& particles, double eta_b);
};

}  // namespace bpm
