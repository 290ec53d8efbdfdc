#include "io/vtk_writer.hpp"

#include <fmt/core.h>

namespace bpm {

VtkPolyData frame_polydata(const Model& model, const VtkMaterialNames& names) {
  const ParticleStore& p = model.particles;
  const BondStore& b = model.bonds;
  VtkPolyData d(p.position);
  VtkArrays& points = d.point_data();
  points.set_active("radius", "displacement");
  points.int64s("id", p.id);
  points.scalars("radius", p.radius);
  points.int32s("material", p.material);
  std::vector<Vec3> displacement(p.size()), rotation(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    displacement[i] = p.position[i] - p.reference_position[i];
    rotation[i] = rotation_vector(p.orientation[i]);
  }
  points.vectors("displacement", displacement);
  points.vectors("velocity", p.velocity);
  points.vectors("angular_velocity", p.angular_velocity);
  points.vectors("rotation", rotation);
  points.vectors("force", p.force);

  d.lines(b.alpha, b.beta);
  // The per-step state arrays exist only after finalize(); an unfinalised model gets zeros.
  const bool finalised = b.force.size() == b.size() && b.axis.size() == b.size();
  const std::vector<Vec3> zeros(finalised ? 0 : b.size());
  std::vector<double> axial(b.size(), 0.0);
  std::vector<std::int32_t> intact(b.size(), 1);  // 1 intact, 0 broken: threshold on it for cracks
  for (std::size_t k = 0; finalised && k < b.size(); ++k) {
    axial[k] = dot(b.force[k], b.axis[k]);  // > 0: tension
    if (b.intact.size() == b.size()) intact[k] = b.intact[k] == 1;
  }
  VtkArrays& cells = d.cell_data();
  cells.set_active("axial_force", "force");
  cells.vectors("force", finalised ? b.force : zeros);
  cells.vectors("moment", finalised ? b.moment : zeros);
  cells.scalars("axial_force", axial);
  cells.int32s("material", b.material);
  cells.int32s("intact", intact);

  if (!names.particle.empty()) d.field_data().strings("particle_material_names", names.particle);
  if (!names.bond.empty()) d.field_data().strings("bond_material_names", names.bond);
  return d;
}

std::string polydata_vtp(const Model& model, const VtkMaterialNames& names, VtkEncoding encoding) {
  return frame_polydata(model, names).vtp(encoding);
}

std::string collection_pvd(const std::vector<VtkFrame>& frames) {
  std::string s =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      "  <Collection>\n";
  for (const VtkFrame& f : frames) {
    s += fmt::format("    <DataSet timestep=\"{:.12g}\" group=\"\" part=\"0\" file=\"{}\"/>\n",
                     f.time, f.file);
    if (!f.walls_file.empty())
      s += fmt::format("    <DataSet timestep=\"{:.12g}\" group=\"\" part=\"1\" file=\"{}\"/>\n",
                       f.time, f.walls_file);
  }
  s += "  </Collection>\n</VTKFile>\n";
  return s;
}

}  // namespace bpm
