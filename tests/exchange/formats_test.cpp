// Other codes' formats (io/structure_exchange.hpp, io/lammps_data.hpp): a structure written as a
// LAMMPS data file (both atom styles) or as YADE text and read back is the same, bit for bit, where
// the format holds the value, and the loss is listed where it does not; files as LAMMPS's
// write_data writes them are read; malformed files are refused naming the file and line; and
// Debian's LAMMPS (when installed) reads our data file and writes back the same atoms and bonds.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <utility>

#include "common/exchange_structures.hpp"
#include "common/test_files.hpp"
#include "core/error.hpp"
#include "io/lammps_data.hpp"
#include "io/structure_exchange.hpp"

namespace bpm {
namespace {

using test::awkward_structure;
using test::expect_bitwise;
using test::expect_same_structure;
using test::message_of;
using test::TempDir;

TEST(LammpsData, BothAtomStylesRoundTripBitForBit) {
  TempDir dir;
  const ExchangeStructure s = awkward_structure();
  for (const LammpsAtomStyle style :
       {LammpsAtomStyle::bpm_sphere, LammpsAtomStyle::hybrid_sphere_bond}) {
    LammpsDataOptions options;
    options.style = style;
    const std::string path = dir.write("structure.data", lammps_data_text(s, options));
    std::vector<std::string> dropped;
    const ExchangeStructure back = read_lammps_data(path, &dropped);
    expect_same_structure(s, back, true);
    EXPECT_TRUE(dropped.empty());
  }
}

TEST(LammpsData, LammpsIdsAreOursPlusOne) {
  const std::string text = lammps_data_text(awkward_structure(), {});
  // id 7 -> atom 8 of type 2 (steel plate), diameter 2 R; the bond 7-0 -> atoms 8 and 1.
  EXPECT_NE(text.find("\n8 1 2 0.4 2650 0.1 -0 1e-310\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\n1 1 8 1 # r_b 0.1\n"), std::string::npos) << text;
  EXPECT_NE(text.find("# atom type 2: steel plate\n"), std::string::npos);
}

TEST(LammpsData, WithoutDensitiesAskForOne) {
  ExchangeStructure s = awkward_structure();
  s.density.clear();
  const std::string message = message_of([&] { (void)lammps_data_text(s, {}); });
  EXPECT_NE(message.find("--density"), std::string::npos) << message;
  LammpsDataOptions options;
  options.density = 1500;
  TempDir dir;
  const ExchangeStructure back =
      read_lammps_data(dir.write("s.data", lammps_data_text(s, options)));
  EXPECT_EQ(back.density, std::vector<double>(4, 1500.0));
}

/// A file as LAMMPS's write_data writes it: no names, image flags, velocities, coefficients.
TEST(LammpsData, ReadsWhatWriteDataWrites) {
  TempDir dir;
  const std::string path = dir.write(
      "written.data", R"(LAMMPS data file via write_data, version 29 Sep 2021, timestep = 0

3 atoms
2 atom types
2 bonds
1 bond types

-1 2 xlo xhi
-1 2 ylo yhi
-1 2 zlo zhi

Masses

1 0
2 0

Bond Coeffs # zero

1 0

Atoms # hybrid

3 2 1 0 0 0.5 2650 1 0 0 0
1 1 0 0 0 0.5 2650 1 1 0 0
2 1 0.5 0 0 0.5 2650 1 0 0 0

Velocities

3 0 0 0 0 0 0
1 0 0 0 0 0 0
2 0 0 0 0 0 0

Bonds

1 1 1 2
2 1 2 3
)");
  std::vector<std::string> dropped;
  const ExchangeStructure s = read_lammps_data(path, &dropped);
  EXPECT_EQ(s.particles.id, (std::vector<std::int64_t>{2, 0, 1}));
  EXPECT_EQ(s.particles.radius, std::vector<double>(3, 0.25));
  EXPECT_EQ(s.particles.material_names, (std::vector<std::string>{"type1", "type2"}));
  EXPECT_EQ(s.particles.material, (std::vector<std::uint32_t>{1, 0, 0}));
  EXPECT_EQ(s.bonds.i, (std::vector<std::int64_t>{0, 1}));
  EXPECT_EQ(s.bonds.j, (std::vector<std::int64_t>{1, 2}));
  EXPECT_TRUE(s.bonds.radius.empty());
  EXPECT_TRUE(s.bonds.material.empty());  // one unnamed bond type: no materials
  const std::string all = [&] {
    std::string a;
    for (const auto& d : dropped) a += d + "; ";
    return a;
  }();
  for (const char* what : {"image flags", "velocities", "Bond Coeffs", "Masses"}) {
    EXPECT_NE(all.find(what), std::string::npos) << what << " not in: " << all;
  }
}

TEST(LammpsData, MalformedFilesNameFileAndLine) {
  TempDir dir;
  const std::string head = "title\n\n2 atoms\n1 atom types\n1 bonds\n1 bond types\n\n";
  const std::string atoms = "Atoms # bpm/sphere\n\n1 1 1 0.5 2650 0 0 0\n2 1 1 0.5 2650 0.5 0 0\n";
  const auto error = [&](const std::string& name, const std::string& text) {
    const std::string path = dir.write(name, text);
    return message_of([&] { (void)read_lammps_data(path); });
  };
  std::string m =
      error("nostyle.data", head + "Atoms\n\n1 1 1 0.5 2650 0 0 0\n2 1 1 0.5 2650 0.5 0 0\n");
  EXPECT_NE(m.find("nostyle.data:8"), std::string::npos) << m;
  EXPECT_NE(m.find("Atoms # bpm/sphere"), std::string::npos) << m;
  m = error("short.data", head + atoms + "\nBonds\n\n");
  EXPECT_NE(m.find("ends after 0 of 1 rows"), std::string::npos) << m;
  m = error("stranger.data", head + atoms + "\nBonds\n\n1 1 1 9\n");
  EXPECT_NE(m.find("particle 8, which is not listed"), std::string::npos) << m;
  m = error("word.data",
            head + "Atoms # bpm/sphere\n\n1 1 1 0.5 2650 0 zero 0\n2 1 1 0.5 2650 0.5 0 0\n");
  EXPECT_NE(m.find("word.data:10"), std::string::npos) << m;
  EXPECT_NE(m.find("'zero'"), std::string::npos) << m;
  m = error("angles.data", head + atoms + "\nAngles\n\n1 1 1 2 3\n");
  EXPECT_NE(m.find("Angles section is not supported"), std::string::npos) << m;
}

TEST(YadeText, RoundTripKeepsCentresAndRadiiAndSaysWhatItDrops) {
  TempDir dir;
  const ExchangeStructure s = awkward_structure();
  const ExchangeFiles files = yade_structure_files(s);
  for (const auto& [name, content] : files.files) dir.write(name, content);
  const ExchangeStructure back = read_yade_structure(dir.path(""));
  ASSERT_EQ(back.particles.id, (std::vector<std::int64_t>{0, 1, 2, 3}));  // rows
  for (std::size_t k = 0; k < 4; ++k) {
    expect_bitwise(back.particles.position[k].x, s.particles.position[k].x, "x");
    expect_bitwise(back.particles.position[k].z, s.particles.position[k].z, "z");
    expect_bitwise(back.particles.radius[k], s.particles.radius[k], "r");
  }
  // Bond 7-0 joins rows 0 and 1; 0-3 rows 1 and 2; 12-3 rows 3 and 2.
  EXPECT_EQ(back.bonds.i, (std::vector<std::int64_t>{0, 1, 3}));
  EXPECT_EQ(back.bonds.j, (std::vector<std::int64_t>{1, 2, 2}));
  std::string dropped;
  for (const auto& d : files.dropped) dropped += d + "; ";
  for (const char* what :
       {"particle ids", "particle materials", "densities", "bond radii", "bond materials"}) {
    EXPECT_NE(dropped.find(what), std::string::npos) << what << " not in: " << dropped;
  }
}

TEST(BpmkitCsv, RoundTripThroughLammpsIsTheSameFiles) {
  TempDir dir;
  ExchangeStructure s = awkward_structure();
  const ExchangeFiles files = bpmkit_structure_files(s);
  for (const auto& [name, content] : files.files) dir.write(name, content);
  const ExchangeStructure read = read_bpmkit_structure(dir.path(""));
  s.density.clear();  // particles.csv holds none
  expect_same_structure(s, read, false);
  LammpsDataOptions options;
  options.density = 2650;
  const ExchangeStructure back =
      read_lammps_data(dir.write("s.data", lammps_data_text(read, options)));
  EXPECT_EQ(bpmkit_structure_files(back).files, files.files);
}

/// Runs a shell command; its exit status.
int shell(const std::string& command) {
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(LammpsData, DebiansLammpsReadsOurFile) {
  if (shell("command -v lmp > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "Debian's lammps (lmp) is not installed";
  TempDir dir;
  const ExchangeStructure s = awkward_structure();
  LammpsDataOptions options;
  options.style = LammpsAtomStyle::hybrid_sphere_bond;  // Debian 12's LAMMPS has no BPM package
  dir.write("ours.data", lammps_data_text(s, options));
  dir.write("in.read",
            "units si\natom_style hybrid sphere bond\natom_modify map array\nboundary f f f\n"
            "bond_style zero\nread_data ours.data\nbond_coeff *\nwrite_data written.data\n");
  ASSERT_EQ(shell("cd '" + dir.path("") + "' && lmp -in in.read -log none -screen none"), 0);
  const ExchangeStructure back = read_lammps_data(dir.path("written.data"));
  // write_data keeps ids, types, centres, diameters and densities; it sorts the atoms by id and
  // drops our comments (material names, r_b).
  std::map<std::int64_t, std::size_t> row;
  for (std::size_t k = 0; k < back.particles.id.size(); ++k) row[back.particles.id[k]] = k;
  ASSERT_EQ(row.size(), s.particles.id.size());
  for (std::size_t k = 0; k < s.particles.id.size(); ++k) {
    const std::size_t b = row.at(s.particles.id[k]);
    expect_bitwise(back.particles.position[b].x, s.particles.position[k].x, "x");
    expect_bitwise(back.particles.position[b].y, s.particles.position[k].y, "y");
    expect_bitwise(back.particles.position[b].z, s.particles.position[k].z, "z");
    expect_bitwise(back.particles.radius[b], s.particles.radius[k], "radius");
    expect_bitwise(back.density[b], s.density[k], "density");
    EXPECT_EQ(back.particles.material[b], s.particles.material[k]);
  }
  std::set<std::pair<std::int64_t, std::int64_t>> ours, theirs;
  for (std::size_t k = 0; k < s.bonds.i.size(); ++k)
    ours.insert(std::minmax(s.bonds.i[k], s.bonds.j[k]));
  for (std::size_t k = 0; k < back.bonds.i.size(); ++k)
    theirs.insert(std::minmax(back.bonds.i[k], back.bonds.j[k]));
  EXPECT_EQ(ours, theirs);
}

}  // namespace
}  // namespace bpm
