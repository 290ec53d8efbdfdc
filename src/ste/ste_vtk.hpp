#pragma once
/// The per-particle STE result for ParaView: one VTK XML PolyData file (.vtp; io/vtk_polydata.hpp,
/// binary and zlib-compressed) with the particle centres as points and point data
///   radius (m), id, volume (V^n, m^3), used (1/0), use (0 used, 1 singular, 2 no volume),
///   coordination, C11 C22 C33 C44 C55 C66 C12 C13 C23 (of C^n, Pa; the Voigt diagonal and the
///   normal coupling), and with the local map E_local_x/y/z (Pa) and E_excess_x/y/z
///   ((local - mean) / mean = -Jarolin Eq. 36; local_map.hpp).
/// Glyph filter: sphere, scale by radius, factor 2.
#include <string>

#include "model/particle_store.hpp"
#include "ste/stiffness_tensor_estimation.hpp"

namespace bpm::ste {

std::string ste_polydata_vtp(const ParticleStore& particles, const SteResult& result);

/// Writes ste_polydata_vtp atomically (io/atomic_file.hpp); throws InputError naming the path.
void write_ste_vtp(const std::string& path, const ParticleStore& particles,
                   const SteResult& result);

}  // namespace bpm::ste
