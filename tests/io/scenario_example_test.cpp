// End to end through the library, as `bpmkit run` does it: Chen's case 1 example scenarios run to
// rest and reproduce the reference tip deflections (Chen Eq. 29) within 0.1 %. Labelled slow.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <nlohmann/json.hpp>
#include <string>

#include "scenario/scenario.hpp"
#include "scenario/scenario_run.hpp"
#include "io_test_util.hpp"

namespace bpm {
namespace {

using test::TempDir;

const std::string kExamples = std::string(BPMKIT_EXAMPLES_DIR) + "/01_cantilever/";

/// Runs an example into a scratch directory; returns the tip (last particle) deflection read back
/// from final_state.csv, in m, positive along the load (-y).
double tip_deflection(const TempDir& dir, const std::string& example) {
  Scenario s = load_scenario(kExamples + example);
  const ScenarioRunResult r = run_scenario(s, dir.path("out"));
  EXPECT_EQ(r.summary.reason, StopReason::rest) << example;
  const auto summary = nlohmann::json::parse(test::read_text(dir.path("out/summary.json")));
  EXPECT_EQ(summary["stop_reason"], "rest");
  const auto lines = test::read_lines(dir.path("out/final_state.csv"));
  EXPECT_EQ(lines.size(), s.model.particles.size() + 1);
  // Columns id,x,y,z,ux,uy,...: uy is the sixth.
  std::istringstream row(lines.back());
  std::string field;
  for (int c = 0; c < 6; ++c) std::getline(row, field, ',');
  return -std::stod(field);
}

TEST(ScenarioExample, Case1TbbmMatchesTimoshenko) {
  TempDir dir;
  const double timoshenko = 8.534242e-3;  // Chen Eq. 29, F = 100 kN, L0 = 4 m, r_b = 0.2 m
  EXPECT_NEAR(tip_deflection(dir, "case1_tbbm.yaml") / timoshenko - 1.0, 0.0, 1e-3);
}

TEST(ScenarioExample, Case1FromCsvMatchesTimoshenko) {
  TempDir dir;
  EXPECT_NEAR(tip_deflection(dir, "case1_tbbm_csv.yaml") / 8.534242e-3 - 1.0, 0.0, 1e-3);
}

TEST(ScenarioExample, Case1EbbmMatchesEulerBernoulli) {
  TempDir dir;
  const double euler_bernoulli = 8.488264e-3;  // Chen Eq. 29 without the shear term
  EXPECT_NEAR(tip_deflection(dir, "case1_ebbm.yaml") / euler_bernoulli - 1.0, 0.0, 1e-3);
}

TEST(ScenarioExample, BarBreaksAtItsWeakestBond) {
  // All bonds of the pulled bar carry the end load, so the first break happens when the ramped load
  // reaches the smallest sigma_t A_b, in tension, at that bond.
  TempDir dir;
  Scenario s = load_scenario(std::string(BPMKIT_EXAMPLES_DIR) + "/03_breakage/pull_to_failure.yaml");
  const BondStore& b = s.model.bonds;
  std::size_t weakest = 0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    if (b.strength[i].tensile < b.strength[weakest].tensile) weakest = i;
  }
  const ScenarioRunResult r = run_scenario(s, dir.path("out"));
  ASSERT_GE(b.breaks.size(), 1u);
  EXPECT_EQ(b.breaks[0].bond, static_cast<std::int32_t>(weakest));
  EXPECT_EQ(b.breaks[0].mode, BreakMode::tension);
  const Load& pull = s.model.loads.front();
  const double load_at_break = pull.force.x * pull.factor(static_cast<double>(b.breaks[0].update) * s.time_step);
  EXPECT_NEAR(load_at_break / b.strength[weakest].tensile, 1.0, 2e-3);
  const auto lines = test::read_lines(dir.path("out/bond_breaks.csv"));
  EXPECT_EQ(lines.size(), b.breaks.size() + 1);
  const auto summary = nlohmann::json::parse(test::read_text(dir.path("out/summary.json")));
  EXPECT_EQ(summary["bonds_broken"]["tension"].get<std::size_t>() + summary["bonds_broken"]["shear"].get<std::size_t>(),
            b.breaks.size());
  EXPECT_EQ(summary["bonds_intact"].get<std::size_t>(), b.size() - b.breaks.size());
}

TEST(ScenarioExample, SmallCylinderCompressionIsQuasiStatic) {
  // The small compression example: the run must reach its target strain quasi-statically (kinetic
  // energy and platen force imbalance small), with a clean linear fit and the cylinder's own l, A.
  TempDir dir;
  Scenario s = load_scenario(std::string(BPMKIT_EXAMPLES_DIR) + "/04_compression/small_cylinder/compression.yaml");
  const ScenarioRunResult r = run_scenario(s, dir.path("out"));
  ASSERT_TRUE(r.compression.has_value());
  const CompressionResult& c = *r.compression;
  EXPECT_EQ(c.stop, "target_strain");
  EXPECT_LT(c.max_kinetic_ratio, 1e-2);
  EXPECT_LT(c.max_force_imbalance, 1e-2);
  EXPECT_GT(c.fit_r2, 0.99);
  EXPECT_NEAR(c.sample.length, 2e-3, 2e-5);                       // cylinder of height 2 mm ...
  EXPECT_NEAR(c.sample.area / (std::numbers::pi * 1e-6), 1.0, 1e-2);  // ... and radius 1 mm
  EXPECT_GT(c.youngs_modulus, 0.0);
}

}  // namespace
}  // namespace bpm
