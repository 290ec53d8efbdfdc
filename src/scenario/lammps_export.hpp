#pragma once
/// `bpmkit export lammps`: a loaded scenario as a LAMMPS data file and input deck for the BPM
/// package's `bond_style bpm/rotational` (LAMMPS 4 May 2022 or later; docs/formats.md).
///
/// The mapping (small strains): bpm/rotational is a pair of springs at the midpoint of the centres
/// with F_r = K_r (r - r_0), a shear force K_s times the lateral displacement of that point, a
/// bending torque K_b theta and a twisting torque K_t psi (Wang 2009, as LAMMPS implements it).
/// Chen's unified law with the contact point at L_b/2 is the same element, so
///   K_r = k_n,  K_s = k_s,  K_t = k_tor,  K_b = k_ben
/// for every bond model (PBM, Brendel, EBBM, TBBM, Obermayr, ...): the model only decides the four
/// numbers. Exact where our contact point is the midpoint (arm offset 0: beam-centre models, and
/// the gap-centre models PBM and Brendel between equal radii); a bond with an offset keeps its
/// stiffnesses but LAMMPS couples its shear and rotation at the midpoint instead (counted in the
/// notes). Large rotations follow each code's own kinematics.
#include <string>
#include <vector>

#include "bonds/bond_stiffness.hpp"
#include "scenario/scenario.hpp"

namespace bpm {

/// K_r, K_s, K_t, K_b of bpm/rotational for a bond of stiffness set k.
struct BpmRotationalStiffness {
  double k_r = 0.0;  ///< N/m
  double k_s = 0.0;  ///< N/m
  double k_t = 0.0;  ///< N m/rad
  double k_b = 0.0;  ///< N m/rad
};
BpmRotationalStiffness bpm_rotational_stiffness(const BondStiffness& k);

struct LammpsExport {
  std::string data;                ///< structure.data
  std::string deck;                ///< in.bpmkit
  std::size_t bond_types = 0;      ///< distinct coefficient sets
  std::vector<std::string> notes;  ///< what the export does not carry over, and why
};

/// The data file (atom_style bpm/sphere, one bond type per distinct coefficient set) and the
/// deck that reads it and runs the scenario's time step for its end time.
LammpsExport export_lammps(const Scenario& scenario);

}  // namespace bpm
