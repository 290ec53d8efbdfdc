#pragma once
/// MUSEN's text import/export format (its CExportAsText and CImportFromText), the subset a bonded
/// structure needs: spheres and solid bonds at one time point.
///
/// The spec is MUSEN's own source (github.com/msolids/musen), read at these commits:
///   Modules/SimResultsStorage/ExportAsText.cpp and ImportFromText.cpp (the line layout) at
///     1ddf23c8c0e57270fcc1ba1215f604a2b22a5f37 (ExportAsText.cpp at
///     7f0ed580b453927cfbccb5b6685211dac60a009b writes objects the same way);
///   Modules/GeneralSources/MUSENDefinitions.h (command numbers, object types) at
///     1dda7aef096b6a3a76de7df4f7bc3d4c2979b61f;
///   Modules/SystemStructure/Sphere.cpp (d91d132d15a3478826a898c2406c0d229ba75dd4) and Bond.cpp
///     (39a01d6253f07141beaf1827915bdb7a2c8ce395): the geometry text.
///
/// One object per line: pairs of a command number and its values, separated by spaces.
///   sphere:     0 ID 1 1 5 R R_CONTACT [23 COMPOUND] [24 T_START T_END] 2 TIME 12 X Y Z ...
///   solid bond: 0 ID 1 9 5 ID_LEFT ID_RIGHT DIAMETER L_INITIAL [23 COMPOUND] [24 ...] ...
/// After `2 TIME` come that time point's values (12 centre, 15 velocity, 16 angular velocity,
/// 31 orientation, ...); a line may hold several time points. Lines of scene, geometry,
/// material and generator data start with their own command (22, 25-30, 32-34, 38-41, 46).
/// Object ids are one 32-bit unsigned number space for spheres, bonds and walls. SI units.
///
/// Written: per sphere its id, radius (= contact radius), compound key (the material name,
/// whitespace as '_'), the activity interval [0, 1e300] (MUSEN's default), time 0 with its centre
/// and the identity orientation; per bond an id after the largest particle id, the two particle
/// ids, the diameter 2 r_b, the initial length |x_j - x_i| and its compound key. Numbers in their
/// shortest exact form, so bpmkit -> MUSEN -> bpmkit keeps ids, centres, radii and r_b bit for
/// bit. Read back: the same; everything else (later time points, velocities, forces,
/// orientations, stresses, temperatures, contact radii, activity intervals, liquid bonds, walls,
/// geometries, the materials database, generators) is listed in `dropped`.
#include <string>
#include <vector>

#include "io/structure_exchange.hpp"

namespace bpm {

/// Reads a MUSEN text file: its spheres and solid bonds at the file's first time point. Anything
/// malformed is an InputError naming the file and line. `dropped` (if given) receives what the
/// file held that bpmkit does not keep.
ExchangeStructure read_musen_structure(const std::string& path,
                                       std::vector<std::string>* dropped = nullptr);

/// The structure as one MUSEN text file (musen.txt), and what it could not hold.
ExchangeFiles musen_structure_files(const ExchangeStructure& s);

/// True if the file's first non-blank line starts like a MUSEN object line, "0 ID 1 TYPE": how
/// `bpmkit convert` tells it from a LAMMPS data file, whose first line is a free title.
bool is_musen_text(const std::string& path);

}  // namespace bpm
