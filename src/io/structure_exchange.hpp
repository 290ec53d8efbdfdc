#pragma once
/// A bonded structure as other DEM codes exchange it (`bpmkit convert`, `bpmkit export lammps`):
/// particles (id, centre, radius, material, and a density where the format has one) and bonds
/// (the two particle ids, r_b, material). The formats, their files and what they hold:
///   - bpmkit: particles.csv, bonds.csv; ids, centres, radii, materials, r_b (no density).
///   - lammps: a data file (io/lammps_data.hpp); ids + 1, centres, diameters, densities, types.
///   - yade:   spheres.txt, bonds.txt; centres, radii (ids = row numbers), bond pairs.
///   - musen:  musen.txt (io/musen_text.hpp); ids, centres, radii, compound keys, bond diameters.
///
/// Each writer returns, besides the text, what the format could not hold (`dropped`), so a round
/// trip says what it loses instead of losing it silently. Numbers are written with the shortest
/// text that reads back to the same double: a round trip through any format keeps them bit for bit.
#include <string>
#include <vector>

#include "io/structure_table.hpp"

namespace bpm {

struct ExchangeStructure {
  ParticleTable particles;
  std::vector<double> density;  ///< kg/m^3 per particle, or empty: the source had none
  BondTable bonds;
};

/// A format's files, by name within its folder, and what it could not hold.
struct ExchangeFiles {
  std::vector<std::pair<std::string, std::string>> files;  ///< (name, content)
  std::vector<std::string> dropped;
};

/// particles.csv and bonds.csv (or their binary twins, io/structure_table.hpp) of a folder, as
/// `bpmkit generate` writes them; a folder without bonds.csv has no bonds.
ExchangeStructure read_bpmkit_structure(const std::string& dir);
ExchangeFiles bpmkit_structure_files(const ExchangeStructure& s);

/// YADE's text export (`yade.export.text`: a `#format x_y_z_r` line, then "x y z r" per sphere;
/// `ymport.text` reads it back) in spheres.txt, and bonds.txt with one "i j" pair per line, i and j
/// being 0-based rows of spheres.txt (the body ids YADE gives the spheres when it imports them
/// into an empty scene).
ExchangeStructure read_yade_structure(const std::string& dir);
ExchangeFiles yade_structure_files(const ExchangeStructure& s);

/// Checks what every format needs: unique ids, positive finite radii, bonds between listed
/// particles. `source` names the input in the message.
void check_exchange_structure(const ExchangeStructure& s, const std::string& source);

}  // namespace bpm
