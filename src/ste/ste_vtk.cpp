#include "ste/ste_vtk.hpp"

#include <fmt/core.h>

#include <iterator>

#include "io/atomic_file.hpp"

namespace bpm::ste {
namespace {

/// One DataArray of n tuples; value(out, i) appends the i-th tuple's text to out (fmt::format_to:
/// no temporary string per number).
template <class Value>
void data_array(std::string& s, const char* type, const std::string& name, int components, std::size_t n, Value&& value) {
  s += fmt::format("        <DataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\" format=\"ascii\">\n", type,
                   name, components);
  for (std::size_t i = 0; i < n; ++i) {
    s += "          ";
    value(s, i);
    s += '\n';
  }
  s += "        </DataArray>\n";
}

template <class Get>
void scalar(std::string& s, const std::string& name, std::size_t n, Get&& get) {
  data_array(s, "Float64", name, 1, n,
             [&](std::string& out, std::size_t i) { fmt::format_to(std::back_inserter(out), "{:.10g}", get(i)); });
}

template <class Get>
void integer(std::string& s, const std::string& name, std::size_t n, Get&& get) {
  data_array(s, "Int32", name, 1, n, [&](std::string& out, std::size_t i) { out += std::to_string(get(i)); });
}

}  // namespace

std::string ste_polydata_vtp(const ParticleStore& p, const SteResult& r) {
  const std::size_t n = p.size();
  std::string s = fmt::format(
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      "  <PolyData>\n"
      "    <Piece NumberOfPoints=\"{}\" NumberOfVerts=\"0\" NumberOfLines=\"0\" NumberOfStrips=\"0\" "
      "NumberOfPolys=\"0\">\n      <Points>\n",
      n);
  data_array(s, "Float64", "position", 3, n, [&](std::string& out, std::size_t i) {
    const Vec3& x = p.position[i];
    fmt::format_to(std::back_inserter(out), "{:.10g} {:.10g} {:.10g}", x.x, x.y, x.z);
  });
  s += "      </Points>\n      <PointData Scalars=\"radius\">\n";
  scalar(s, "radius", n, [&](std::size_t i) { return p.radius[i]; });
  // The user's ids: the points come in bpmkit's canonical order, not the file's.
  data_array(s, "Int64", "id", 1, n, [&](std::string& out, std::size_t i) { out += std::to_string(p.id[i]); });
  scalar(s, "volume", n, [&](std::size_t i) { return r.particle_volume[i]; });
  integer(s, "used", n, [&](std::size_t i) { return r.particle_use[i] == ParticleUse::used ? 1 : 0; });
  integer(s, "use", n, [&](std::size_t i) { return static_cast<int>(r.particle_use[i]); });
  integer(s, "coordination", n, [&](std::size_t i) { return r.coordination[i]; });
  static constexpr int kEntries[9][2] = {{0, 0}, {1, 1}, {2, 2}, {3, 3}, {4, 4}, {5, 5}, {0, 1}, {0, 2}, {1, 2}};
  for (const auto& e : kEntries) {
    scalar(s, fmt::format("C{}{}", e[0] + 1, e[1] + 1), n, [&](std::size_t i) { return r.particle_stiffness[i](e[0], e[1]); });
  }
  if (r.local) {
    const LocalMap& m = *r.local;
    static constexpr const char* kAxes[3] = {"x", "y", "z"};
    for (int d = 0; d < 3; ++d) scalar(s, fmt::format("E_local_{}", kAxes[d]), n, [&](std::size_t i) { return m.modulus[i][d]; });
    for (int d = 0; d < 3; ++d) scalar(s, fmt::format("E_excess_{}", kAxes[d]), n, [&](std::size_t i) { return m.excess[i][d]; });
  }
  s += "      </PointData>\n    </Piece>\n  </PolyData>\n</VTKFile>\n";
  return s;
}

void write_ste_vtp(const std::string& path, const ParticleStore& particles, const SteResult& result) {
  write_file_atomic(path, ste_polydata_vtp(particles, result));
}

}  // namespace bpm::ste
