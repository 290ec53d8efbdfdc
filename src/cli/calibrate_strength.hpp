#pragma once
/// `bpmkit calibrate --target-ucs PA --target-bts PA --disc DISC SCENARIO`: the bond strengths for
/// a datasheet's UCS and BTS by DEM runs of the strength tests
/// (calibrate/strength_calibration.hpp), after the elastic stages if E (and nu) are targets too:
/// the cylinder of SCENARIO and the disc share the calibrated bond materials (by name). Every
/// evaluation is printed and written to calibration.json as it ends; calibrated.yaml and
/// calibrated_disc.yaml get the strengths.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "bonds/bond_material.hpp"
#include "io/output_folder.hpp"
#include "scenario/scenario.hpp"

namespace bpm::cli {

struct StrengthOptions {
  double target_ucs = 0.0;  ///< Pa
  double target_bts = 0.0;  ///< Pa
  std::string disc;         ///< the Brazilian test's scenario
  double tolerance = 0.02;
  int max_evaluations = 10;
};

void add_strength_options(CLI::App* cmd, StrengthOptions& o);

/// The scenarios of the strength tests: SCENARIO itself for the UCS, the disc for the BTS.
struct StrengthScenarios {
  Scenario cylinder;
  std::optional<Scenario> disc;
};

/// Checks that each targeted test runs past its peak (failure_drop) on breakable bonds, and that
/// the disc is a Brazilian test whose bond materials SCENARIO defines; InputError otherwise.
StrengthScenarios load_strength_scenarios(const Scenario& scenario, const StrengthOptions& o);

/// Runs the search with the bond materials `answer` (SCENARIO's, after the elastic stages), scales
/// their strengths in place, writes the calibrated scenarios and returns the strength block that
/// `calibration` (calibration.json, rewritten after every evaluation) holds.
nlohmann::json calibrate_strengths(const std::string& scenario_path, const StrengthScenarios& tests,
                                   const StrengthOptions& o, std::vector<BondMaterial>& answer,
                                   bool with_shear_ratio, const OutputFolder& folder,
                                   nlohmann::json& calibration);

}  // namespace bpm::cli
