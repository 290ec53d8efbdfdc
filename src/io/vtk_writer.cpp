#include "io/vtk_writer.hpp"

#include <fmt/core.h>

#include <functional>

namespace bpm {
namespace {

// Text is built with fmt::format and appended, not fmt::format_to into a back-inserter: the latter
// fails to link with clang against a GCC-built libfmt 9.

/// Appends one DataArray of n tuples with `components` values each; tuple(i) gives the i-th as text.
void data_array(std::string& s, const char* type, const char* name, int components, std::size_t n,
                const std::function<std::string(std::size_t)>& tuple) {
  s += fmt::format("        <DataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\" format=\"ascii\">\n", type,
                   name, components);
  for (std::size_t i = 0; i < n; ++i) s += "          " + tuple(i) + "\n";
  s += "        </DataArray>\n";
}

std::string vec_text(const Vec3& v) { return fmt::format("{:.10g} {:.10g} {:.10g}", v.x, v.y, v.z); }

void vector_array(std::string& s, const char* name, const std::vector<Vec3>& v) {
  data_array(s, "Float64", name, 3, v.size(), [&](std::size_t i) { return vec_text(v[i]); });
}

}  // namespace

std::string polydata_vtp(const Model& model) {
  const ParticleStore& p = model.particles;
  const BondStore& b = model.bonds;
  std::string s = fmt::format(
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      "  <PolyData>\n"
      "    <Piece NumberOfPoints=\"{}\" NumberOfVerts=\"0\" NumberOfLines=\"{}\" NumberOfStrips=\"0\" "
      "NumberOfPolys=\"0\">\n",
      p.size(), b.size());

  s += "      <Points>\n";
  vector_array(s, "position", p.position);
  s += "      </Points>\n";

  s += "      <PointData Scalars=\"radius\" Vectors=\"displacement\">\n";
  data_array(s, "Int64", "id", 1, p.size(), [&](std::size_t i) { return std::to_string(p.id[i]); });
  data_array(s, "Float64", "radius", 1, p.size(), [&](std::size_t i) { return fmt::format("{:.10g}", p.radius[i]); });
  std::vector<Vec3> displacement(p.size()), rotation(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    displacement[i] = p.position[i] - p.reference_position[i];
    rotation[i] = rotation_vector(p.orientation[i]);
  }
  vector_array(s, "displacement", displacement);
  vector_array(s, "velocity", p.velocity);
  vector_array(s, "angular_velocity", p.angular_velocity);
  vector_array(s, "rotation", rotation);
  vector_array(s, "force", p.force);
  s += "      </PointData>\n";

  s += "      <Lines>\n";
  data_array(s, "Int32", "connectivity", 1, b.size(), [&](std::size_t i) { return fmt::format("{} {}", b.alpha[i], b.beta[i]); });
  data_array(s, "Int64", "offsets", 1, b.size(), [&](std::size_t i) { return std::to_string(2 * (i + 1)); });
  s += "      </Lines>\n";

  // The per-step state arrays exist only after finalize(); an unfinalised model gets zeros.
  const bool finalised = b.force.size() == b.size() && b.axis.size() == b.size();
  const std::vector<Vec3> zeros(b.size());
  s += "      <CellData Scalars=\"axial_force\" Vectors=\"force\">\n";
  vector_array(s, "force", finalised ? b.force : zeros);
  vector_array(s, "moment", finalised ? b.moment : zeros);
  data_array(s, "Float64", "axial_force", 1, b.size(), [&](std::size_t i) {
    return fmt::format("{:.10g}", finalised ? dot(b.force[i], b.axis[i]) : 0.0);  // > 0: tension
  });
  data_array(s, "Int32", "material", 1, b.size(), [&](std::size_t i) { return std::to_string(b.material[i]); });
  // 1 intact, 0 broken (threshold on it in ParaView to see the cracks).
  data_array(s, "Int32", "intact", 1, b.size(), [&](std::size_t i) {
    return finalised && b.intact.size() == b.size() ? std::to_string(b.intact[i] == 1) : std::string("1");
  });
  s += "      </CellData>\n    </Piece>\n  </PolyData>\n</VTKFile>\n";
  return s;
}

std::string collection_pvd(const std::vector<VtkFrame>& frames) {
  std::string s =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      "  <Collection>\n";
  for (const VtkFrame& f : frames) {
    s += fmt::format("    <DataSet timestep=\"{:.12g}\" group=\"\" part=\"0\" file=\"{}\"/>\n", f.time, f.file);
  }
  s += "  </Collection>\n</VTKFile>\n";
  return s;
}

}  // namespace bpm
