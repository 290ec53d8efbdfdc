#pragma once
/// VTK output for ParaView: one XML PolyData file (.vtp, ASCII) per frame and a collection file
/// (.pvd) that lists the frames with their times, so ParaView opens the run as one time series.
///
/// Points are the particle centres, with point data id, radius (m), displacement (m), velocity
/// (m/s), angular_velocity (rad/s), rotation (rotation vector, rad) and force (N). Lines are the
/// bonds (alpha, beta), with cell data force and moment (the elastic bond load on alpha at the
/// contact point, global frame: BondStore::force and ::moment, Chen Table 8), axial_force
/// (force . axis; positive in tension) and material (index into the scenario's bond materials).
/// To see spheres, apply a Glyph filter (sphere, scale by `radius`, scale factor 2).
#include <string>
#include <vector>

#include "dem/model.hpp"

namespace bpm {

std::string polydata_vtp(const Model& model);

struct VtkFrame {
  double time = 0.0;  ///< s
  std::string file;   ///< path of the .vtp relative to the .pvd
};

std::string collection_pvd(const std::vector<VtkFrame>& frames);

}  // namespace bpm
