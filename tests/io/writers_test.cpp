// The result writers: the files a run produces exist and parse (CSV columns and rows, JSON via
// nlohmann, VTK XML well-formed with the right number of points and cells), and their values are
// the model's.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <numbers>
#include <regex>
#include <string>
#include <vector>

#include "scenario/probe_recorder.hpp"
#include "scenario/scenario.hpp"
#include "scenario/scenario_run.hpp"
#include "io/state_csv.hpp"
#include "io/vtk_writer.hpp"
#include "io_test_util.hpp"
#include "vtk_test_reader.hpp"

namespace bpm {
namespace {

using test::kGoodScenario;
using test::read_lines;
using test::read_text;
using test::TempDir;

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (true) {
    const auto comma = line.find(',', start);
    out.push_back(line.substr(start, comma - start));
    if (comma == std::string::npos) return out;
    start = comma + 1;
  }
}

/// Checks that every tag opens and closes in order (a small XML well-formedness check, enough for
/// the files we write: no CDATA, comments or '>' inside attribute values).
::testing::AssertionResult well_formed_xml(const std::string& xml) {
  std::vector<std::string> open;
  const std::regex tag(R"(<(/?)([A-Za-z_][\w.-]*)[^>]*?(/?)>)");
  std::size_t tags = 0;
  for (auto it = std::sregex_iterator(xml.begin(), xml.end(), tag); it != std::sregex_iterator(); ++it) {
    ++tags;
    const std::string name = (*it)[2];
    if ((*it)[1] == "/") {
      if (open.empty() || open.back() != name) return ::testing::AssertionFailure() << "unexpected </" << name << ">";
      open.pop_back();
    } else if ((*it)[3] != "/") {
      open.push_back(name);
    }
  }
  if (!open.empty()) return ::testing::AssertionFailure() << "<" << open.back() << "> is never closed";
  if (tags == 0) return ::testing::AssertionFailure() << "no tags";
  return ::testing::AssertionSuccess();
}

/// The values of the first array named `name` (ASCII or appended zlib), as doubles.
std::vector<double> data_array(const std::string& vtp, const std::string& name) {
  return test::vtk_numbers(vtp, name);
}

std::string attribute(const std::string& file, const std::string& name) {
  std::smatch m;
  const std::string xml = test::vtk_xml(file);  // not the appended bytes
  if (!std::regex_search(xml, m, std::regex(name + "=\"([^\"]*)\""))) return {};
  return m[1];
}

TEST(ScenarioOutput, RunWritesAllFiles) {
  TempDir dir;
  Scenario s = load_scenario(dir.write("scenario.yaml", kGoodScenario));
  const std::string out = dir.path("out");
  const ScenarioRunResult r = run_scenario(s, out);
  EXPECT_EQ(r.summary.reason, StopReason::max_steps);
  EXPECT_EQ(r.summary.steps, 200);
  // Outputs at steps 0, 50, 100, 150, 200 (the final call at step 200 is not repeated).
  EXPECT_EQ(r.frames, 5u);
  for (const auto& f : r.files) EXPECT_TRUE(std::filesystem::is_regular_file(f)) << f;

  // summary.json
  const auto summary = nlohmann::json::parse(read_text(out + "/summary.json"));
  EXPECT_EQ(summary["steps"], 200);
  EXPECT_EQ(summary["stop_reason"], "max_steps");
  EXPECT_EQ(summary["particles"], 3);
  EXPECT_EQ(summary["bonds"], 2);
  EXPECT_DOUBLE_EQ(summary["time_step_s"].get<double>(), s.time_step);
  EXPECT_DOUBLE_EQ(summary["critical_time_step_s"].get<double>(), s.time_step_limit);
  EXPECT_NEAR(summary["simulated_time_s"].get<double>(), 200 * s.time_step, 1e-12);
  EXPECT_GT(summary["energies"]["elastic_J"].get<double>(), 0.0);
  EXPECT_GE(summary["energies"]["kinetic_J"].get<double>(), 0.0);
  EXPECT_GE(summary["wall_s"].get<double>(), 0.0);
  EXPECT_TRUE(summary["bond_updates_per_second"].is_number());
  EXPECT_EQ(summary["vtk_frames"], 5);
  EXPECT_EQ(summary["outputs"].size(), 4u);  // final_state.csv, probes.csv, frames.pvd, summary.json

  // final_state.csv: header + one row per particle, 19 columns, displacement = position - reference.
  const auto state = read_lines(out + "/final_state.csv");
  ASSERT_EQ(state.size(), 4u);
  EXPECT_EQ(state[0], "id,x,y,z,ux,uy,uz,rx,ry,rz,vx,vy,vz,wx,wy,wz,fx,fy,fz");
  const auto tip = split(state[3]);
  ASSERT_EQ(tip.size(), 19u);
  EXPECT_EQ(tip[0], "2");
  EXPECT_DOUBLE_EQ(std::stod(tip[5]), s.model.particles.position[2].y - s.model.particles.reference_position[2].y);
  EXPECT_LT(std::stod(tip[5]), 0.0);  // pushed down

  // probes.csv: header + 5 rows of time + 9 columns.
  const auto probes = read_lines(out + "/probes.csv");
  ASSERT_EQ(probes.size(), 6u);
  EXPECT_EQ(split(probes[0]).size(), 10u);
  EXPECT_EQ(split(probes[0])[2], "tip_uy");
  EXPECT_EQ(split(probes[1])[0], "0");
  EXPECT_NEAR(std::stod(split(probes[5])[2]), std::stod(tip[5]), 1e-10 * std::abs(std::stod(tip[5])));  // 12 digits

  // frames.pvd lists the 5 frames with increasing times; each frame is well-formed.
  const std::string pvd = read_text(out + "/frames.pvd");
  EXPECT_TRUE(well_formed_xml(pvd));
  const std::regex dataset(R"re(<DataSet timestep="([^"]+)"[^>]*file="([^"]+)")re");
  std::vector<double> times;
  for (auto it = std::sregex_iterator(pvd.begin(), pvd.end(), dataset); it != std::sregex_iterator(); ++it) {
    times.push_back(std::stod((*it)[1]));
    const std::string vtp = read_text(out + "/" + std::string((*it)[2]));
    EXPECT_TRUE(well_formed_xml(test::vtk_xml(vtp))) << (*it)[2];
    EXPECT_EQ(attribute(vtp, "NumberOfPoints"), "3");
    EXPECT_EQ(attribute(vtp, "NumberOfLines"), "2");
    EXPECT_EQ(data_array(vtp, "position").size(), 9u);
    EXPECT_EQ(data_array(vtp, "radius").size(), 3u);
    EXPECT_EQ(data_array(vtp, "connectivity").size(), 4u);
    EXPECT_EQ(data_array(vtp, "axial_force").size(), 2u);
  }
  ASSERT_EQ(times.size(), 5u);
  EXPECT_TRUE(std::is_sorted(times.begin(), times.end()));
  EXPECT_DOUBLE_EQ(times.front(), 0.0);
}

/// output.bond_csv: a file per output time, every bond in input order, the last one the model's
/// bond loads exactly (shortest round-trip numbers).
TEST(ScenarioOutput, BondCsvAtEveryOutput) {
  TempDir dir;
  std::string text = kGoodScenario;
  test::replace_once(text, "  every_steps: 50\n", "  every_steps: 50\n  bond_csv: true\n");
  Scenario s = load_scenario(dir.write("scenario.yaml", text));
  const std::string out = dir.path("out");
  run_scenario(s, out);
  for (int k = 0; k < 5; ++k) {
    EXPECT_TRUE(std::filesystem::is_regular_file(out + "/bonds/bonds_00000" + std::to_string(k) + ".csv")) << k;
  }
  EXPECT_FALSE(std::filesystem::exists(out + "/bonds/bonds_000005.csv"));
  const auto rows = read_lines(out + "/bonds/bonds_000004.csv");
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0], "bond,i,j,intact,axial_force,force_x,force_y,force_z,moment_x,moment_y,moment_z");
  const BondStore& b = s.model.bonds;
  for (std::size_t r = 1; r < rows.size(); ++r) {
    const auto f = split(rows[r]);
    ASSERT_EQ(f.size(), 11u);
    EXPECT_EQ(f[0], std::to_string(r - 1));  // input order
    std::size_t k = 0;
    while (b.input_row[k] != static_cast<std::int32_t>(r - 1)) ++k;
    EXPECT_EQ(std::stoll(f[1]), s.model.particles.id[b.alpha[k]]);
    EXPECT_EQ(f[3], "1");
    EXPECT_EQ(std::stod(f[4]), dot(b.force[k], b.axis[k]));
    EXPECT_EQ(std::stod(f[6]), b.force[k].y);
    EXPECT_EQ(std::stod(f[10]), b.moment[k].z);
    EXPECT_NE(b.force[k].y, 0.0);  // the loaded cantilever's bonds carry shear
  }
  const auto summary = nlohmann::json::parse(read_text(out + "/summary.json"));
  const auto owned = summary["owned_files"].get<std::vector<std::string>>();
  EXPECT_NE(std::find(owned.begin(), owned.end(), "bonds/bonds_*.csv"), owned.end());
}

TEST(ScenarioOutput, StateCsvDisplacementAndRotation) {
  ParticleStore p;
  p.add(42, {1, 2, 3}, 0.5, 1000.0);
  p.position[0] = {1.5, 2, 2};
  const double angle = 0.3;  // about z
  p.orientation[0] = {std::cos(angle / 2), 0, 0, std::sin(angle / 2)};
  p.velocity[0] = {0, 1, 0};
  p.force[0] = {0, 0, -7};
  const auto lines = [&] {
    std::vector<std::string> out;
    std::istringstream in(state_csv(p));
    for (std::string l; std::getline(in, l);) out.push_back(l);
    return out;
  }();
  ASSERT_EQ(lines.size(), 2u);
  const auto f = split(lines[1]);
  ASSERT_EQ(f.size(), 19u);
  EXPECT_EQ(f[0], "42");
  EXPECT_DOUBLE_EQ(std::stod(f[4]), 0.5);   // ux
  EXPECT_DOUBLE_EQ(std::stod(f[6]), -1.0);  // uz
  EXPECT_NEAR(std::stod(f[9]), angle, 1e-15);  // rz
  EXPECT_DOUBLE_EQ(std::stod(f[11]), 1.0);  // vy
  EXPECT_DOUBLE_EQ(std::stod(f[18]), -7.0);  // fz
}

TEST(ScenarioOutput, ProbeMeansAndSums) {
  ParticleStore p;
  p.add(0, {0, 0, 0}, 0.1, 1000.0);
  p.add(1, {1, 0, 0}, 0.1, 1000.0);
  p.position[0] = {0.2, 0, 0};
  p.position[1] = {1.4, 0, 0};
  p.velocity[1] = {2, 0, 0};
  p.force[0] = {1, 2, 3};
  p.force[1] = {1, 2, 3};
  ProbeRecorder rec({{"pair", {0, 1}}});
  std::istringstream in(rec.header() + rec.row(0.5, p));
  std::string header, row;
  std::getline(in, header);
  std::getline(in, row);
  EXPECT_EQ(header, "time,pair_ux,pair_uy,pair_uz,pair_vx,pair_vy,pair_vz,pair_fx,pair_fy,pair_fz");
  EXPECT_EQ(row, "0.5,0.3,0,0,1,0,0,2,4,6");
}

TEST(ScenarioOutput, VtpBondFieldsAndEmptyModel) {
  Model m;
  m.particles.add(0, {0, 0, 0}, 0.2, 1000.0);
  m.particles.add(1, {0.4, 0, 0}, 0.2, 1000.0);
  m.bonds.add(0, 1, {{1e9, 1e8, 1e6, 1e6}, 0.0}, 0.2, 0.4);
  m.finalize();
  m.bonds.force[0] = {5, 1, 0};  // pulls alpha towards beta: tension
  m.bonds.moment[0] = {0, 0, 3};
  const std::string vtp = polydata_vtp(m);
  EXPECT_TRUE(well_formed_xml(test::vtk_xml(vtp)));
  EXPECT_EQ(data_array(vtp, "axial_force"), std::vector<double>{5});
  EXPECT_EQ(data_array(vtp, "moment"), (std::vector<double>{0, 0, 3}));
  EXPECT_EQ(data_array(vtp, "offsets"), std::vector<double>{2});

  const std::string empty = polydata_vtp(Model{});
  EXPECT_TRUE(well_formed_xml(test::vtk_xml(empty)));
  EXPECT_EQ(attribute(empty, "NumberOfPoints"), "0");
  EXPECT_TRUE(well_formed_xml(collection_pvd({})));
}

}  // namespace
}  // namespace bpm
