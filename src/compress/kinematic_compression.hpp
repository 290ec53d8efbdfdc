#pragma once
/// Explicit DEM with the linear DSM's boundary conditions (compress/platen_loading.hpp): the bottom
/// set held along the axis, the top set driven along -axis at constant speed to the platen
/// displacement, then held while the sample comes to rest (Chen's quasi-static stop, every particle
/// slower than rest_speed). Across the axis the sets are free for frictionless platens, held
/// otherwise. This is the DEM reference that the linear DSM must reproduce particle by particle:
/// the same structure, the same constraints, solved by time integration instead of K u = f.
#include <cstdint>
#include <vector>

#include "compress/platen_loading.hpp"
#include "dem/simulation.hpp"

namespace bpm {

struct KinematicCompressionSettings {
  double strain_rate = 0.1;      ///< 1/s, platen speed over sample length during the ramp
  double rest_speed = 1e-9;      ///< m/s, Chen's quasi-static stop
  double particle_damping = 0.7; ///< gamma_b for the run (local damping, Chen Eq. 11-12)
  double safety_factor = 0.8;    ///< time step / critical_time_step
  std::int64_t max_steps = 50'000'000;
};

struct KinematicCompressionResult {
  std::vector<Vec3> displacement;  ///< per particle at rest, m
  double force_top = 0.0;          ///< compressive, from the bond loads on the top set, N
  double force_bottom = 0.0;
  double stiffness = 0.0;          ///< force_top / displacement, N/m
  double youngs_modulus = 0.0;     ///< K l / A, Pa
  double max_speed = 0.0;          ///< at the end, m/s
  bool at_rest = false;
  std::int64_t steps = 0;
  double time_step = 0.0;
  double seconds = 0.0;
};

/// Runs on a copy of `model` (bonds finalised); the model itself is not changed.
KinematicCompressionResult run_kinematic_compression(const Model& model, const PlatenLoading& load,
                                                     const KinematicCompressionSettings& settings = {});

}  // namespace bpm
