// The binary structure tables (io/structure_table.hpp): every value comes back bit for bit, a
// scenario loads the same model from them as from the CSV files, and a damaged, cut, foreign or
// mismatched file is refused with a message that names the file and the cause.
#include "io/structure_table.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "scenario/scenario.hpp"
#include "io_test_util.hpp"

namespace bpm {
namespace {

using test::expect_contains;
using test::TempDir;

/// Values a text round trip could get wrong: subnormals, -0, the extremes of int64.
ParticleTable awkward_particles() {
  ParticleTable t;
  t.id = {0, -7, std::numeric_limits<std::int64_t>::max(), std::numeric_limits<std::int64_t>::min()};
  t.position = {{0.1, -0.0, 1e-310}, {1.0 / 3.0, 2e300, -5e-324}, {1, 2, 3}, {-1, -2, -3}};
  t.radius = {0.2, std::nextafter(0.2, 1.0), 1e-9, 3.0};
  t.material_names = {"grain", "steel"};
  t.material = {1, 0, 0, 1};
  return t;
}

std::string bytes_of(const ParticleTable& t) { return particle_table_bytes(t); }

TEST(StructureTable, ParticlesComeBackBitForBit) {
  TempDir dir;
  const ParticleTable t = awkward_particles();
  const ParticleTable back = read_particle_table(dir.write("p.bpk", bytes_of(t)));
  EXPECT_EQ(back.id, t.id);
  ASSERT_EQ(back.position.size(), t.position.size());
  for (std::size_t k = 0; k < t.position.size(); ++k) {
    EXPECT_EQ(std::signbit(back.position[k].y), std::signbit(t.position[k].y));
    EXPECT_EQ(back.position[k], t.position[k]);
  }
  EXPECT_EQ(back.radius, t.radius);
  EXPECT_EQ(back.material_names, t.material_names);
  EXPECT_EQ(back.material, t.material);
}

TEST(StructureTable, BondsComeBackWithAndWithoutOptionalColumns) {
  TempDir dir;
  BondTable t;
  t.i = {0, 1, 5};
  t.j = {1, 2, 9};
  t.radius = {0.1, 0.2, 0.3};
  t.material_names = {"a", "b"};
  t.material = {0, 1, 1};
  const BondTable back = read_bond_table(dir.write("b.bpk", bond_table_bytes(t)));
  EXPECT_EQ(back.i, t.i);
  EXPECT_EQ(back.j, t.j);
  EXPECT_EQ(back.radius, t.radius);
  EXPECT_EQ(back.material_names, t.material_names);
  EXPECT_EQ(back.material, t.material);

  BondTable bare;
  bare.i = {3};
  bare.j = {4};
  const BondTable bare_back = read_bond_table(dir.write("bare.bpk", bond_table_bytes(bare)));
  EXPECT_EQ(bare_back.i, bare.i);
  EXPECT_TRUE(bare_back.radius.empty());
  EXPECT_TRUE(bare_back.material.empty());
}

TEST(StructureTable, EmptyTablesComeBackEmpty) {
  // libFuzzer's first CI run: zero rows once reached memcpy with a null destination (UBSan).
  TempDir dir;
  ParticleTable none;
  none.material_names = {"grain"};
  const ParticleTable back = read_particle_table(dir.write("none.bpk", bytes_of(none)));
  EXPECT_TRUE(back.id.empty());
  EXPECT_TRUE(back.position.empty());
  EXPECT_TRUE(back.material.empty());
  EXPECT_EQ(back.material_names, none.material_names);
  EXPECT_TRUE(read_bond_table(dir.write("none_b.bpk", bond_table_bytes(BondTable{}))).i.empty());
}

/// The message of the InputError `read` raises.
template <class Read>
std::string error_of(Read read) {
  try {
    read();
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an InputError";
  return {};
}

TEST(StructureTable, DamagedCutForeignAndMismatchedFilesAreRefused) {
  TempDir dir;
  const std::string good = bytes_of(awkward_particles());
  std::string flipped = good;
  flipped[40] = static_cast<char>(flipped[40] ^ 0x10);
  const std::string f = dir.write("flipped.bpk", flipped);
  expect_contains(error_of([&] { read_particle_table(f); }), {f, "checksum mismatch"});
  const std::string cut = dir.write("cut.bpk", good.substr(0, good.size() / 2));
  expect_contains(error_of([&] { read_particle_table(cut); }), {cut, "checksum mismatch"});
  const std::string tiny = dir.write("tiny.bpk", good.substr(0, 10));
  expect_contains(error_of([&] { read_particle_table(tiny); }), {tiny, "not a bpmkit structure table"});
  const std::string csv = dir.write("p.csv", "id,x,y,z,radius\n0,0,0,0,1\n");
  EXPECT_FALSE(is_structure_table(csv));
  EXPECT_TRUE(is_structure_table(dir.write("good.bpk", good)));
  const std::string bonds = dir.write("bonds.bpk", bond_table_bytes(BondTable{{0}, {1}, {}, {}, {}}));
  expect_contains(error_of([&] { read_particle_table(bonds); }), {bonds, "a bonds table where particles are expected"});
  EXPECT_FALSE(is_structure_table(dir.path("missing.bpk")));
}

TEST(StructureTable, ScenarioLoadsTheSameModelFromTablesAsFromCsv) {
  TempDir dir;
  dir.write("p.csv", "id,x,y,z,radius,material\n10,0,0,0,0.2,grain\n11,0.4,0,0,0.2,grain\n12,0.8,0,0.01,0.2,rock\n");
  dir.write("b.csv", "i,j,radius,material\n10,11,0.1,beam\n12,11,0.15,beam\n");
  ParticleTable p;
  p.id = {10, 11, 12};
  p.position = {{0, 0, 0}, {0.4, 0, 0}, {0.8, 0, 0.01}};
  p.radius = {0.2, 0.2, 0.2};
  p.material_names = {"grain", "rock"};
  p.material = {0, 0, 1};
  dir.write("p.bpk", particle_table_bytes(p));
  dir.write("b.bpk", bond_table_bytes(BondTable{{10, 12}, {11, 11}, {0.1, 0.15}, {"beam"}, {0, 0}}));
  const std::string head = R"(particle_materials:
  grain: {density: 2500}
  rock: {density: 2700}
bond_materials:
  beam: {model: tbbm, youngs_modulus: 1e9, poisson_ratio: 0.3}
stop:
  max_steps: 1
)";
  const Scenario csv = load_scenario(dir.write("csv.yaml", head + "particles: {file: p.csv}\nbonds: {file: b.csv}\n"));
  const Scenario bin = load_scenario(dir.write("bin.yaml", head + "particles: {file: p.bpk}\nbonds: {file: b.bpk}\n"));
  EXPECT_EQ(bin.model.particles.id, csv.model.particles.id);
  EXPECT_EQ(bin.model.particles.position, csv.model.particles.position);
  EXPECT_EQ(bin.model.particles.material, csv.model.particles.material);
  EXPECT_EQ(bin.model.bonds.alpha, csv.model.bonds.alpha);
  EXPECT_EQ(bin.model.bonds.beta, csv.model.bonds.beta);
  EXPECT_EQ(bin.model.bonds.radius, csv.model.bonds.radius);
  EXPECT_EQ(bin.time_step, csv.time_step);

  // What the CSV reader refuses row by row, the table reader refuses with the row.
  p.material_names = {"grain", "granite"};
  dir.write("p2.bpk", particle_table_bytes(p));
  expect_contains(test::load_error(dir.write("bad_mat.yaml", head + "particles: {file: p2.bpk}\nbonds: {file: b.bpk}\n")),
                  {"p2.bpk, row 3", "unknown material 'granite'", "rock"});
  dir.write("b2.bpk", bond_table_bytes(BondTable{{10, 11}, {11, 10}, {}, {"beam"}, {0, 0}}));
  expect_contains(test::load_error(dir.write("dup.yaml", head + "particles: {file: p.bpk}\nbonds: {file: b2.bpk}\n")),
                  {"b2.bpk, row 2", "duplicate bond 11-10"});
  dir.write("b3.bpk", bond_table_bytes(BondTable{{10}, {11}, {-0.1}, {"beam"}, {0}}));
  expect_contains(test::load_error(dir.write("neg.yaml", head + "particles: {file: p.bpk}\nbonds: {file: b3.bpk}\n")),
                  {"b3.bpk, row 1", "bond radius -0.1 must be greater than 0"});
  expect_contains(test::load_error(dir.write("swap.yaml", head + "particles: {file: b.bpk}\nbonds: {file: b.bpk}\n")),
                  {"b.bpk", "a bonds table where particles are expected"});
}

}  // namespace
}  // namespace bpm
