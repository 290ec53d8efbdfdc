#pragma once
/// The walls of a DEM frame as their own PolyData, the second part of frames.pvd
/// (io/vtk_writer.hpp), so that ParaView shows them as a block of their own. Each wall is drawn as
/// polygons; infinite walls are cut to the sample (the particles' bounding box, radii included):
///   plane      a square of side 1.2 x the box diagonal, centred on the box centre's projection
///   rectangle  its rectangle
///   disc       a polygon of kVtkWallSegments sides on its rim
///   cylinder   kVtkWallSegments quads around the axis, over the particles' extent along it + 10 %
/// Cell data (one value per polygon, that of its wall): wall (index into the field data string
/// array wall_names), force (the particles' force on the wall, N), displacement (m), velocity
/// (m/s).
#include <string>
#include <vector>

#include "io/vtk_polydata.hpp"
#include "model/particle_store.hpp"
#include "model/wall.hpp"

namespace bpm {

inline constexpr int kVtkWallSegments = 64;

VtkPolyData walls_polydata(const std::vector<Wall>& walls, const ParticleStore& particles);

std::string walls_vtp(const std::vector<Wall>& walls, const ParticleStore& particles,
                      VtkEncoding encoding = VtkEncoding::zlib);

}  // namespace bpm
