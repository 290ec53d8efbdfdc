#pragma once
/// One entry point for every way bpmkit measures a sample's stiffness under the uniaxial
/// compression of a scenario (Jarolin section 4.2): the stiffness tensor estimation, the linear and
/// nonlinear direct stiffness method, and the explicit DEM (with the real platens, or with the
/// linear DSM's kinematic platens). Each returns K (N/m) and E = K l / A with the same l and A.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "compress/kinematic_compression.hpp"
#include "compress/uniaxial_compression.hpp"
#include "dsm/dsm_linear.hpp"
#include "ste/stiffness_tensor_estimation.hpp"

namespace bpm {

enum class StiffnessMethod { ste, dsm, dsm_kinematic, dsm_nonlinear, dem, dem_kinematic };

/// "ste", "dsm", "dsm-kinematic", "dsm-nonlinear", "dem", "dem-kinematic".
std::string_view to_string(StiffnessMethod method);
StiffnessMethod parse_stiffness_method(std::string_view name, std::string_view where);

struct StiffnessSettings {
  UniaxialCompression compression;  ///< axis, platen material, target strain, fit window; DEM rate
  DsmOptions dsm;
  ste::SteOptions ste;  ///< the axis is set from `compression`; the platens are added in series
  KinematicCompressionSettings kinematic;
};

struct StiffnessEstimate {
  StiffnessMethod method = StiffnessMethod::dsm;
  double stiffness = 0.0;       ///< K, N/m
  double youngs_modulus = 0.0;  ///< E = K l / A, Pa
  BodyModuli body;              ///< E and nu of the body's middle third (compress/strain_gauge.hpp)
  std::size_t gauge_particles = 0;
  double seconds = 0.0;         ///< wall clock of the method, including its set-up
  SampleGeometry sample;
  std::vector<Vec3> displacement;  ///< per particle (DSM and DEM), m
  nlohmann::json details;          ///< method-specific figures (solver, iterations, checks)
  std::optional<ste::SteResult> ste;  ///< the whole STE result (tensors, local map) for --method ste
};

/// The estimate as stiffness.json holds it (method, stiffness_N_per_m, youngs_modulus_Pa,
/// sample_length_m, sample_area_m2, wall_s, details), and back: `bpmkit stiffness` writes it, the
/// rows of `bpmkit compare` are it plus the comparison, and `compare --reference-from` reads it.
/// The displacement field and the STE result are not in it.
nlohmann::json to_json(const StiffnessEstimate& e);
/// Throws InputError naming `where` for a missing or mistyped field.
StiffnessEstimate stiffness_estimate_from_json(const nlohmann::json& j, const std::string& where);

/// Runs `method` on a copy of `model` (finalised, at its initial state; its contact materials
/// include the platen material).
StiffnessEstimate estimate_sample_stiffness(const Model& model, StiffnessMethod method, const StiffnessSettings& settings);

}  // namespace bpm
