#pragma once
/// The calibrated scenario: the user's scenario file with the bond parameters a calibration found,
/// written beside its results so that `bpmkit run` runs it as it is.
#include <string>
#include <vector>

#include "bonds/bond_material.hpp"

namespace bpm {

/// The YAML text of the scenario file `scenario_path` with each named bond material's
/// youngs_modulus, its kappa or shear_coefficient where `with_shear_ratio`, and its
/// tensile_strength and shear_strength where `with_strengths`, taken from `materials`; the particle
/// and bond file paths rewritten for a file in `folder` (relative where one exists, else absolute).
/// `header` lines become comments on top. Comments of the original are not kept (the original stays
/// where it is).
std::string calibrated_scenario_yaml(const std::string& scenario_path,
                                     const std::vector<BondMaterial>& materials,
                                     bool with_shear_ratio, bool with_strengths,
                                     const std::string& folder,
                                     const std::vector<std::string>& header);

}  // namespace bpm
