// The canonical order at load (model/spatial_order.hpp, issue 12): a scenario whose particle rows
// and bond rows are shuffled runs exactly as the unshuffled one (final_state.csv, summary.json
// apart from its times, the tables and the VTK frames byte for byte), with bonds breaking and
// contacts acting; bond_breaks.csv names each bond by its row in the file the user gave; and
// everything the scenario names by id (constraints, loads, probes, bond ends) still finds its
// particle.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "io_test_util.hpp"
#include "resume_scenario.hpp"
#include "scenario/scenario_run.hpp"

namespace bpm {
namespace {

using test::TempDir;

using IdPair = std::pair<std::int64_t, std::int64_t>;

/// The lines of `text` without the lines that hold one of `keys` (summary.json: one key a line).
std::string without_lines(const std::string& text, const std::vector<std::string>& keys) {
  std::istringstream in(text);
  std::string kept;
  for (std::string line; std::getline(in, line);) {
    const bool drop = std::any_of(keys.begin(), keys.end(), [&](const std::string& key) {
      return line.find("\"" + key + "\":") != std::string::npos;
    });
    if (!drop) kept += line + "\n";
  }
  return kept;
}

std::string bonds_csv(const std::vector<IdPair>& bonds) {
  std::string csv = "i,j\n";
  for (const auto& [i, j] : bonds) csv += std::to_string(i) + "," + std::to_string(j) + "\n";
  return csv;
}

/// Runs the scenario into tmp/run, then moves that folder to tmp/`name`: both runs write into the
/// same folder, so that summary.json names the same files.
ScenarioRunResult run_as(const TempDir& tmp, const std::string& scenario_path,
                         const std::string& name) {
  Scenario scenario = load_scenario(scenario_path);
  ScenarioRunResult result = run_scenario(scenario, tmp.path("run"));
  std::filesystem::rename(tmp.path("run"), tmp.path(name));
  return result;
}

/// The result files compared byte for byte: the tables and every VTK frame.
std::vector<std::string> compared_files(const std::string& dir) {
  std::vector<std::string> names{"final_state.csv", "probes.csv", "walls.csv", "frames.pvd"};
  for (const auto& e : std::filesystem::directory_iterator(dir + "/frames")) {
    names.push_back("frames/" + e.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

TEST(CanonicalOrderRun, ShuffledRowsGiveTheSameRun) {
  TempDir tmp;
  test::ResumeScenario s;
  s.max_steps = 120;
  s.every_steps = 20;
  const std::string path = test::write_resume_scenario(tmp, s);
  // The bonds `auto` finds, as explicit rows (by id), so that their rows can be shuffled too.
  std::vector<IdPair> bonds;
  {
    const Scenario found = load_scenario(path);
    const ParticleStore& p = found.model.particles;
    for (std::size_t k = 0; k < found.model.bonds.size(); ++k) {
      bonds.emplace_back(p.id[found.model.bonds.alpha[k]], p.id[found.model.bonds.beta[k]]);
    }
  }
  std::string yaml = test::read_text(path);
  test::replace_once(yaml, "auto: {max_gap: 1e-4}", "file: bonds.csv");
  tmp.write("scenario.yaml", yaml);
  tmp.write("bonds.csv", bonds_csv(bonds));
  const ScenarioRunResult ordered = run_as(tmp, path, "ordered");

  // Particle rows (below the header) and bond rows in a random order; each bond keeps its ends.
  std::vector<std::string> particle_rows = test::read_lines(tmp.path("particles.csv"));
  const std::string header = particle_rows.front();
  particle_rows.erase(particle_rows.begin());
  std::mt19937_64 rng(2024);
  std::shuffle(particle_rows.begin(), particle_rows.end(), rng);
  std::string particles_csv = header + "\n";
  for (const std::string& row : particle_rows) particles_csv += row + "\n";
  std::vector<std::size_t> row_of(bonds.size());  // row_of[ordered row] = shuffled row
  std::vector<std::size_t> order(bonds.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::shuffle(order.begin(), order.end(), rng);
  std::vector<IdPair> shuffled_bonds;
  for (const std::size_t k : order) {
    row_of[k] = shuffled_bonds.size();
    shuffled_bonds.push_back(bonds[k]);
  }
  tmp.write("particles.csv", particles_csv);
  tmp.write("bonds.csv", bonds_csv(shuffled_bonds));
  run_as(tmp, path, "shuffled");

  // The comparison means something only if bonds broke and contacts acted.
  const std::vector<std::string> breaks = test::read_lines(tmp.path("ordered/bond_breaks.csv"));
  ASSERT_GT(breaks.size(), 4u);
  EXPECT_GT(ordered.energies.contact, 0.0);

  const std::vector<std::string> names = compared_files(tmp.path("ordered"));
  EXPECT_EQ(names, compared_files(tmp.path("shuffled")));
  EXPECT_GT(names.size(), 6u);
  for (const std::string& name : names) {
    const std::string expected = test::read_text(tmp.path("ordered/" + name));
    ASSERT_FALSE(expected.empty()) << name;
    EXPECT_TRUE(expected == test::read_text(tmp.path("shuffled/" + name))) << name << " differs";
  }
  const std::string summary = test::read_text(tmp.path("ordered/summary.json"));
  const std::vector<std::string> times{"wall_s", "bond_updates_per_second", "started", "ended"};
  EXPECT_EQ(without_lines(summary, times),
            without_lines(test::read_text(tmp.path("shuffled/summary.json")), times));

  // bond_breaks.csv: the same breaks in the same order; its `bond` column is the row in each file.
  const std::vector<std::string> shuffled_breaks =
      test::read_lines(tmp.path("shuffled/bond_breaks.csv"));
  ASSERT_EQ(shuffled_breaks.size(), breaks.size());
  EXPECT_EQ(shuffled_breaks.front(), breaks.front());
  for (std::size_t line = 1; line < breaks.size(); ++line) {
    const std::size_t comma = breaks[line].find(',');
    const std::size_t row = std::stoul(breaks[line].substr(0, comma));
    EXPECT_EQ(shuffled_breaks[line], std::to_string(row_of[row]) + breaks[line].substr(comma));
    // And that row of the file is the pair the line names.
    const std::string pair =
        std::to_string(bonds[row].first) + "," + std::to_string(bonds[row].second) + ",";
    EXPECT_EQ(breaks[line].compare(comma + 1, pair.size(), pair), 0) << breaks[line];
  }
}

TEST(CanonicalOrderRun, IdsStillNameTheirParticles) {
  // Ids neither in row order nor row numbers; the bonds given against the canonical order.
  TempDir tmp;
  std::string yaml = test::kGoodScenario;
  test::replace_once(yaml,
                     "    - {id: 0, position: [0, 0, 0], radius: 0.2}\n"
                     "    - {id: 1, position: [0.4, 0, 0], radius: 0.2}\n"
                     "    - {id: 2, position: [0.8, 0, 0], radius: 0.2}\n",
                     "    - {id: 7, position: [0.8, 0, 0], radius: 0.2}\n"
                     "    - {id: 3, position: [0, 0, 0], radius: 0.2}\n"
                     "    - {id: 5, position: [0.4, 0, 0], radius: 0.2}\n");
  test::replace_once(yaml, "list: [[0, 1], [1, 2]]", "list: [[7, 5], [3, 5]]");
  test::replace_once(yaml, "  - particles: [0]\n    fix: all", "  - particles: [3]\n    fix: all");
  test::replace_once(yaml, "  - particles: [2]\n    force", "  - particles: [7]\n    force");
  test::replace_once(yaml, "{name: tip, particles: [2]}", "{name: tip, particles: [7]}");
  const Scenario s = load_scenario(tmp.write("scenario.yaml", yaml));
  const ParticleStore& p = s.model.particles;
  EXPECT_EQ(p.id, (std::vector<std::int64_t>{3, 5, 7}));  // along x, the Morton order here
  EXPECT_EQ(p.position[2], (Vec3{0.8, 0, 0}));
  EXPECT_EQ(p.translation_free[0], (Vec3{0, 0, 0}));
  EXPECT_EQ(p.translation_free[2], (Vec3{1, 1, 1}));
  ASSERT_EQ(s.model.loads.size(), 1u);
  EXPECT_EQ(s.model.loads[0].particles, (std::vector<std::int32_t>{2}));
  ASSERT_EQ(s.probes.size(), 1u);
  EXPECT_EQ(s.probes[0].particles, (std::vector<std::int32_t>{2}));
  // Bonds sorted by their lower (canonical) particle, each as given (alpha = i), with its row.
  const BondStore& b = s.model.bonds;
  EXPECT_EQ(b.alpha, (std::vector<std::int32_t>{0, 2}));
  EXPECT_EQ(b.beta, (std::vector<std::int32_t>{1, 1}));
  EXPECT_EQ(b.input_row, (std::vector<std::int32_t>{1, 0}));
}

}  // namespace
}  // namespace bpm
