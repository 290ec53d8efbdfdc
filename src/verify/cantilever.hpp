#pragma once
/// Chen's cantilever verification suite (Chen 2022, section 3, Table 3, cases 1-5).
///
/// A row of particles, the first fixed in all six DOFs, the last loaded by F = 100 kN across the
/// axis, ramped at 100 kN/s for 1 s and then held; E_b = 200 GPa, nu_b = 0.3. Each run stops at
/// quasi-static rest (max particle speed < 1e-9 m/s). For every case, variant and model we report
/// the DEM tip deflection, the Timoshenko (Eq. 29) and Euler-Bernoulli tip deflections, and the
/// exact static deflection of the same discrete model (linearised elements, solved directly).
///
/// Chen gives no particle density; we use 7850 kg/m^3 (steel, consistent with E = 200 GPa). It
/// changes the dynamics only, not the steady state.
#include <string>
#include <vector>

#include "bonds/bond_material.hpp"
#include "model/model.hpp"
#include "dem/simulation.hpp"

namespace bpm::verify {

struct CantileverSpec {
  std::string case_name;        ///< "case1" .. "case5"
  std::string variant;          ///< e.g. "bonds=4", "middle_radius=0.4"
  std::vector<double> x;        ///< particle centres along the axis, m (first one fixed)
  std::vector<double> radius;   ///< particle radii, m
  double bond_radius = 0.2;     ///< r_b, m
  double youngs_modulus = 200e9;
  double poisson_ratio = 0.3;
  double load = 1e5;            ///< N, applied in -y at the last particle
  double ramp_time = 1.0;       ///< s
  double density = 7850.0;      ///< kg/m^3
  ShearOverride pbm_shear = ShearOverride::none;  ///< case 5: PBM k_s from Eq. 26

  double beam_length() const { return x.back() - x.front(); }
};

/// Chen Table 3 and sections 3.1-3.5: the variants of one case (1..5).
std::vector<CantileverSpec> cantilever_case(int case_number);

/// The material of a spec for one model key (applies the case-5 shear override to PBM).
BondMaterial cantilever_material(const CantileverSpec& spec, const std::string& model_key);

/// Builds the model: particles along x, consecutive pairs bonded, first particle fixed, tip load.
Model build_cantilever(const CantileverSpec& spec, const std::string& model_key, double particle_damping);

/// alpha = F L0^2 / (E_b I_b) of the whole beam, the parameter of the large-deflection correction.
double load_parameter(const CantileverSpec& spec);

/// Timoshenko deflection at distance s from the fixed end (Chen Eq. 28); shear term included or not.
double timoshenko_deflection(const CantileverSpec& spec, double s, bool include_shear = true);

struct CantileverResult {
  std::string case_name, variant, model;
  int bonds = 0;
  double beam_length = 0.0;
  double tip_dem = 0.0;          ///< m, deflection (positive along the load)
  double tip_discrete = 0.0;     ///< m, exact static solution of the same discrete model
  double tip_timoshenko = 0.0;   ///< m, Chen Eq. 29
  double tip_euler_bernoulli = 0.0;  ///< m, Eq. 29 without the shear term
  /// Elastica large-deflection factor (elastica.hpp): the small-deflection references above are
  /// multiplied by it before they are compared with the geometrically exact DEM.
  double large_deflection_factor = 1.0;
  std::vector<double> deflection_dem;       ///< per particle, m
  std::vector<double> deflection_discrete;  ///< per particle, m
  RunSummary run;
  double time_step = 0.0;

  /// Relative errors against the large-deflection-corrected references.
  double error_vs_discrete() const { return tip_dem / (large_deflection_factor * tip_discrete) - 1.0; }
  double error_vs_timoshenko() const { return tip_dem / (large_deflection_factor * tip_timoshenko) - 1.0; }
  double error_vs_euler_bernoulli() const {
    return tip_dem / (large_deflection_factor * tip_euler_bernoulli) - 1.0;
  }
  /// The same against the uncorrected small-deflection references, as Chen reports them.
  double linear_error_vs_discrete() const { return tip_dem / tip_discrete - 1.0; }
  double linear_error_vs_timoshenko() const { return tip_dem / tip_timoshenko - 1.0; }
};

struct CantileverRunOptions {
  double particle_damping = 0.7;   ///< gamma_b used to reach rest quickly (Chen: any small value)
  double rest_speed = 1e-9;        ///< m/s (Chen)
  double time_step_safety = 0.8;   ///< fraction of the guaranteed stability limit
  double max_time = 600.0;         ///< s of simulated time, a guard against non-convergence
};

/// Runs one model on one spec.
CantileverResult run_cantilever(const CantileverSpec& spec, const std::string& model_key,
                                const CantileverRunOptions& options = {});

/// The models run on each case: pbm, ebbm, tbbm.
std::vector<std::string> cantilever_models();

/// Bond stiffnesses of case 3 for Chen Table 5: one row per bond count with k_n and k_s per model.
struct StiffnessRow {
  int bonds = 0;
  double bond_to_beam_length = 0.0;
  double k_n = 0.0;
  double k_s_pbm = 0.0, k_s_ebbm = 0.0, k_s_tbbm = 0.0;
};
std::vector<StiffnessRow> case3_stiffness_table();

}  // namespace bpm::verify
