// The files `bpmkit generate` writes: particles.csv and bonds.csv and their binary twins (.bpk)
// load through bpm::load_scenario (the written scenario stub names the .bpk, a hand-written
// scenario the CSVs) and give back the same particles, bonds, radii and materials; the VTK file and the summary hold the right counts;
// a spec with the same seed writes byte-identical CSVs.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

#include "core/error.hpp"
#include "io/output_folder.hpp"
#include "scenario/scenario.hpp"
#include "structure/generate.hpp"
#include "structure/generate_spec.hpp"
#include "structure/structure_writer.hpp"
#include "structure_test_util.hpp"

namespace bpm {
namespace {

using test::TempDir;

const std::string kSpec = R"(seed: 5
container:
  cylinder: {radius: 0.5, height: 1.0}
radii:
  uniform: {min: 0.03, max: 0.05}
packing:
  porosity: 0.45
bonds:
  contact_radius_multiplier: 1.1
  radius_multiplier: 0.5
  materials: {soft: 0.3, stiff: 0.7}
)";

TEST(StructureOutput, CsvFilesLoadThroughLoadScenario) {
  TempDir dir;
  const GenerateSpec spec = load_generate_spec(dir.write("spec.yaml", kSpec));
  const GeneratedStructure g = generate_structure(spec);
  ASSERT_GT(g.bonds.size(), g.packing.size());
  const auto files = write_structure(spec, g, dir.path("out"));
  EXPECT_EQ(files.size(), 7u);  // particles and bonds as CSV and .bpk, VTK, stub, summary

  // 1. The stub (it names the binary tables, particles.bpk and bonds.bpk).
  const Scenario stub = load_scenario(dir.path("out/scenario.yaml"));
  ASSERT_EQ(stub.model.particles.size(), g.packing.size());
  ASSERT_EQ(stub.model.bonds.size(), g.bonds.size());
  // The scenario stores particles and bonds in its canonical order (model/spatial_order.hpp): the
  // particle ids are the generated indices, and each bond keeps its row in bonds.csv.
  const ParticleStore& p = stub.model.particles;
  for (std::size_t k = 0; k < g.packing.size(); ++k) {
    const auto i = static_cast<std::size_t>(p.id[k]);
    ASSERT_LT(i, g.packing.size());
    EXPECT_EQ(p.position[k], g.packing.position[i]);  // shortest round-trip text
    EXPECT_EQ(p.radius[k], g.packing.radius[i]);
  }
  ASSERT_EQ(stub.bond_material_names, (std::vector<std::string>{"soft", "stiff"}));
  const BondStore& bonds = stub.model.bonds;
  for (std::size_t k = 0; k < g.bonds.size(); ++k) {
    const auto b = static_cast<std::size_t>(bonds.input_row[k]);
    ASSERT_LT(b, g.bonds.size());
    EXPECT_EQ(p.id[static_cast<std::size_t>(bonds.alpha[k])], g.bonds[b].first);
    EXPECT_EQ(p.id[static_cast<std::size_t>(bonds.beta[k])], g.bonds[b].second);
    EXPECT_EQ(bonds.material[k], g.bond_material[b]);
    EXPECT_EQ(bonds.radius[k], g.bond_radius[b]);
    EXPECT_DOUBLE_EQ(g.bond_radius[b], 0.5 * std::min(g.packing.radius[static_cast<std::size_t>(g.bonds[b].first)],
                                                      g.packing.radius[static_cast<std::size_t>(g.bonds[b].second)]));
  }

  // 2. A hand-written scenario referencing the CSVs.
  const std::string scenario = dir.write("run.yaml", R"(particle_materials:
  glass: {density: 2500}
bond_materials:
  soft: {model: pbm, youngs_modulus: 1e8, poisson_ratio: 0.2}
  stiff: {model: tbbm, youngs_modulus: 4e8, poisson_ratio: 0.2}
particles:
  file: out/particles.csv
bonds:
  file: out/bonds.csv
stop:
  max_steps: 1
)");
  const Scenario run = load_scenario(scenario);
  EXPECT_EQ(run.model.particles.size(), g.packing.size());
  EXPECT_EQ(run.model.bonds.size(), g.bonds.size());
  EXPECT_GT(run.time_step, 0.0);
  // The CSV files and their binary twins give the same model, bit for bit.
  EXPECT_EQ(run.model.particles.id, p.id);
  EXPECT_EQ(run.model.particles.position, p.position);
  EXPECT_EQ(run.model.particles.radius, p.radius);
  EXPECT_EQ(run.model.bonds.alpha, bonds.alpha);
  EXPECT_EQ(run.model.bonds.beta, bonds.beta);
  EXPECT_EQ(run.model.bonds.radius, bonds.radius);
  EXPECT_EQ(run.model.bonds.material, bonds.material);
  EXPECT_EQ(run.model.bonds.input_row, bonds.input_row);

  // 3. VTK and summary.
  const std::string vtp = test::read_text(dir.path("out/structure.vtp"));
  EXPECT_NE(vtp.find("NumberOfPoints=\"" + std::to_string(g.packing.size()) + "\""), std::string::npos);
  EXPECT_NE(vtp.find("NumberOfLines=\"" + std::to_string(g.bonds.size()) + "\""), std::string::npos);
  const auto summary = nlohmann::json::parse(test::read_text(dir.path("out/summary.json")));
  EXPECT_EQ(summary["particles"], g.packing.size());
  EXPECT_EQ(summary["bonds"], g.bonds.size());
  EXPECT_EQ(summary["seed"], 5);
  EXPECT_DOUBLE_EQ(summary["porosity"].get<double>(), g.stats.porosity);
  EXPECT_NEAR(g.stats.porosity, 0.45, 2e-3);
  EXPECT_DOUBLE_EQ(summary["coordination_number"].get<double>(), 2.0 * static_cast<double>(g.bonds.size()) / static_cast<double>(g.packing.size()));
  EXPECT_LE(summary["max_overlap"].get<double>(), 0.01);
  EXPECT_TRUE(summary["relaxation_converged"].get<bool>());
  EXPECT_EQ(summary["bond_materials"]["soft"]["bonds"].get<std::size_t>() + summary["bond_materials"]["stiff"]["bonds"].get<std::size_t>(),
            g.bonds.size());
}

TEST(StructureOutput, SameSeedSameFilesOtherSeedOtherFiles) {
  TempDir dir;
  const GenerateSpec spec = load_generate_spec(dir.write("spec.yaml", kSpec));
  const GeneratedStructure a = generate_structure(spec), b = generate_structure(spec);
  EXPECT_EQ(particle_table_csv(particle_table(a.packing)), particle_table_csv(particle_table(b.packing)));
  EXPECT_EQ(bond_table_csv(bond_table(spec, a)), bond_table_csv(bond_table(spec, b)));
  GenerateSpec other = spec;
  other.seed = 6;
  const GeneratedStructure c = generate_structure(other);
  EXPECT_NE(particle_table_csv(particle_table(a.packing)), particle_table_csv(particle_table(c.packing)));
}

TEST(StructureOutput, NoBondsSectionGivesAnEmptyBondFileThatLoads) {
  TempDir dir;
  std::string text = kSpec.substr(0, kSpec.find("bonds:"));
  const GenerateSpec spec = load_generate_spec(dir.write("spec.yaml", text));
  const GeneratedStructure g = generate_structure(spec);
  EXPECT_TRUE(g.bonds.empty());
  write_structure(spec, g, dir.path("out"));
  // A bonds file without rows is refused, so the stub says "no bonds" with an empty list.
  EXPECT_NE(test::read_text(dir.path("out/scenario.yaml")).find("bonds: {list: []}"),
            std::string::npos);
  const Scenario stub = load_scenario(dir.path("out/scenario.yaml"));
  EXPECT_EQ(stub.model.particles.size(), g.packing.size());
  EXPECT_EQ(stub.model.bonds.size(), 0u);
}

TEST(StructureOutput, FilesAreWrittenAsOneSet) {
  TempDir dir;
  const GenerateSpec spec = load_generate_spec(dir.write("spec.yaml", kSpec));
  const GeneratedStructure g = generate_structure(spec);
  const std::string out = dir.path("out");
  write_structure(spec, g, out);
  EXPECT_FALSE(std::filesystem::exists(out + "/generate.tmp")) << "the staging folder is gone";
  // The second run's bonds.csv cannot be written (a folder stands in its staged place): the run
  // fails, and the particles it had written are not moved in beside no (or old) bonds.
  std::filesystem::create_directories(out + "/generate.tmp/bonds.csv");
  OutputFolder folder(out, "generate", structure_outputs(spec), true);
  EXPECT_THROW(folder.run([&] { return write_structure(spec, g, folder).second; }), InputError);
  for (const char* name : {"particles.csv", "bonds.csv", "structure.vtp", "scenario.yaml", "generate.tmp/particles.csv"}) {
    EXPECT_FALSE(std::filesystem::exists(out + "/" + name)) << name;
  }
  EXPECT_EQ(nlohmann::json::parse(test::read_text(out + "/summary.json"))["status"], "failed");
  // Once the write can succeed, the whole set arrives.
  std::filesystem::remove(out + "/generate.tmp/bonds.csv");
  OutputFolder again(out, "generate", structure_outputs(spec), true);
  again.run([&] { return write_structure(spec, g, again).second; });
  EXPECT_EQ(test::read_text(out + "/particles.csv"), particle_table_csv(particle_table(g.packing)));
  EXPECT_EQ(test::read_text(out + "/bonds.csv"), bond_table_csv(bond_table(spec, g)));
  EXPECT_FALSE(std::filesystem::exists(out + "/generate.tmp"));
}

/// The small examples in examples/02_generate generate what their READMEs promise.
TEST(StructureExamples, SmallBoxAndBicomponentAgglomerate) {
  const std::string folder = std::string(BPMKIT_EXAMPLES_DIR) + "/02_generate/";
  {
    const GeneratedStructure g = generate_structure(load_generate_spec(folder + "small_box.yml"));
    EXPECT_TRUE(g.relaxation.converged);
    EXPECT_NEAR(g.stats.porosity, 0.45, 2e-3);
  }
  {
    const GenerateSpec spec = load_generate_spec(folder + "agglomerate_bicomponent.yml");
    const GeneratedStructure g = generate_structure(spec);
    EXPECT_EQ(g.packing.size(), 6000u);
    EXPECT_NEAR(static_cast<double>(g.bonds.size()), 29000.0, 1500.0);  // Jarolin case 2: 6e3 particles, 2.9e4 bonds
    ASSERT_EQ(spec.bond_materials.size(), 2u);
    const auto soft = static_cast<double>(std::count(g.bond_material.begin(), g.bond_material.end(), 0));
    const double n = static_cast<double>(g.bonds.size());
    EXPECT_NEAR(soft, 0.4 * n, 4.0 * std::sqrt(n * 0.4 * 0.6));
  }
}

}  // namespace
}  // namespace bpm
