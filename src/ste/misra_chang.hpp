#pragma once
/// The per-particle stiffness tensor after Misra & Chang (Jarolin section 3.2, Eq. 11-35).
///
/// Readings of the converted text (derived from the physics, checked by the tests):
/// - Eq. 12-13: d^nm = x^m - x^n, f^nm the force on n from m, f^nm = K^nm u^nm with
///   u^nm = u^m - u^n (a bond in tension pulls n towards m), so sigma^n = 1/(2 V^n) sum_m d^nm (x) f^nm
///   is positive in tension. The 1/2 is the contact point halfway along the branch vector.
/// - Eq. 17 and 19: u^nm = eps . d^nm - phi^n + phi^m with eps the symmetric average strain
///   (the average rotation moves no bond in this translational model); in Voigt form
///   eps . d = D(d) e (voigt.hpp), and sigma^n = 1/(2 V^n) sum_m D(d)^T f.
/// - Eq. 20 has "-phi~^m sum_m K" in the second term; equilibrium of particle n,
///   sum_m K^nm u^nm = 0, needs phi~^n there. Then phi~^n = (Gamma^n + Gamma^n_hat) e with
///   Gamma^n = (sum_m K^nm)^-1 sum_m K^nm D(d^nm) (Eq. 23, inverse applied on the left) and
///   Gamma^n_hat = (sum_m K^nm)^-1 sum_m K^nm phi~^m (Eq. 24).
/// - Eq. 32 as the paper used it (section 3.2.2, last paragraph): Gamma^m from Eq. 26 (the
///   neighbour's own first-neighbour fluctuation), Gamma^n_hat by inserting Eq. 29 with
///   Gamma^m_hat neglected, i.e. Gamma^n_hat = (sum_m K^nm)^-1 sum_m K^nm Gamma^m, and Gamma^m_hat
///   neglected in A (Eq. 31):
///     C^n = 1/(2 V^n) sum_m D^T K^nm (D - Gamma^n - Gamma^n_hat + Gamma^m).
///   Summed over a sample this is the affine (Voigt) stiffness minus the first Neumann term of the
///   exact relaxation (B^T diag(sum K)^-1 B) minus half the second; it is major-symmetric when no
///   particle is left out (each pair term appears with its transpose).
///   Eq. 33-35 (Gamma^n alone) removes only half the first term; it is kept as an option.
/// - Particles whose sum_m K^nm is singular (smallest eigenvalue <= tolerance * largest: fewer than
///   three bonds spanning space when k_s = 0, or no bonds) are left out of the average and counted
///   (Jarolin: "neglect these particles"). As neighbours of others their fluctuation still enters,
///   with the pseudo-inverse: a dangling particle on one bond follows the affine motion of its
///   neighbour, so the bond's own stretch is relaxed as it is in the structure (Gamma = 0 would
///   treat it as anchored and let dangling bonds stiffen the sample).
/// Particle rotations are held (Jarolin section 3.1: "neglect the rotations of single particles").
#include <cstdint>
#include <vector>

#include "ste/neighbour_stiffness.hpp"
#include "ste/voigt.hpp"

namespace bpm::ste {

/// Which neighbour fluctuations enter C^n.
enum class Fluctuation : std::uint8_t {
  affine,           ///< none: every particle follows the average strain (Voigt bound)
  first_neighbour,  ///< Gamma^n only (Jarolin Eq. 33-35)
  paper,            ///< Gamma^n, Gamma^m and Gamma^n_hat via Eq. 29 (Jarolin Eq. 32, as used there)
};

/// What happened to a particle in the average.
enum class ParticleUse : std::uint8_t {
  used = 0,
  singular = 1,   ///< sum_m K^nm singular (too few bonds or contacts)
  no_volume = 2,  ///< no cell volume (a radical Voronoi cell can vanish for a small particle)
};

struct ParticleTensors {
  std::vector<Voigt6> stiffness;     ///< C^n, Pa; zero unless used
  std::vector<ParticleUse> use;
  std::vector<std::int32_t> coordination;  ///< interactions (intact bonds + contacts)
  std::size_t used = 0, singular = 0, no_volume = 0;
};

/// C^n for every particle from its interactions and volume V^n (m^3). Parallel over particles
/// (OpenMP); each particle sums its own interactions in a fixed order, so the result is bitwise the
/// same for any thread count. Memory: C^n (36 doubles) per particle, and during the call P^n and
/// Gamma^n (18 each) and (sum K)^-1 (9).
ParticleTensors particle_stiffness_tensors(const NeighbourStiffness& neighbours, const std::vector<double>& volume,
                                           Fluctuation fluctuation, double singular_tolerance);

}  // namespace bpm::ste
