#pragma once
/// Bonds as structure of arrays, contiguous by bond index: the constants fixed at creation, the
/// incremental state carried from step to step, and the per-step end loads that the particle
/// gather reads. A particle-to-bond adjacency (CSR) lets each particle sum its own bonds in a fixed
/// order, so the result is the same for any thread count.
#include <cstdint>
#include <vector>

#include "bonds/bond_model.hpp"
#include "core/vec3.hpp"

namespace bpm {

struct ParticleStore;

struct BondStore {
  // Constants, set at creation.
  std::vector<std::int32_t> alpha, beta;  ///< particle indices
  std::vector<BondStiffness> stiffness;   ///< k_n, k_s, k_tor, k_ben
  std::vector<double> arm_offset;         ///< contact point at L/2 + offset from alpha
  std::vector<double> radius;             ///< r_b, m
  std::vector<double> rest_length;        ///< L_b at creation, m
  std::vector<std::int32_t> material;     ///< index into the scenario's bond materials
  std::vector<double> damping_force;      ///< 2 eta_b sqrt(k_n m_bar), N s/m (Chen Eq. 9)
  std::vector<double> damping_moment;     ///< 2 eta_b sqrt(2 k_tor I_bar), N m s (Chen Eq. 10)

  /// 1 while the bond holds, 0 once it has broken (irreversible). A broken bond carries no load and
  /// hands its pair over to the particle contact law.
  std::vector<std::uint8_t> intact;

  // Incremental state: elastic load on alpha at the contact point (global frame) and the bond axis
  // it was last expressed for.
  std::vector<Vec3> force, moment, axis;

  // End loads of the last evaluation (elastic plus damping), read by the gather.
  std::vector<Vec3> end_force_alpha, end_moment_alpha, end_moment_beta;

  // Particle -> bonds adjacency: entries adjacency[adjacency_start[p] .. adjacency_start[p+1]) hold
  // 2 * bond + side (side 0: p is alpha, 1: p is beta), in bond order.
  std::vector<std::int32_t> adjacency_start, adjacency;

  std::size_t size() const { return alpha.size(); }

  /// Appends an unloaded bond; call finalize() before simulating.
  void add(std::int32_t a, std::int32_t b, const BondConstants& constants, double bond_radius,
           double length, std::int32_t mat = 0);

  /// Sets the initial axes from the particle positions, the damping coefficients for bond damping
  /// ratio eta_b, and builds the adjacency.
  void finalize(const ParticleStore& particles, double eta_b);
};

}  // namespace bpm
