// The one VTK writer (io/vtk_polydata.hpp) byte by byte: the compressed block layout against zlib
// itself, every array's appended block inflating to the bytes given, the ASCII mode reading back
// to the same numbers, the frame's and the walls' arrays, and the collection's parts.
#include <gtest/gtest.h>
#include <zlib.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/vtk_polydata.hpp"
#include "io/vtk_walls.hpp"
#include "io/vtk_writer.hpp"
#include "io/vtk_zlib.hpp"
#include "vtk_test_reader.hpp"

namespace bpm {
namespace {

std::uint64_t u64(const std::string& s, std::size_t at) {
  std::uint64_t v = 0;
  std::memcpy(&v, s.data() + at, 8);
  return v;
}

/// Half random, half repeated bytes: some blocks compress, some do not.
std::string sample_bytes(std::size_t n) {
  std::mt19937 rng(5);
  std::string s(n, '\0');
  for (std::size_t i = 0; i < n; ++i)
    s[i] = static_cast<char>(i % 2 == 0 ? rng() & 0xff : i / 1000);
  return s;
}

TEST(VtkZlib, BlockLayoutInflatesWithZlib) {
  for (const std::size_t n : {std::size_t{0}, std::size_t{1}, std::size_t{1000}, kVtkBlockSize,
                              kVtkBlockSize + 1, 3 * kVtkBlockSize + 17}) {
    const std::string raw = sample_bytes(n);
    const std::string block = vtk_zlib_block(raw, 6);
    const std::size_t blocks = (n + kVtkBlockSize - 1) / kVtkBlockSize;
    ASSERT_EQ(u64(block, 0), blocks) << n;
    EXPECT_EQ(u64(block, 8), kVtkBlockSize);
    EXPECT_EQ(u64(block, 16), n % kVtkBlockSize);  // 0: the last block is full
    // Inflate each block with zlib directly (not through vtk_zlib_unblock).
    std::string inflated;
    std::size_t at = 8 * (3 + blocks);
    for (std::size_t b = 0; b < blocks; ++b) {
      const std::uint64_t packed = u64(block, 8 * (3 + b));
      std::string out(kVtkBlockSize, '\0');
      uLongf size = kVtkBlockSize;
      ASSERT_EQ(uncompress(reinterpret_cast<Bytef*>(out.data()), &size,
                           reinterpret_cast<const Bytef*>(block.data() + at), packed),
                Z_OK);
      inflated.append(out.data(), size);
      at += packed;
    }
    EXPECT_EQ(at, block.size()) << "no bytes after the last block";
    EXPECT_EQ(inflated, raw) << n;
    std::size_t used = 0;
    EXPECT_EQ(vtk_zlib_unblock(block + "trailing", &used), raw);
    EXPECT_EQ(used, block.size());
  }
}

TEST(VtkZlib, DamagedBlocksAreRefused) {
  const std::string block = vtk_zlib_block(sample_bytes(50000), 1);
  EXPECT_THROW(vtk_zlib_unblock(block.substr(0, block.size() - 10)), std::runtime_error);
  std::string flipped = block;
  flipped[8 * 5 + 3] ^= 0x55;  // inside the first zlib stream
  EXPECT_THROW(vtk_zlib_unblock(flipped), std::runtime_error);
  EXPECT_THROW(vtk_zlib_unblock(block.substr(0, 12)), std::runtime_error);
}

VtkPolyData sample_polydata() {
  static const std::vector<Vec3> points{{0, 0, 0}, {1.5, -2, 3e-9}, {0.1, 0.2, 0.3}};
  VtkPolyData d(points);
  d.lines(std::vector<std::int32_t>{0, 1}, std::vector<std::int32_t>{1, 2});
  d.polygon(std::vector<std::int64_t>{0, 1, 2});
  d.point_data().scalars("radius", std::vector<double>{0.1, 1.0 / 3.0, 2e-300});
  d.point_data().int64s("id", std::vector<std::int64_t>{-1, 1LL << 40, 7});
  d.point_data().vectors("velocity", points);
  d.cell_data().int32s("material", std::vector<std::int32_t>{3, -4, 5});
  d.field_data().strings("names", {"a", "", "b c"});
  return d;
}

TEST(VtkPolyData, AppendedArraysAreTheInputBytes) {
  const std::string vtp = sample_polydata().vtp();
  const std::string xml = test::vtk_xml(vtp);
  EXPECT_NE(xml.find("compressor=\"vtkZLibDataCompressor\""), std::string::npos);
  EXPECT_NE(xml.find("header_type=\"UInt64\""), std::string::npos);
  EXPECT_NE(xml.find("NumberOfLines=\"2\""), std::string::npos);
  EXPECT_NE(xml.find("NumberOfPolys=\"1\""), std::string::npos);
  EXPECT_EQ(xml.find("format=\"ascii\""), std::string::npos);
  EXPECT_EQ(test::vtk_values<double>(vtp, "position"),
            (std::vector<double>{0, 0, 0, 1.5, -2, 3e-9, 0.1, 0.2, 0.3}));
  EXPECT_EQ(test::vtk_values<double>(vtp, "radius"), (std::vector<double>{0.1, 1.0 / 3.0, 2e-300}));
  EXPECT_EQ(test::vtk_values<std::int64_t>(vtp, "id"),
            (std::vector<std::int64_t>{-1, 1LL << 40, 7}));
  EXPECT_EQ(test::vtk_values<std::int32_t>(vtp, "material"), (std::vector<std::int32_t>{3, -4, 5}));
  EXPECT_EQ(test::vtk_values<std::int64_t>(vtp, "connectivity", "Lines"),
            (std::vector<std::int64_t>{0, 1, 1, 2}));
  EXPECT_EQ(test::vtk_values<std::int64_t>(vtp, "offsets", "Lines"),
            (std::vector<std::int64_t>{2, 4}));
  EXPECT_EQ(test::vtk_values<std::int64_t>(vtp, "offsets", "Polys"),
            (std::vector<std::int64_t>{3}));
  EXPECT_EQ(test::vtk_strings(vtp, "names"), (std::vector<std::string>{"a", "", "b c"}));
  // The appended section ends the file: the raw bytes, a newline and the closing tags.
  EXPECT_TRUE(vtp.ends_with("\n  </AppendedData>\n</VTKFile>\n"));
}

TEST(VtkPolyData, AsciiReadsBackToTheSameNumbers) {
  const VtkPolyData d = sample_polydata();
  const std::string ascii = d.vtp(VtkEncoding::ascii), zlib = d.vtp();
  EXPECT_EQ(ascii.find("AppendedData"), std::string::npos);
  EXPECT_EQ(ascii.find("compressor"), std::string::npos);
  for (const char* name : {"position", "radius", "velocity"})
    EXPECT_EQ(test::vtk_values<double>(ascii, name), test::vtk_values<double>(zlib, name)) << name;
  EXPECT_EQ(test::vtk_values<std::int64_t>(ascii, "id"),
            test::vtk_values<std::int64_t>(zlib, "id"));
  EXPECT_EQ(test::vtk_values<std::int64_t>(ascii, "connectivity"),
            (std::vector<std::int64_t>{0, 1, 1, 2}));
  EXPECT_EQ(test::vtk_strings(ascii, "names"), (std::vector<std::string>{"a", "", "b c"}));
}

TEST(VtkPolyData, ArraysOfTheWrongLengthAreRefused) {
  const std::vector<Vec3> points(2);
  VtkPolyData d(points);
  d.point_data().scalars("radius", std::vector<double>{1.0});
  try {
    d.vtp();
    FAIL() << "a point array of 1 value for 2 points was written";
  } catch (const std::logic_error& e) {
    EXPECT_NE(std::string(e.what()).find("radius"), std::string::npos) << e.what();
  }
  VtkPolyData lines(points);
  EXPECT_THROW(lines.lines(std::vector<std::int32_t>{0}, std::vector<std::int32_t>{}),
               std::invalid_argument);
}

TEST(VtkFrame, MaterialsAndNamesOfTheModel) {
  Model m;
  m.particles.add(4, {0, 0, 0}, 0.2, 1000.0, 1);
  m.particles.add(9, {0.4, 0, 0}, 0.2, 1000.0, 0);
  m.bonds.add(0, 1, {{1e9, 1e8, 1e6, 1e6}, 0.0}, 0.2, 0.4);
  m.bonds.material[0] = 1;
  m.finalize();
  const std::string vtp = polydata_vtp(m, {{"a", "b"}, {"x", "y"}});
  EXPECT_EQ(test::vtk_values<std::int32_t>(vtp, "material", "PointData"),
            (std::vector<std::int32_t>{1, 0}));
  EXPECT_EQ(test::vtk_values<std::int32_t>(vtp, "material", "CellData"),
            (std::vector<std::int32_t>{1}));
  EXPECT_EQ(test::vtk_values<std::int64_t>(vtp, "id"), (std::vector<std::int64_t>{4, 9}));
  EXPECT_EQ(test::vtk_strings(vtp, "particle_material_names"),
            (std::vector<std::string>{"a", "b"}));
  EXPECT_EQ(test::vtk_strings(vtp, "bond_material_names"), (std::vector<std::string>{"x", "y"}));
  // Without names there is no field data.
  EXPECT_EQ(polydata_vtp(m).find("FieldData"), std::string::npos);
}

TEST(VtkWalls, PlaneCoversTheSampleAndCylinderHasItsRadius) {
  ParticleStore p;
  p.add(0, {0, 0, 0}, 0.5, 1000.0);
  p.add(1, {4, 2, 1}, 0.5, 1000.0);
  std::vector<Wall> walls(2);
  walls[0].shape = WallShape::plane;
  walls[0].point = {0, 0, -3};
  walls[0].normal = {0, 0, 1};
  walls[1].shape = WallShape::cylinder;
  walls[1].point = {1, 1, 0};
  walls[1].normal = {0, 0, 1};
  walls[1].radius = 6;
  const std::string vtp = walls_vtp(walls, p);
  const std::vector<double> xyz = test::vtk_values<double>(vtp, "position");
  ASSERT_EQ(xyz.size(), 3u * (4 + 4 * kVtkWallSegments));
  // The plane's quad: in the plane, around the particles' box (x -0.5..4.5, y -0.5..2.5).
  for (int k = 0; k < 4; ++k) EXPECT_EQ(xyz[3 * k + 2], -3.0);
  double lo_x = 1e9, hi_x = -1e9, lo_y = 1e9, hi_y = -1e9;
  for (int k = 0; k < 4; ++k) {
    lo_x = std::min(lo_x, xyz[3 * k]);
    hi_x = std::max(hi_x, xyz[3 * k]);
    lo_y = std::min(lo_y, xyz[3 * k + 1]);
    hi_y = std::max(hi_y, xyz[3 * k + 1]);
  }
  EXPECT_LT(lo_x, -0.5);
  EXPECT_GT(hi_x, 4.5);
  EXPECT_LT(lo_y, -0.5);
  EXPECT_GT(hi_y, 2.5);
  // The cylinder: every point at its radius from the axis, spanning the box along it (z -0.5..1.5).
  double lo_z = 1e9, hi_z = -1e9;
  for (std::size_t k = 4; k < xyz.size() / 3; ++k) {
    EXPECT_NEAR(std::hypot(xyz[3 * k] - 1, xyz[3 * k + 1] - 1), 6.0, 1e-12);
    lo_z = std::min(lo_z, xyz[3 * k + 2]);
    hi_z = std::max(hi_z, xyz[3 * k + 2]);
  }
  EXPECT_LT(lo_z, -0.5);
  EXPECT_GT(hi_z, 1.5);
  EXPECT_EQ(test::vtk_values<std::int32_t>(vtp, "wall").size(), 1u + kVtkWallSegments);
}

TEST(VtkCollection, WallsAreTheSecondPart) {
  const std::string pvd = collection_pvd({{0.0, "f0.vtp", "w0.vtp"}, {1.5, "f1.vtp", ""}});
  EXPECT_NE(pvd.find(R"(timestep="0" group="" part="0" file="f0.vtp")"), std::string::npos) << pvd;
  EXPECT_NE(pvd.find(R"(timestep="0" group="" part="1" file="w0.vtp")"), std::string::npos) << pvd;
  EXPECT_NE(pvd.find(R"(timestep="1.5" group="" part="0" file="f1.vtp")"), std::string::npos)
      << pvd;
  EXPECT_EQ(pvd.find(R"(part="1" file="")"), std::string::npos) << pvd;
}

}  // namespace
}  // namespace bpm
