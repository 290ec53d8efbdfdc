#pragma once
/// The local stiffness map (Jarolin section 4.4): for each particle, the volume-weighted average of
/// the C^n of the used particles whose centres lie within a sphere of diameter factor * d around
/// its centre (Jarolin: three particle diameters; d the mean diameter, or optionally the particle's
/// own), and from that local tensor the stiffness in each direction.
///
/// Documented choices:
/// - "Stiffness in direction i" is the directional Young's modulus E_i = 1 / S_ii of the local
///   tensor (what the sample stiffness K = E A / l uses), not C_ii (which ignores the lateral
///   contraction).
/// - The deviation is written as excess_i = (E_i - mean_i) / mean_i: positive where the sample is
///   locally stiffer. This is minus Jarolin Eq. 36 ((mean - local) / mean), hence the name. The
///   mean is the arithmetic mean over the particles that have a local value (Eq. 36).
#include <cstdint>
#include <vector>

#include "model/particle_store.hpp"
#include "ste/misra_chang.hpp"

namespace bpm::ste {

struct LocalMap {
  double sphere_diameter = 0.0;   ///< factor * mean diameter, m (per particle if own diameters)
  std::vector<Vec3> modulus;      ///< (E_x, E_y, E_z) of the local tensor, Pa; 0 without a value
  std::vector<std::uint8_t> valid;  ///< 1 if some used particle lies in the sphere
  std::size_t valid_count = 0;
  Vec3 mean;                      ///< arithmetic mean of modulus over the valid particles, Pa
  std::vector<Vec3> excess;       ///< (E_i - mean_i) / mean_i = -(Jarolin Eq. 36); 0 if not valid
};

/// Parallel over particles (cell grid of the sphere radius); bitwise the same for any thread count.
LocalMap local_stiffness_map(const ParticleStore& particles, const ParticleTensors& tensors,
                             const std::vector<double>& volume, double diameter_factor, bool own_diameter);

}  // namespace bpm::ste
