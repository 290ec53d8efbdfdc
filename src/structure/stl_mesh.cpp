#include "structure/stl_mesh.hpp"

#include <fmt/core.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <tuple>

#include "core/error.hpp"
#include "io/parse_number.hpp"

namespace bpm {
namespace {

/// Merges vertices with identical coordinates.
class VertexWelder {
 public:
  explicit VertexWelder(TriangleMesh& mesh) : mesh_(mesh) {}
  std::int32_t index(const Vec3& v) {
    const auto [it, added] = index_.emplace(std::make_tuple(v.x, v.y, v.z), static_cast<std::int32_t>(mesh_.vertices.size()));
    if (added) mesh_.vertices.push_back(v);
    return it->second;
  }

 private:
  TriangleMesh& mesh_;
  std::map<std::tuple<double, double, double>, std::int32_t> index_;
};

void add_triangle(TriangleMesh& mesh, VertexWelder& welder, const std::array<Vec3, 3>& v) {
  std::array<std::int32_t, 3> t{welder.index(v[0]), welder.index(v[1]), welder.index(v[2])};
  // A triangle with two equal corners has no area and no edges worth matching.
  if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) return;
  mesh.triangles.push_back(t);
}

TriangleMesh read_binary(const std::string& path, const std::string& bytes, double scale) {
  std::uint32_t count = 0;
  std::memcpy(&count, bytes.data() + 80, 4);
  if (bytes.size() < 84 + 50ull * count) {
    throw InputError(path, fmt::format("binary STL is truncated: it declares {} triangles ({} bytes) but has {} bytes",
                                       count, 84 + 50ull * count, bytes.size()),
                     "re-export the file");
  }
  TriangleMesh mesh;
  VertexWelder welder(mesh);
  for (std::uint32_t t = 0; t < count; ++t) {
    const char* rec = bytes.data() + 84 + 50ull * t + 12;  // skip the normal
    std::array<Vec3, 3> v;
    for (int k = 0; k < 3; ++k) {
      float xyz[3];
      std::memcpy(xyz, rec + 12 * k, 12);
      v[static_cast<std::size_t>(k)] = Vec3{xyz[0], xyz[1], xyz[2]} * scale;
    }
    add_triangle(mesh, welder, v);
  }
  return mesh;
}

TriangleMesh read_ascii(const std::string& path, const std::string& text, double scale) {
  TriangleMesh mesh;
  VertexWelder welder(mesh);
  std::istringstream in(text);
  std::array<Vec3, 3> v;
  int corners = 0, line_no = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_no;
    std::istringstream words(line);
    std::string word;
    if (!(words >> word)) continue;
    if (word == "vertex") {
      std::string a, b, c;
      words >> a >> b >> c;
      const auto x = parse_double(a), y = parse_double(b), z = parse_double(c);
      if (!x || !y || !z) {
        throw InputError(fmt::format("{}:{}", path, line_no), "a vertex line needs three finite numbers",
                         "write 'vertex X Y Z'");
      }
      if (corners == 3) {
        throw InputError(fmt::format("{}:{}", path, line_no), "a facet has more than 3 vertices",
                         "the STL must be triangulated");
      }
      v[static_cast<std::size_t>(corners++)] = Vec3{*x, *y, *z} * scale;
    } else if (word == "endfacet") {
      if (corners != 3) {
        throw InputError(fmt::format("{}:{}", path, line_no), fmt::format("a facet has {} vertices, not 3", corners),
                         "the STL must be triangulated");
      }
      add_triangle(mesh, welder, v);
      corners = 0;
    }
  }
  return mesh;
}

}  // namespace

TriangleMesh read_stl(const std::string& path, double scale, const std::string& referenced_from) {
  if (!std::filesystem::is_regular_file(path)) {
    throw InputError(referenced_from.empty() ? path : referenced_from, "STL file '" + path + "' not found",
                     "check the path; it is relative to the spec file's folder");
  }
  std::ifstream in(path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  if (!in) throw InputError(path, "cannot read the STL file", "check that it exists and is readable");
  const std::string bytes = buffer.str();

  // A binary file may also start with "solid", so the size decides: binary if 84 + 50 n bytes.
  bool binary = false;
  if (bytes.size() >= 84) {
    std::uint32_t count = 0;
    std::memcpy(&count, bytes.data() + 80, 4);
    binary = bytes.size() == 84 + 50ull * count || bytes.compare(0, 5, "solid") != 0;
  }
  const bool ascii = !binary && bytes.compare(0, 5, "solid") == 0;
  if (!binary && !ascii) {
    throw InputError(path, "not an STL file (too short, and it does not start with 'solid')",
                     "give an ASCII or binary STL");
  }
  TriangleMesh mesh = binary ? read_binary(path, bytes, scale) : read_ascii(path, bytes, scale);
  if (mesh.triangles.empty()) throw InputError(path, "the STL holds no triangles", "give a closed triangulated surface");
  return mesh;
}

}  // namespace bpm
