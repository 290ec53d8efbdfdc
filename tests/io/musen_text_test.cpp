// MUSEN's text import/export format (io/musen_text.hpp): bpmkit -> MUSEN -> bpmkit keeps ids,
// centres, radii and r_b bit for bit and says what the file cannot hold; a file laid out as
// MUSEN's ExportAsText writes it (every field selected, two time points, a wall, scene and
// material lines) reads to its spheres and solid bonds at the first time point and lists the
// rest; malformed files are refused naming the file and line; `bpmkit convert` tells a MUSEN file
// from a LAMMPS data file and converts both ways.
#include <fmt/core.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <bit>
#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "bpmkit_process.hpp"
#include "common/exchange_structures.hpp"
#include "common/test_files.hpp"
#include "core/error.hpp"
#include "io/musen_text.hpp"
#include "io/structure_exchange.hpp"

namespace bpm {
namespace {

using test::awkward_structure;
using test::expect_bitwise;
using test::expect_same_structure;
using test::message_of;
using test::TempDir;

std::string joined(const std::vector<std::string>& list) {
  std::string all;
  for (const std::string& d : list) all += d + "; ";
  return all;
}

std::vector<std::string> names_of(const std::vector<std::string>& names,
                                  const std::vector<std::uint32_t>& material) {
  std::vector<std::string> out;
  for (const std::uint32_t m : material) out.push_back(names[m]);
  return out;
}

TEST(MusenText, RoundTripKeepsIdsCentresRadiiAndBondsBitForBit) {
  TempDir dir;
  const ExchangeStructure s = awkward_structure();
  const ExchangeFiles files = musen_structure_files(s);
  ASSERT_EQ(files.files.size(), 1u);
  EXPECT_EQ(files.files[0].first, "musen.txt");
  const std::string path = dir.write("musen.txt", files.files[0].second);
  std::vector<std::string> read_dropped{"stale"};
  const ExchangeStructure back = read_musen_structure(path, &read_dropped);

  // The same structure, bit for bit, with the materials by name; the space, which a compound key
  // cannot hold, becomes '_'.
  ExchangeStructure expected = s;
  expected.particles.material_names = {"grain", "steel_plate"};
  expect_same_structure(back, expected, /*densities=*/false);
  EXPECT_TRUE(back.density.empty());

  // What the file could not hold is said on writing; reading our own file drops nothing.
  const std::string dropped = joined(files.dropped);
  EXPECT_NE(dropped.find("densities"), std::string::npos) << dropped;
  EXPECT_NE(dropped.find("'steel plate' as 'steel_plate'"), std::string::npos) << dropped;
  EXPECT_EQ(files.dropped.size(), 2u) << dropped;
  EXPECT_TRUE(read_dropped.empty()) << joined(read_dropped);
}

/// The lines as MUSEN's ExportAsText lays them out, for our own writer: pins the layout.
TEST(MusenText, WritesMusensObjectLines) {
  const std::string text = musen_structure_files(awkward_structure()).files[0].second;
  // Sphere 7: id, type 1, radius and contact radius, compound key, activity, time 0, centre,
  // identity orientation.
  EXPECT_NE(text.find("0 7 1 1 5 0.2 0.2 23 steel_plate 24 0 1e+300 2 0 12 0.1 -0 1e-310 "
                      "31 1 0 0 0\n"),
            std::string::npos)
      << text;
  // Bond 7-0: the first id after the largest particle id (12), type 9, the particle ids, the
  // diameter 2 r_b, the initial length |x_0 - x_7|, compound key, activity.
  const double length = norm(Vec3{1.0 / 3.0, -2.5e-3, 5e-324} - Vec3{0.1, -0.0, 1e-310});
  EXPECT_NE(text.find(fmt::format("0 13 1 9 5 7 0 0.2 {} 23 cement 24 0 1e+300\n", length)),
            std::string::npos)
      << text;
  EXPECT_EQ(text.find("0 16 "), std::string::npos) << "3 bonds: ids 13, 14, 15\n" << text;
}

TEST(MusenText, WithoutBondRadiiOrWithIdsMusenCannotHoldSaysSo) {
  TempDir dir;
  ExchangeStructure s = awkward_structure();
  s.bonds.radius.clear();
  s.particles.id = {7, -1, 3, 12};  // MUSEN's ids are unsigned
  s.bonds.i = {7, -1, 12};
  s.bonds.j = {-1, 3, 3};
  const ExchangeFiles files = musen_structure_files(s);
  const std::string dropped = joined(files.dropped);
  EXPECT_NE(dropped.find("particle ids"), std::string::npos) << dropped;
  EXPECT_NE(dropped.find("bond radii"), std::string::npos) << dropped;
  const ExchangeStructure back = read_musen_structure(dir.write("m.txt", files.files[0].second));
  EXPECT_EQ(back.particles.id, (std::vector<std::int64_t>{0, 1, 2, 3}));  // rows
  EXPECT_EQ(back.bonds.i, (std::vector<std::int64_t>{0, 1, 3}));
  EXPECT_EQ(back.bonds.j, (std::vector<std::int64_t>{1, 2, 2}));
  // r_b = min(R_i, R_j), the scenario's default.
  expect_bitwise(back.bonds.radius[0], 0.2, "r_b 7-0");
  expect_bitwise(back.bonds.radius[1], 1e-9, "r_b 0-3");
}

/// Three spheres, two solid bonds and a wall as MUSEN's ExportAsText writes them with every
/// field selected (trailing spaces, CRLF line ends, two time points), then the scene,
/// geometry and material lines. Sphere line: 0 ID 1 1 5 R R_C 23 KEY 24 START END, then per time
/// point 2 T 16 ANGVEL 12 COORD 20 FORCE 18 |F| 31 Q 42 PRINCIPAL 36 TENSOR 37 TEMP 15 VEL.
/// Bond: 0 ID 1 9 5 LEFT RIGHT D L 23 KEY 24 START END, then 2 T 12 COORD 20 FORCE 18 |F|
/// 45 TANG_OVERLAP 37 TEMP 43 TORQUE 15 VEL. Wall: 5 with no geometry, 44 with its 3 vertices.
const char* const kMusenExport =
    "0 0 1 1 5 0.001 0.001 23 QUARTZ 24 0 1e+300 "
    "2 0 16 0 0 0 12 0 0 0 20 0 0 0 18 0 31 1 0 0 0 42 0 0 0 36 0 0 0 0 0 0 0 0 0 37 0 15 0 0 0 "
    "2 0.5 16 0 0 0 12 0 0 -0.001 20 0 0 -0.1 18 0.1 31 1 0 0 0 42 0 0 0 36 0 0 0 0 0 0 0 0 0 "
    "37 0 15 0 0 -0.002 \r\n"
    "0 1 1 1 5 0.001 0.0012 23 QUARTZ 24 0 1e+300 "
    "2 0 16 0 0 0 12 0.002 0 0 20 0 0 0 18 0 31 1 0 0 0 42 0 0 0 36 0 0 0 0 0 0 0 0 0 37 0 15 0 0 "
    "0 "
    "2 0.5 16 0 0 0 12 0.002 0 -0.001 20 0 0 0 18 0 31 1 0 0 0 42 0 0 0 36 0 0 0 0 0 0 0 0 0 "
    "37 0 15 0 0 -0.002 \r\n"
    "0 2 1 1 5 0.0015 0.0015 23 Undefined 24 0 1e+300 "
    "2 0 16 0 0 0 12 0.004 0 0 20 0 0 0 18 0 31 1 0 0 0 42 0 0 0 36 0 0 0 0 0 0 0 0 0 37 0 15 0 0 "
    "0 "
    "2 0.5 16 0 0 0 12 0.004 0 -0.001 20 0 0 0 18 0 31 1 0 0 0 42 0 0 0 36 0 0 0 0 0 0 0 0 0 "
    "37 0 15 0 0 -0.002 \r\n"
    "0 3 1 9 5 0 1 0.0008 0.002 23 BOND 24 0 1e+300 "
    "2 0 12 0.001 0 0 20 0 0 0 18 0 45 0 0 0 37 0 43 0 15 0 0 0 "
    "2 0.5 12 0.001 0 -0.001 20 0 0 0 18 0 45 0 0 0 37 0 43 0 15 0 0 -0.002 \r\n"
    "0 4 1 9 5 1 2 0.0006 0.0020000001 23 BOND 24 0 1e+300 "
    "2 0 12 0.003 0 0 20 0 0 0 18 0 45 0 0 0 37 0 43 0 15 0 0 0 "
    "2 0.5 12 0.003 0 -0.001 20 0 0 0 18 0 45 0 0 0 37 0 43 0 15 0 0 -0.002 \r\n"
    "0 5 1 14 5  23 STEEL 24 0 1e+300 "
    "2 0 44 -1 -1 -0.01 1 -1 -0.01 0 1 -0.01 20 0 0 0 18 0 15 0 0 0 "
    "2 0.5 44 -1 -1 -0.01 1 -1 -0.01 0 1 -0.01 20 0 0 0 18 0 15 0 0 0 \r\n"
    "22 -0.01 -0.01 -0.01 0.01 0.01 0.01 \r\n"
    "28 0 0 0 0 0 0 0 0 0 0 0 0 0 0 \r\n"
    "29 0 \r\n"
    "30 0 \r\n"
    "25 Plate PLATE 0 0 0 0 0 \r\n"
    "32 QUARTZ Quartz 2 2650 3 5e+07 \r\n";

TEST(MusenText, ReadsWhatMusensExporterWrites) {
  TempDir dir;
  std::vector<std::string> dropped;
  const ExchangeStructure s = read_musen_structure(dir.write("export.txt", kMusenExport), &dropped);
  EXPECT_EQ(s.particles.id, (std::vector<std::int64_t>{0, 1, 2}));
  ASSERT_EQ(s.particles.position.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {  // the first time point's centres
    EXPECT_EQ(s.particles.position[k].x, 0.002 * static_cast<double>(k));
    EXPECT_EQ(s.particles.position[k].z, 0.0);
  }
  EXPECT_EQ(s.particles.radius, (std::vector<double>{0.001, 0.001, 0.0015}));
  EXPECT_EQ(names_of(s.particles.material_names, s.particles.material),
            (std::vector<std::string>{"QUARTZ", "QUARTZ", "Undefined"}));
  EXPECT_EQ(s.bonds.i, (std::vector<std::int64_t>{0, 1}));
  EXPECT_EQ(s.bonds.j, (std::vector<std::int64_t>{1, 2}));
  EXPECT_EQ(s.bonds.radius, (std::vector<double>{0.0004, 0.0003}));  // half the diameters
  EXPECT_EQ(names_of(s.bonds.material_names, s.bonds.material),
            (std::vector<std::string>{"BOND", "BOND"}));
  EXPECT_TRUE(s.density.empty());

  const std::string all = joined(dropped);
  for (const char* what :
       {"time points other than t = 0 s (the file holds 2)", "velocities (5 objects)",
        "forces (1 object)", "contact radii (1 sphere with", "bond initial lengths (1 bond other",
        "triangular walls (1)", "the simulation domain", "periodic boundaries", "scene options",
        "geometries", "the materials database"}) {
    EXPECT_NE(all.find(what), std::string::npos) << what << " not in: " << all;
  }
  // Zeros and the identity orientation lose nothing.
  for (const char* what : {"orientations", "temperatures", "stresses", "torques"})
    EXPECT_EQ(all.find(what), std::string::npos) << what << " in: " << all;
}

TEST(MusenText, MalformedFilesNameFileAndLine) {
  TempDir dir;
  const std::string sphere0 = "0 0 1 1 5 0.001 0.001 2 0 12 0 0 0\n";
  const std::string sphere1 = "0 1 1 1 5 0.001 0.001 2 0 12 0.002 0 0\n";
  const auto error = [&](const std::string& name, const std::string& text) {
    const std::string path = dir.write(name, text);
    return message_of([&] { (void)read_musen_structure(path); });
  };
  std::string m = error("word.txt", sphere0 + "0 1 1 1 5 0.001 0.001 2 0 12 0.002 zero 0\n");
  EXPECT_NE(m.find("word.txt:2"), std::string::npos) << m;
  EXPECT_NE(m.find("'zero'"), std::string::npos) << m;
  m = error("stranger.txt", sphere0 + sphere1 + "\n0 2 1 9 5 0 7 0.001 0.002\n");
  EXPECT_NE(m.find("stranger.txt:4"), std::string::npos) << m;
  EXPECT_NE(m.find("joins object 7, which is not a sphere"), std::string::npos) << m;
  m = error("short.txt", sphere0 + "0 1 1 1 5 0.001 0.001 2 0 12 0.002 0\n");
  EXPECT_NE(m.find("short.txt:2"), std::string::npos) << m;
  EXPECT_NE(m.find("the line ends before"), std::string::npos) << m;
  m = error("bond_short.txt", sphere0 + sphere1 + "0 2 1 9 5 0 1 0.001\n");
  EXPECT_NE(m.find("bond_short.txt:3"), std::string::npos) << m;
  EXPECT_NE(m.find("initial length"), std::string::npos) << m;
  m = error("noid.txt", sphere0 + "1 1 5 0.001 0.001 2 0 12 0.002 0 0\n");
  EXPECT_NE(m.find("noid.txt:2"), std::string::npos) << m;
  EXPECT_NE(m.find("not with the object's id"), std::string::npos) << m;
  m = error("twice.txt", sphere0 + "0 0 1 1 5 0.001 0.001 2 0 12 0.002 0 0\n");
  EXPECT_NE(m.find("twice.txt:2"), std::string::npos) << m;
  EXPECT_NE(m.find("also on line 1"), std::string::npos) << m;
  m = error("nocentre.txt", "0 0 1 1 5 0.001 0.001 23 QUARTZ 24 0 1e+300\n");
  EXPECT_NE(m.find("nocentre.txt:1"), std::string::npos) << m;
  EXPECT_NE(m.find("has no centre"), std::string::npos) << m;
  m = error("command.txt", "0 0 1 1 5 0.001 0.001 2 0 12 0 0 0 99 1\n");
  EXPECT_NE(m.find("command.txt:1"), std::string::npos) << m;
  EXPECT_NE(m.find("command 99"), std::string::npos) << m;
  m = error("times.txt", sphere0 + "0 1 1 1 5 0.001 0.001 2 0.5 12 0.002 0 0\n");
  EXPECT_NE(m.find("times.txt:2"), std::string::npos) << m;
  EXPECT_NE(m.find("one time point"), std::string::npos) << m;
  m = error("empty.txt", "22 0 0 0 1 1 1\n");
  EXPECT_NE(m.find("no spheres"), std::string::npos) << m;
}

TEST(MusenText, ToldFromALammpsDataFileByItsFirstLine) {
  TempDir dir;
  EXPECT_TRUE(is_musen_text(dir.write("a.txt", kMusenExport)));
  EXPECT_TRUE(is_musen_text(dir.write("b.txt", "\n  \n0 12 1 9 5 0 1 0.001 0.002\n")));
  EXPECT_FALSE(is_musen_text(dir.write("c.data", "LAMMPS data file via write_data\n\n2 atoms\n")));
  EXPECT_FALSE(is_musen_text(dir.write("d.data", "0 atoms title\n")));
  EXPECT_FALSE(is_musen_text(dir.path("missing.txt")));
}

/// `bpmkit convert`: a MUSEN file is recognised without --from and converted to bpmkit's CSV,
/// printing what it drops; back to MUSEN with --to musen gives the same spheres and bonds.
TEST(MusenText, ConvertCommandBothWays) {
  TempDir dir;
  dir.write("export.txt", kMusenExport);
  test::Outcome o = test::run_bpmkit("convert export.txt --to bpmkit --out csv", dir.path(""));
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_NE(o.output.find("(musen) -> bpmkit"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("not carried over: triangular walls (1)"), std::string::npos) << o.output;
  const auto summary = nlohmann::json::parse(test::read_text(dir.path("csv/summary.json")));
  EXPECT_EQ(summary["from"], "musen");
  EXPECT_EQ(summary["particles"], 3);
  EXPECT_EQ(summary["bonds"], 2);

  o = test::run_bpmkit("convert csv --to musen --out back", dir.path(""));
  ASSERT_EQ(o.status, 0) << o.output;
  const ExchangeStructure from_csv = read_bpmkit_structure(dir.path("csv"));
  const ExchangeStructure back = read_musen_structure(dir.path("back/musen.txt"));
  EXPECT_EQ(back.particles.id, from_csv.particles.id);
  EXPECT_EQ(back.particles.radius, from_csv.particles.radius);
  EXPECT_EQ(back.bonds.i, from_csv.bonds.i);
  EXPECT_EQ(back.bonds.radius, from_csv.bonds.radius);
}

}  // namespace
}  // namespace bpm
