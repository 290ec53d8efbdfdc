#pragma once
/// VTK output for ParaView: one XML PolyData file (.vtp, io/vtk_polydata.hpp: binary, zlib) per
/// frame and a collection file (.pvd) that lists the frames with their times, so ParaView opens
/// the run as one time series.
///
/// Points are the particle centres, with point data id, radius (m), material (index into
/// particle_material_names), displacement (m), velocity (m/s), angular_velocity (rad/s), rotation
/// (rotation vector, rad) and force (N). Lines are the bonds (alpha, beta), with cell data force
/// and moment (the elastic bond load on alpha at the contact point, global frame:
/// BondStore::force and ::moment, Chen Table 8), axial_force (force . axis; positive in tension),
/// material (index into bond_material_names) and intact (1 intact, 0 broken). Field data: the
/// string arrays particle_material_names and bond_material_names, when given.
/// To see spheres, apply a Glyph filter (sphere, scale by `radius`, scale factor 2).
#include <string>
#include <vector>

#include "io/vtk_polydata.hpp"
#include "model/model.hpp"

namespace bpm {

/// The names that the material indices of a frame refer to (Scenario's lists).
struct VtkMaterialNames {
  std::vector<std::string> particle, bond;
};

VtkPolyData frame_polydata(const Model& model, const VtkMaterialNames& names = {});

/// frame_polydata serialised.
std::string polydata_vtp(const Model& model, const VtkMaterialNames& names = {},
                         VtkEncoding encoding = VtkEncoding::zlib);

struct VtkFrame {
  double time = 0.0;       ///< s
  std::string file;        ///< path of the particles' .vtp relative to the .pvd (part 0)
  std::string walls_file;  ///< path of the walls' .vtp (part 1); empty: no walls
};

/// The collection: part 0 the particles and bonds, part 1 the walls (io/vtk_walls.hpp), so that
/// ParaView shows them as two blocks with the same time steps.
std::string collection_pvd(const std::vector<VtkFrame>& frames);

}  // namespace bpm
