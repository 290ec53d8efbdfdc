// bpmkit's VTK files read back by VTK's own XML readers (vtkXMLPolyDataReader,
// the .pvd parsed as XML: what ParaView opens them with), through python3-vtk9 and
// read_vtk_frame.py: the counts, positions, bond ends, ids, radii, bond forces, materials and
// their names, the walls and the collection's parts must be the model's. Skipped, saying why, where
// /usr/bin/python3 or its vtk module is missing (scripts/install-deps.sh installs them).
#include <gtest/gtest.h>

#include <fmt/core.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "io/vtk_walls.hpp"
#include "io/vtk_writer.hpp"
#include "io_test_util.hpp"
#include "scenario/scenario.hpp"
#include "scenario/scenario_run.hpp"

namespace bpm {
namespace {

using nlohmann::json;
using test::TempDir;

constexpr const char* kPython = "/usr/bin/python3";

struct Read {
  bool skipped = false;
  std::string why;
  json result;
};

/// Runs read_vtk_frame.py on `files`; skipped when python3 or vtk is missing, a test failure when
/// VTK reports an error.
Read read_with_vtk(const std::vector<std::string>& files) {
  if (!std::filesystem::exists(kPython)) return {true, std::string(kPython) + " is missing", {}};
  std::string command = std::string(kPython) + " '" + BPMKIT_VTK_READER + "'";
  for (const std::string& f : files) command += " '" + f + "'";
  command += " 2>&1";
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return {true, "cannot start " + command, {}};
  std::string output;
  char buffer[4096];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;)
    output.append(buffer, n);
  const int status = ::pclose(pipe);
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  if (code == 77)
    return {true, "python3-vtk9 is missing (apt-get install python3-vtk9): " + output, {}};
  Read r;
  if (code != 0) {
    ADD_FAILURE() << "read_vtk_frame.py failed (" << code << "):\n" << output;
    return r;
  }
  r.result = json::parse(output, nullptr, false);
  if (r.result.is_discarded()) ADD_FAILURE() << "not JSON:\n" << output;
  return r;
}

#define READ_OR_SKIP(read, files)             \
  const Read read = read_with_vtk(files);     \
  if (read.skipped) GTEST_SKIP() << read.why; \
  ASSERT_TRUE(read.result.is_object())

std::vector<double> values(const json& array) {
  return array.at("values").get<std::vector<double>>();
}

std::vector<double> flat(const std::vector<Vec3>& v) {
  std::vector<double> out;
  for (const Vec3& x : v) out.insert(out.end(), {x.x, x.y, x.z});
  return out;
}

/// Four particles of two materials in a bent chain, three bonds of two materials, loaded bonds,
/// the third broken.
Model chain() {
  Model m;
  m.particles.add(7, {0, 0, 0}, 0.10, 1000.0, 0);
  m.particles.add(3, {0.2, 0, 0}, 0.11, 1000.0, 1);
  m.particles.add(11, {0.4, 0.05, 0}, 0.12, 1000.0, 1);
  m.particles.add(5, {0.6, 0.05, 0.1}, 0.13, 1000.0, 0);
  for (int k = 0; k < 3; ++k) m.bonds.add(k, k + 1, {{1e9, 1e8, 1e6, 1e6}, 0.0}, 0.05, 0.2);
  m.bonds.material = {0, 1, 1};
  m.finalize();
  m.bonds.force = {{5, 1, 0}, {-2, 0.5, 0.25}, {1e-3, 2e3, -7}};
  m.bonds.intact[2] = 0;
  m.particles.force[2] = {1, -2, 3};
  return m;
}

std::vector<Wall> walls() {
  std::vector<Wall> w(4);
  w[0].name = "floor";
  w[0].shape = WallShape::plane;
  w[0].point = {0, -1, 0};
  w[0].normal = {0, 1, 0};
  w[0].force = {0, -4, 0};
  w[1].name = "plate";
  w[1].shape = WallShape::rectangle;
  w[1].point = {0, 1, 0};
  w[1].normal = {0, -1, 0};
  w[1].half_width = 0.5;
  w[1].half_height = 0.25;
  w[2].name = "lid";
  w[2].shape = WallShape::disc;
  w[2].point = {0, 0, 1};
  w[2].normal = {0, 0, -1};
  w[2].radius = 0.3;
  w[3].name = "mould";
  w[3].shape = WallShape::cylinder;
  w[3].point = {0.3, 0, 0};
  w[3].normal = {1, 0, 0};
  w[3].radius = 0.5;
  w[3].displacement = {0.01, 0, 0};
  return w;
}

TEST(VtkParaView, FrameReadsBackAsTheModel) {
  const Model m = chain();
  const VtkMaterialNames names{{"sand", "glass"}, {"cement", "glue"}};
  TempDir dir;
  const std::string frame = dir.write("frame.vtp", polydata_vtp(m, names));
  READ_OR_SKIP(read, {frame});
  const json& f = read.result.at(frame);
  const ParticleStore& p = m.particles;
  EXPECT_EQ(f.at("points"), 4);
  EXPECT_EQ(f.at("lines"), 3);
  EXPECT_EQ(f.at("xyz").get<std::vector<double>>(), flat(p.position));
  EXPECT_EQ(f.at("cells"), json::parse("[[0,1],[1,2],[2,3]]"));
  const json& pd = f.at("point_data");
  EXPECT_EQ(pd.at("id").at("type"), "long long");  // Int64 as read
  EXPECT_EQ(values(pd.at("id")), (std::vector<double>{7, 3, 11, 5}));
  EXPECT_EQ(values(pd.at("radius")), p.radius);
  EXPECT_EQ(values(pd.at("material")), (std::vector<double>{0, 1, 1, 0}));
  EXPECT_EQ(values(pd.at("force")), flat(p.force));
  EXPECT_EQ(pd.at("displacement").at("components"), 3);
  const json& cd = f.at("cell_data");
  EXPECT_EQ(values(cd.at("force")), flat(m.bonds.force));
  EXPECT_DOUBLE_EQ(values(cd.at("axial_force"))[0], dot(m.bonds.force[0], m.bonds.axis[0]));
  EXPECT_EQ(values(cd.at("material")), (std::vector<double>{0, 1, 1}));
  EXPECT_EQ(values(cd.at("intact")), (std::vector<double>{1, 1, 0}));
  const json& fd = f.at("field_data");
  EXPECT_EQ(fd.at("particle_material_names").at("values"), json(names.particle));
  EXPECT_EQ(fd.at("bond_material_names").at("values"), json(names.bond));

  // The ASCII mode reads back to the same numbers.
  const std::string ascii = dir.write("ascii.vtp", polydata_vtp(m, names, VtkEncoding::ascii));
  READ_OR_SKIP(text, {ascii});
  const json& a = text.result.at(ascii);
  for (const char* key : {"xyz", "cells", "point_data", "cell_data", "field_data"})
    EXPECT_EQ(a.at(key), f.at(key)) << key;
}

TEST(VtkParaView, EmptyModelReads) {
  TempDir dir;
  const std::string frame = dir.write("empty.vtp", polydata_vtp(Model{}));
  READ_OR_SKIP(read, {frame});
  EXPECT_EQ(read.result.at(frame).at("points"), 0);
  EXPECT_EQ(read.result.at(frame).at("point_data").at("radius").at("values"), json::array());
}

TEST(VtkParaView, WallsAndCollectionReadBack) {
  const Model m = chain();
  const std::vector<Wall> w = walls();
  TempDir dir;
  std::filesystem::create_directories(dir.path("frames"));
  dir.write("frames/frame_000000.vtp", polydata_vtp(m));
  const std::string wall_file = dir.write("frames/walls_000000.vtp", walls_vtp(w, m.particles));
  dir.write("frames/frame_000001.vtp", polydata_vtp(m));
  dir.write("frames/walls_000001.vtp", walls_vtp(w, m.particles));
  const std::string pvd = dir.write(
      "frames.pvd", collection_pvd({{0.0, "frames/frame_000000.vtp", "frames/walls_000000.vtp"},
                                    {0.5, "frames/frame_000001.vtp", "frames/walls_000001.vtp"}}));
  READ_OR_SKIP(read, (std::vector<std::string>{wall_file, pvd}));

  const json& ws = read.result.at(wall_file);
  EXPECT_EQ(ws.at("polys"), 3 + kVtkWallSegments);  // plane, rectangle, disc; the cylinder's quads
  EXPECT_EQ(ws.at("field_data").at("wall_names").at("values"),
            json::parse(R"(["floor","plate","lid","mould"])"));
  std::vector<double> expect_wall{0, 1, 2};
  expect_wall.insert(expect_wall.end(), kVtkWallSegments, 3);
  EXPECT_EQ(values(ws.at("cell_data").at("wall")), expect_wall);
  const std::vector<double> force = values(ws.at("cell_data").at("force"));
  EXPECT_EQ(std::vector<double>(force.begin(), force.begin() + 3), (std::vector<double>{0, -4, 0}));
  const std::vector<double> shift = values(ws.at("cell_data").at("displacement"));
  EXPECT_EQ(shift[3 * 3], 0.01);  // the cylinder's first quad
  // The disc's rim: every point at its radius in its plane.
  const json& rim = ws.at("cells")[2];
  ASSERT_EQ(rim.size(), static_cast<std::size_t>(kVtkWallSegments));
  const std::vector<double> xyz = ws.at("xyz").get<std::vector<double>>();
  for (const auto& id : rim) {
    const std::size_t k = 3 * id.get<std::size_t>();
    EXPECT_NEAR(std::hypot(xyz[k], xyz[k + 1]), 0.3, 1e-12);
    EXPECT_EQ(xyz[k + 2], 1.0);
  }

  const json& c = read.result.at(pvd);
  ASSERT_EQ(c.at("datasets").size(), 4u);
  EXPECT_EQ(c.at("datasets")[1].at("part"), "1");
  EXPECT_EQ(c.at("datasets")[1].at("file"), "frames/walls_000000.vtp");
  EXPECT_EQ(c.at("datasets")[3].at("timestep"), "0.5");
  EXPECT_EQ(c.at("parts"), 2);  // particles and walls: two blocks in ParaView
  EXPECT_EQ(c.at("datasets")[2].at("points"), 4);
  EXPECT_EQ(c.at("datasets")[3].at("cells"), 3 + kVtkWallSegments);
}

/// kGoodScenario with a contact law and two walls (a floor and a mould around the chain).
std::string scenario_with_walls() {
  std::string s = test::kGoodScenario;
  test::replace_once(
      s, "    density: 7850\n",
      "    density: 7850\n    contact: {law: linear, k_n: 2e9, k_t: 2e9, restitution: 0.5}\n");
  s += "walls:\n"
       "  - {name: floor, shape: plane, point: [0, -0.5, 0], normal: [0, 1, 0], material: steel}\n"
       "  - {name: mould, shape: cylinder, point: [0, 0, 0], axis: [1, 0, 0], radius: 0.6, inside: "
       "true, "
       "material: steel}\n";
  return s;
}

TEST(VtkParaView, RunWritesWallsAsTheSecondPart) {
  TempDir dir;
  Scenario s = load_scenario(dir.write("scenario.yaml", scenario_with_walls()));
  const std::string out = dir.path("out");
  const ScenarioRunResult r = run_scenario(s, out);
  ASSERT_EQ(r.frames, 5u);
  for (int k = 0; k < 5; ++k) {
    EXPECT_TRUE(std::filesystem::is_regular_file(out + fmt::format("/frames/walls_{:06d}.vtp", k)))
        << k;
  }
  const std::string last = out + "/frames/frame_000004.vtp", pvd = out + "/frames.pvd";
  READ_OR_SKIP(read, (std::vector<std::string>{last, out + "/frames/walls_000004.vtp", pvd}));
  // The last frame is the model as the run left it.
  const json& f = read.result.at(last);
  EXPECT_EQ(f.at("xyz").get<std::vector<double>>(), flat(s.model.particles.position));
  EXPECT_EQ(values(f.at("cell_data").at("force")), flat(s.model.bonds.force));
  EXPECT_EQ(f.at("field_data").at("particle_material_names").at("values"),
            json::parse(R"(["steel"])"));
  EXPECT_EQ(f.at("field_data").at("bond_material_names").at("values"), json::parse(R"(["beam"])"));
  EXPECT_EQ(read.result.at(out + "/frames/walls_000004.vtp").at("polys"), 1 + kVtkWallSegments);
  const json& datasets = read.result.at(pvd).at("datasets");
  ASSERT_EQ(datasets.size(), 10u);
  for (std::size_t k = 0; k < 10; ++k)
    EXPECT_EQ(datasets[k].at("part"), k % 2 == 0 ? "0" : "1") << k;
  EXPECT_EQ(read.result.at(pvd).at("parts"), 2);
}

TEST(VtkParaView, RunWithoutWallsWritesOnePart) {
  TempDir dir;
  Scenario s = load_scenario(dir.write("scenario.yaml", test::kGoodScenario));
  run_scenario(s, dir.path("out"));
  EXPECT_FALSE(std::filesystem::exists(dir.path("out/frames/walls_000000.vtp")));
  const std::string pvd = test::read_text(dir.path("out/frames.pvd"));
  EXPECT_EQ(pvd.find("part=\"1\""), std::string::npos);
  EXPECT_NE(pvd.find("part=\"0\""), std::string::npos);
}

}  // namespace
}  // namespace bpm
