// Good scenarios parse into the right model: counts, bond constants from the registry (Chen
// Table 9), defaults, constraints, particle sets, CSV inputs and automatic bonding.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "bonds/bond_model.hpp"
#include "dem/time_step.hpp"
#include "spatial/pairs_within_gap.hpp"
#include "scenario/scenario.hpp"
#include "io_test_util.hpp"

namespace bpm {
namespace {

using test::edited;
using test::replace_once;
using test::kGoodScenario;
using test::TempDir;

Scenario load_text(const TempDir& dir, const std::string& yaml) { return load_scenario(dir.write("scenario.yaml", yaml)); }

TEST(ScenarioParse, GoodScenarioCountsAndStiffness) {
  TempDir dir;
  const Scenario s = load_text(dir, kGoodScenario);
  const Model& m = s.model;
  ASSERT_EQ(m.particles.size(), 3u);
  ASSERT_EQ(m.bonds.size(), 2u);
  EXPECT_EQ(s.particle_material_names, std::vector<std::string>{"steel"});
  EXPECT_EQ(s.bond_material_names, std::vector<std::string>{"beam"});
  EXPECT_EQ(m.particles.id[2], 2);
  EXPECT_DOUBLE_EQ(m.particles.mass[0], 7850.0 * 4.0 / 3.0 * std::numbers::pi * 0.008);

  // TBBM constants (Chen Table 9): k_n = E A / L, k_s = 12 E I / L^3 / (1 + Phi_s) (Eq. 18, 25),
  // k_tor = G J / L, k_ben = E I / L.
  const double E = 200e9, nu = 0.3, r = 0.2, L = 0.4;
  const double A = std::numbers::pi * r * r, I = 0.25 * std::numbers::pi * r * r * r * r;
  const double phi = 20.0 * r * r * (1.0 + nu) / (3.0 * L * L);
  for (std::size_t b = 0; b < 2; ++b) {
    const BondStiffness& k = m.bonds.stiffness[b];
    EXPECT_NEAR(k.k_n, E * A / L, 1e-9 * E * A / L);
    EXPECT_NEAR(k.k_s, 12.0 * E * I / (L * L * L) / (1.0 + phi), 1e-9 * k.k_n);
    EXPECT_NEAR(k.k_tor, E / (2.0 * (1.0 + nu)) * 2.0 * I / L, 1e-9 * k.k_n);
    EXPECT_NEAR(k.k_ben, E * I / L, 1e-9 * k.k_n);
    EXPECT_DOUBLE_EQ(m.bonds.radius[b], 0.2);
    EXPECT_NEAR(m.bonds.rest_length[b], 0.4, 1e-15);
  }
  EXPECT_EQ(m.bonds.alpha[1], 1);
  EXPECT_EQ(m.bonds.beta[1], 2);

  // Constraints, loads, damping.
  EXPECT_EQ(m.particles.translation_free[0], (Vec3{0, 0, 0}));
  EXPECT_EQ(m.particles.rotation_free[0], (Vec3{0, 0, 0}));
  EXPECT_EQ(m.particles.translation_free[1], (Vec3{1, 1, 1}));
  ASSERT_EQ(m.loads.size(), 1u);
  EXPECT_EQ(m.loads[0].particles, std::vector<std::int32_t>{2});
  EXPECT_EQ(m.loads[0].force, (Vec3{0, -1e5, 0}));
  EXPECT_DOUBLE_EQ(m.loads[0].ramp_time, 0.01);
  EXPECT_DOUBLE_EQ(m.damping.particle, 0.7);

  // Time step: auto = 0.8 of the limit of the finalised model.
  EXPECT_DOUBLE_EQ(s.time_step_limit, critical_time_step(m).critical);
  EXPECT_DOUBLE_EQ(s.time_step, 0.8 * s.time_step_limit);
  EXPECT_EQ(s.stop.max_steps, 200);
  EXPECT_TRUE(std::isinf(s.stop.end_time));
  EXPECT_DOUBLE_EQ(s.stop.rest_after, 0.01);  // default: the longest ramp
  EXPECT_EQ(s.output.every_steps, 50);
  EXPECT_TRUE(s.output.vtk);
  ASSERT_EQ(s.probes.size(), 1u);
  EXPECT_EQ(s.probes[0].name, "tip");
  EXPECT_EQ(s.probes[0].particles, std::vector<std::int32_t>{2});
}

TEST(ScenarioParse, BondRadiusRules) {
  TempDir dir;
  // No radius in the material: r_b = 1 * min(R_alpha, R_beta).
  std::string yaml = edited("    radius: 0.2\n", "");
  replace_once(yaml, "{id: 2, position: [0.8, 0, 0], radius: 0.2}", "{id: 2, position: [0.8, 0, 0], radius: 0.1}");
  Scenario s = load_text(dir, yaml);
  EXPECT_DOUBLE_EQ(s.model.bonds.radius[0], 0.2);
  EXPECT_DOUBLE_EQ(s.model.bonds.radius[1], 0.1);
  // radius_multiplier scales the smaller particle radius.
  s = load_text(dir, edited("    radius: 0.2\n", "    radius_multiplier: 0.5\n"));
  EXPECT_DOUBLE_EQ(s.model.bonds.radius[0], 0.1);
  // A radius given on the bond wins.
  s = load_text(dir, edited("list: [[0, 1], [1, 2]]", "list: [[0, 1], {i: 1, j: 2, radius: 0.05}]"));
  EXPECT_DOUBLE_EQ(s.model.bonds.radius[0], 0.2);
  EXPECT_DOUBLE_EQ(s.model.bonds.radius[1], 0.05);
  EXPECT_NEAR(s.model.bonds.stiffness[1].k_n, 200e9 * std::numbers::pi * 0.05 * 0.05 / 0.4, 1.0);
}

TEST(ScenarioParse, ModelOptionsReachTheBondConstants) {
  TempDir dir;
  Scenario s = load_text(dir, edited("    model: tbbm\n", "    model: pbm\n    kappa: 3\n"));
  const BondStiffness k = s.model.bonds.stiffness[0];
  EXPECT_NEAR(k.k_s, k.k_n / 3.0, 1e-9 * k.k_n);  // Chen Table 1: k_s = k_n / kappa

  s = load_text(dir, edited("    model: tbbm\n", "    model: pbm\n    shear_stiffness: 1.5e9\n"));
  EXPECT_DOUBLE_EQ(s.model.bonds.stiffness[0].k_s, 1.5e9);

  s = load_text(dir, edited("    model: tbbm\n", "    model: pbm\n    shear_stiffness: euler_bernoulli\n"));
  const double I = 0.25 * std::numbers::pi * std::pow(0.2, 4);
  EXPECT_NEAR(s.model.bonds.stiffness[0].k_s, 12.0 * 200e9 * I / std::pow(0.4, 3), 1.0);  // Chen Eq. 26

  s = load_text(dir, edited("    model: tbbm\n", "    model: obermayr\n    shear_coefficient: 0.5\n"));
  const BondStiffness ko = s.model.bonds.stiffness[0];
  EXPECT_NEAR(ko.k_s, 0.5 * ko.k_n / (2.0 * 1.3), 1e-9 * ko.k_n);  // Chen Eq. 45

  // Whatever the model, the scenario's constants are make_bond_constants' for the same inputs.
  for (const BondModelInfo& info : bond_models()) {
    s = load_text(dir, edited("model: tbbm", "model: " + std::string(info.key)));
    BondMaterial mat = s.bond_materials[0];
    const BondConstants c = make_bond_constants(mat, {0.2, 0.4, 0.2, 0.2});
    EXPECT_DOUBLE_EQ(s.model.bonds.stiffness[0].k_s, c.stiffness.k_s) << info.key;
    EXPECT_DOUBLE_EQ(s.model.bonds.stiffness[0].k_tor, c.stiffness.k_tor) << info.key;
  }
}

TEST(ScenarioParse, PrescribedVelocityAndPartialFix) {
  TempDir dir;
  const Scenario s = load_text(
      dir, edited("  - particles: [0]\n    fix: all\n",
                  "  - particles: [0]\n    fix: all\n  - particles: [1]\n    fix: [z, rx]\n    velocity: [0.5, ~, ~]\n"
                  "    angular_velocity: [~, ~, 2]\n"));
  const ParticleStore& p = s.model.particles;
  EXPECT_EQ(p.translation_free[1], (Vec3{0, 1, 0}));
  EXPECT_EQ(p.rotation_free[1], (Vec3{0, 1, 0}));
  EXPECT_EQ(p.velocity[1], (Vec3{0.5, 0, 0}));
  EXPECT_EQ(p.angular_velocity[1], (Vec3{0, 0, 2}));
}

TEST(ScenarioParse, RegionAndAllSelectParticles) {
  TempDir dir;
  Scenario s = load_text(dir, edited("  - particles: [2]\n", "  - region: {box: {min: [0.3, -1, -1], max: [1, 1, 1]}}\n"));
  EXPECT_EQ(s.model.loads[0].particles, (std::vector<std::int32_t>{1, 2}));
  s = load_text(dir, edited("{name: tip, particles: [2]}", "{name: all_particles, particles: all}"));
  EXPECT_EQ(s.probes[0].particles, (std::vector<std::int32_t>{0, 1, 2}));
}

TEST(ScenarioParse, OutputEveryTimeAndExplicitTimeStep) {
  TempDir dir;
  Scenario s = load_text(dir, edited("time_step: auto", "time_step: 1e-5"));
  EXPECT_DOUBLE_EQ(s.time_step, 1e-5);
  std::string yaml = edited("time_step: auto", "time_step: 1e-5");
  replace_once(yaml, "every_steps: 50", "every_time: 1e-3");
  s = load_text(dir, yaml);
  EXPECT_EQ(s.output.every_steps, 100);
  EXPECT_DOUBLE_EQ(s.output.every_time, 1e-3);
  s = load_text(dir, edited("output:\n  every_steps: 50\n", "output:\n  vtk: false\n"));
  EXPECT_EQ(s.output.every_steps, 0);
  EXPECT_FALSE(s.output.vtk);
  s = load_text(dir, edited("time_step: auto", "time_step: auto\n  safety_factor: 0.5"));
  EXPECT_DOUBLE_EQ(s.time_step, 0.5 * s.time_step_limit);
}

TEST(ScenarioParse, RowOfParticlesWithDirection) {
  TempDir dir;
  const std::string list =
      "  list:\n    - {id: 0, position: [0, 0, 0], radius: 0.2}\n    - {id: 1, position: [0.4, 0, 0], radius: 0.2}\n"
      "    - {id: 2, position: [0.8, 0, 0], radius: 0.2}\n";
  const Scenario s = load_text(dir, edited(list, "  row: {count: 3, spacing: 0.4, radius: 0.2, start: [1, 2, 3], direction: [0, 0, 2]}\n"));
  ASSERT_EQ(s.model.particles.size(), 3u);
  EXPECT_EQ(s.model.particles.id[2], 2);
  EXPECT_NEAR(s.model.particles.position[2].z, 3.8, 1e-15);
  EXPECT_DOUBLE_EQ(s.model.particles.position[2].x, 1.0);
}

TEST(ScenarioParse, CsvInputsWithAndWithoutHeaders) {
  TempDir dir;
  const std::string two_materials = edited("particle_materials:\n", "particle_materials:\n  light:\n    density: 1000\n");
  const std::string list =
      "  list:\n    - {id: 0, position: [0, 0, 0], radius: 0.2}\n    - {id: 1, position: [0.4, 0, 0], radius: 0.2}\n"
      "    - {id: 2, position: [0.8, 0, 0], radius: 0.2}\n";
  std::string yaml = two_materials;
  replace_once(yaml, list, "  file: parts/particles.csv\n");
  replace_once(yaml, "  list: [[0, 1], [1, 2]]", "  file: parts/bonds.csv");
  std::filesystem::create_directories(dir.path("parts"));
  // No header, comments, CRLF line ends, spaces, an optional material column.
  dir.write("parts/particles.csv", "# three particles\r\n0, 0, 0, 0, 0.2\r\n\r\n1,0.4,0,0,0.2,light\r\n2,0.8,0,0,0.2\r\n");
  dir.write("parts/bonds.csv", "0,1,0.1\n1,2,beam\n");
  Scenario s = load_text(dir, yaml);
  ASSERT_EQ(s.model.particles.size(), 3u);
  EXPECT_EQ(s.model.particles.material, (std::vector<std::int32_t>{1, 0, 1}));  // "steel" is the default
  EXPECT_DOUBLE_EQ(s.model.particles.mass[0], 7850.0 * 4.0 / 3.0 * std::numbers::pi * 0.008);
  EXPECT_DOUBLE_EQ(s.model.particles.mass[1], 1000.0 * 4.0 / 3.0 * std::numbers::pi * 0.008);
  ASSERT_EQ(s.model.bonds.size(), 2u);
  EXPECT_DOUBLE_EQ(s.model.bonds.radius[0], 0.1);  // third column a number: radius
  EXPECT_DOUBLE_EQ(s.model.bonds.radius[1], 0.2);  // third column a name: material

  // With headers.
  dir.write("parts/particles.csv", "id,x,y,z,radius\n10,0,0,0,0.2\n11,0.4,0,0,0.2\n12,0.8,0,0,0.2\n");
  dir.write("parts/bonds.csv", "i,j,radius,material\n10,11,0.2,beam\n12,11,0.15,beam\n");
  replace_once(yaml, "particles: [0]", "particles: [10]");
  replace_once(yaml, "particles: [2]", "particles: [12]");
  replace_once(yaml, "particles: [2]", "particles: [12]");
  s = load_text(dir, yaml);
  EXPECT_EQ(s.model.particles.id, (std::vector<std::int64_t>{10, 11, 12}));
  EXPECT_EQ(s.model.bonds.alpha[1], 2);  // bond order and direction as given
  EXPECT_DOUBLE_EQ(s.model.bonds.radius[1], 0.15);
  EXPECT_EQ(s.probes[0].particles, std::vector<std::int32_t>{2});
}

TEST(ScenarioParse, AutoBondsOnAGrid) {
  // 5 x 5 x 5 touching spheres (R = 0.2 m, spacing 0.4 m): only the 3 * 4 * 25 = 300 face
  // neighbours touch; diagonal neighbours are 0.166 m apart.
  TempDir dir;
  std::string csv = "id,x,y,z,radius\n";
  int id = 0;
  for (int i = 0; i < 5; ++i) {
    for (int j = 0; j < 5; ++j) {
      for (int k = 0; k < 5; ++k) csv += std::to_string(id++) + "," + std::to_string(0.4 * i) + "," + std::to_string(0.4 * j) + "," + std::to_string(0.4 * k) + ",0.2\n";
    }
  }
  dir.write("grid.csv", csv);
  const std::string list =
      "  list:\n    - {id: 0, position: [0, 0, 0], radius: 0.2}\n    - {id: 1, position: [0.4, 0, 0], radius: 0.2}\n"
      "    - {id: 2, position: [0.8, 0, 0], radius: 0.2}\n";
  std::string yaml = edited(list, "  file: grid.csv\n");
  replace_once(yaml, "  list: [[0, 1], [1, 2]]", "  auto: {max_gap: 0}");
  Scenario s = load_text(dir, yaml);
  EXPECT_EQ(s.model.bonds.size(), 300u);
  // A gap of 0.17 m also catches the 2 * 5 * 4 * 4 * 3 = 480 face diagonals.
  replace_once(yaml, "max_gap: 0", "max_gap: 0.17");
  s = load_text(dir, yaml);
  EXPECT_EQ(s.model.bonds.size(), 780u);
}

TEST(ScenarioParse, NeighbourPairsMatchBruteForce) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coord(0.0, 3.0), rad(0.02, 0.15);
  std::vector<Vec3> x(600);
  std::vector<double> r(600);
  for (std::size_t i = 0; i < x.size(); ++i) {
    x[i] = {coord(rng), coord(rng), coord(rng)};
    r[i] = rad(rng);
  }
  const double gap = 0.05;
  std::vector<std::pair<std::int32_t, std::int32_t>> brute;
  for (std::size_t i = 0; i < x.size(); ++i) {
    for (std::size_t j = i + 1; j < x.size(); ++j) {
      if (norm(x[j] - x[i]) - r[i] - r[j] <= gap) brute.emplace_back(static_cast<std::int32_t>(i), static_cast<std::int32_t>(j));
    }
  }
  EXPECT_GT(brute.size(), 100u);
  EXPECT_EQ(pairs_within_gap(x, r, gap), brute);
}

TEST(ScenarioParse, EveryExampleLoads) {
  int count = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(BPMKIT_EXAMPLES_DIR)) {
    if (entry.path().extension() != ".yaml") continue;
    ++count;
    SCOPED_TRACE(entry.path().string());
    EXPECT_NO_THROW({
      const Scenario s = load_scenario(entry.path().string());
      EXPECT_GT(s.model.bonds.size(), 0u);
      EXPECT_GT(s.time_step, 0.0);
    });
  }
  EXPECT_GE(count, 8);
}

}  // namespace
}  // namespace bpm
