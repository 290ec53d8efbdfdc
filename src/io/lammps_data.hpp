#pragma once
/// LAMMPS data files (`read_data`, `write_data`) of bonded spheres, in either atom style LAMMPS
/// offers for them:
///   bpm/sphere           Atoms: atom-ID molecule-ID atom-type diameter density x y z
///   hybrid sphere bond   Atoms: atom-ID atom-type x y z diameter density molecule-ID
/// and a Bonds section "bond-ID bond-type atom-1 atom-2". The Atoms line may end in three image
/// flags. bpm/sphere needs LAMMPS's BPM package (since 4 May 2022); Debian 12's LAMMPS has no BPM
/// package but reads the hybrid style.
///
/// Mapping: LAMMPS atom id = bpmkit id + 1 (LAMMPS ids start at 1); the atom type is the particle
/// material's number + 1 and the bond type the bond material's. The material names, which LAMMPS
/// does not keep, and each bond's r_b are written as comments ('#' starts a comment for LAMMPS):
/// `# atom type 1: rock` in the header and `# r_b 0.002` after a bond, which this reader reads
/// back, so a bpmkit -> LAMMPS -> bpmkit round trip is lossless. Dropped on reading: velocities,
/// image flags, molecule ids, coefficients and the box (bpmkit has no periodic box).
#include <string>

#include "io/structure_exchange.hpp"

namespace bpm {

enum class LammpsAtomStyle { bpm_sphere, hybrid_sphere_bond };

struct LammpsDataOptions {
  LammpsAtomStyle style = LammpsAtomStyle::bpm_sphere;
  /// kg/m^3 for particles without one (ExchangeStructure::density empty); <= 0: none given, which
  /// is an InputError then (LAMMPS needs a density per atom).
  double density = 0.0;
  /// Bond type per bond (1-based) and the "Bond Coeffs" lines, when the caller sets them (bpmkit
  /// export lammps); empty: the bond material decides the type and no coefficients are written.
  std::vector<int> bond_type;
  std::vector<std::string> bond_coeffs;
  std::string bond_style;  ///< the style named in the "Bond Coeffs" comment
};

/// The data file text. It holds everything an ExchangeStructure holds.
std::string lammps_data_text(const ExchangeStructure& s, const LammpsDataOptions& options);

/// Reads a data file of either style (named after "Atoms #", as write_data names it; "hybrid"
/// alone, as write_data writes it, is read as hybrid sphere bond). Anything
/// malformed is an InputError naming the file and line. `dropped` (if given) receives what the
/// file held that bpmkit does not keep.
ExchangeStructure read_lammps_data(const std::string& path,
                                   std::vector<std::string>* dropped = nullptr);

}  // namespace bpm
