// The contact sections of a scenario (contacts, walls, compression) read, validated and run end to
// end: a bonded cubic lattice compressed through `compression:` gives the analytical lattice
// stiffness in summary.json, and bad input names its key.
#include <gtest/gtest.h>

#include <fmt/core.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>

#include "scenario/scenario.hpp"
#include "scenario/scenario_run.hpp"
#include "io_test_util.hpp"

namespace bpm {
namespace {

using test::TempDir;

/// nx x ny x nz touching spheres of R = 1 mm as a particles CSV.
std::string lattice_csv(int nx, int ny, int nz) {
  std::string s = "id,x,y,z,radius\n";
  int id = 0;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
      for (int k = 0; k < nz; ++k) s += fmt::format("{},{},{},{},0.001\n", id++, 2e-3 * i, 2e-3 * j, 2e-3 * k);
  return s;
}

const std::string kCompression = R"(description: bonded lattice between platens
particle_materials:
  steel:
    density: 7850
    contact: {law: linear, k_n: 2e9, k_t: 2e9, restitution: 0.5}
bond_materials:
  beam: {model: tbbm, youngs_modulus: 200e9, poisson_ratio: 0.3, radius_multiplier: 1}
particles:
  material: steel
  file: lattice.csv
bonds:
  material: beam
  auto: {max_gap: 0}
damping:
  particle: 0.7
compression:
  platen_material: steel
  strain_rate: 5
  target_strain: 0.001
  fit_window: [0.3, 1.0]
  curve_points: 100
output:
  vtk: false
)";

TEST(ScenarioCompression, LatticeStiffnessInTheSummary) {
  TempDir dir;
  dir.write("lattice.csv", lattice_csv(3, 3, 8));
  Scenario s = load_scenario(dir.write("scenario.yaml", kCompression));
  ASSERT_TRUE(s.compression.has_value());
  const ScenarioRunResult r = run_scenario(s, dir.path("out"));
  ASSERT_TRUE(r.compression.has_value());
  // 9 columns of 7 bonds (k_n = E_b pi R^2 / 2R) in series with two platen contacts each
  // (two linear materials of 2e9 N/m in series: 1e9 N/m).
  const double k_n = 200e9 * std::numbers::pi * 1e-6 / 2e-3;
  const double analytical = 9.0 / (7.0 / k_n + 2.0 / 1e9);
  const auto summary = nlohmann::json::parse(test::read_text(dir.path("out/summary.json")));
  EXPECT_EQ(summary["stop_reason"], "target_strain");
  const double K = summary["compression"]["stiffness_N_per_m"].get<double>();
  EXPECT_NEAR(K / analytical, 1.0, 1e-3);
  EXPECT_NEAR(summary["compression"]["sample_length_m"].get<double>(), 16e-3, 1e-12);
  const double A = summary["compression"]["sample_area_m2"].get<double>();
  EXPECT_NEAR(A / (36e-6 - (4.0 - std::numbers::pi) * 1e-6), 1.0, 1e-4);
  EXPECT_NEAR(summary["compression"]["youngs_modulus_Pa"].get<double>(), K * 16e-3 / A, 1e-6 * K * 16e-3 / A);
  const auto curve = test::read_lines(dir.path("out/force_displacement.csv"));
  EXPECT_EQ(curve.size(), r.compression->curve.size() + 1);
  EXPECT_GE(r.compression->curve.size(), 100u);
  // The two platens appear in walls.csv: 1 header + one row per curve point.
  const auto walls = test::read_lines(dir.path("out/walls.csv"));
  EXPECT_NE(walls.front().find("platen_top_uz"), std::string::npos);
  EXPECT_EQ(walls.size(), r.compression->curve.size() + 1);
}

void expect_error(const std::string& yaml, const std::vector<std::string>& fragments) {
  TempDir dir;
  dir.write("lattice.csv", lattice_csv(2, 2, 2));
  const std::string message = test::load_error(dir.write("scenario.yaml", yaml));
  test::expect_contains(message, fragments);
}

std::string with(const std::string& from, const std::string& to) {
  std::string s = kCompression;
  test::replace_once(s, from, to);
  return s;
}

TEST(ScenarioCompression, BadInputNamesTheKey) {
  expect_error(with("law: linear", "law: hooke"), {"particle_materials.steel.contact.law", "unknown contact law 'hooke'"});
  expect_error(with("law: linear, k_n: 2e9", "law: linear, youngs_modulus: 1e9, k_n: 2e9"),
               {"contact.youngs_modulus", "linear law takes k_n and k_t"});
  expect_error(with("restitution: 0.5}", "restitution: 1.5}"), {"contact.restitution", "(0, 1]"});
  expect_error(with("    contact: {law: linear, k_n: 2e9, k_t: 2e9, restitution: 0.5}\n", ""),
               {"scenario.yaml", "has no contact properties"});
  expect_error(with("  platen_material: steel", "  platen_material: iron"), {"compression.platen_material", "'iron'"});
  expect_error(with("  target_strain: 0.001", "  target_strain: 1.5"), {"compression.target_strain", "below 1"});
  expect_error(with("  fit_window: [0.3, 1.0]", "  fit_window: [0.8, 0.5]"), {"compression.fit_window"});
  expect_error(with("  curve_points: 100", "  curve_points: 100\n  max_strain: 0.01"), {"compression.max_strain", "failure_drop"});
  expect_error(kCompression + "stop: {end_time: 1}\n", {"stop", "compression test stops"});
  const std::string walls = "walls:\n  - {name: floor, shape: plane, point: [0, 0, 0], normal: [0, 0, 1], material: steel}\n";
  std::string w = walls;
  test::replace_once(w, "shape: plane", "shape: sphere");
  expect_error(kCompression + w, {"walls[0].shape", "unknown wall shape 'sphere'"});
  w = walls;
  test::replace_once(w, "normal: [0, 0, 1]", "normal: [0, 0, 0]");
  expect_error(kCompression + w, {"walls[0].normal", "must not be zero"});
  w = walls;
  test::replace_once(w, "shape: plane", "shape: cylinder");
  expect_error(kCompression + w, {"walls[0].axis", "missing"});
  expect_error(kCompression + "contacts: {particle_particle: true, bonded: glue}\n", {"contacts.bonded", "unknown value 'glue'"});
  // The laboratory tests.
  expect_error(with("  platen_material: steel", "  test: shear\n  platen_material: steel"),
               {"compression.test", "uniaxial, brazilian or tension", "'shear'"});
  expect_error(with("  platen_material: steel", "  test: brazilian\n  platen_material: steel"),
               {"compression", "needs disc_axis", "disc_axis: [0, 0, 1]"});
  expect_error(with("  platen_material: steel", "  test: brazilian\n  disc_axis: [0, 0, 2]\n  platen_material: steel"),
               {"compression.disc_axis", "normal to the loading axis"});
  expect_error(with("  platen_material: steel", "  disc_axis: [1, 0, 0]\n  platen_material: steel"),
               {"compression.disc_axis", "only to test: brazilian"});
  expect_error(with("  platen_material: steel", "  grip_depth: 0.002\n  platen_material: steel"),
               {"compression.grip_depth", "only to test: tension"});
}

/// `test: tension` through a scenario: grips instead of platens, the strength block in
/// summary.json, and the bonds broken by mode in force_displacement.csv.
TEST(ScenarioCompression, DirectTensionWritesItsStrengthAndBreakage) {
  TempDir dir;
  dir.write("lattice.csv", lattice_csv(2, 2, 6));
  // The bonds break near strain 1.25e-4: 5 bonds of 3e-7 m stretch over 12 mm.
  std::string yaml = with("  platen_material: steel", "  test: tension\n  platen_material: steel\n  failure_drop: 0.5\n  max_strain: 3e-4");
  test::replace_once(yaml, "target_strain: 0.001", "target_strain: 3e-5");
  test::replace_once(yaml, "curve_points: 100", "curve_points: 1000");
  test::replace_once(yaml, "strain_rate: 5", "strain_rate: 0.2");
  test::replace_once(yaml, "radius_multiplier: 1}", "radius_multiplier: 1, tensile_strength: 30e6}");
  Scenario s = load_scenario(dir.write("scenario.yaml", yaml));
  ASSERT_EQ(s.compression->test, LabTest::tension);
  const ScenarioRunResult r = run_scenario(s, dir.path("out"));
  const auto summary = nlohmann::json::parse(test::read_text(dir.path("out/summary.json")));
  const auto& strength = summary["compression"]["strength"];
  EXPECT_EQ(strength["test"], "tension");
  EXPECT_EQ(strength["definition"], "tensile strength = F / A");
  EXPECT_EQ(strength["grip_particles"], 8);
  // Four columns of bonds in pure tension: each breaks at sigma_t pi r_b^2.
  const double peak = 4.0 * 30e6 * std::numbers::pi * 1e-6;
  EXPECT_NEAR(strength["peak_force_N"].get<double>() / peak, 1.0, 2e-2);
  EXPECT_GT(strength["bonds_broken_tension"].get<int>(), 0);
  EXPECT_EQ(strength["bonds_broken_shear"], 0);
  const auto curve = test::read_lines(dir.path("out/force_displacement.csv"));
  EXPECT_NE(curve.front().find("bonds_broken_tension,bonds_broken_shear"), std::string::npos);
  // No platens in a tension test.
  EXPECT_EQ(r.compression->stop, "failure");
}

}  // namespace
}  // namespace bpm
