#pragma once
/// The exact static solution of the linearised discrete model: the intact bonds' elements assembled
/// into the global stiffness by the one assembly of the static methods (static_assembly.hpp, 6 DOF
/// per particle), fixed DOFs removed, loads at full value, solved directly. This is the reference
/// the DEM steady state must reach (Chen's cantilevers).
#include <Eigen/SparseCore>
#include <vector>

#include "model/model.hpp"

namespace bpm {

struct StaticSolution {
  std::vector<Vec3> displacement;  ///< per particle, m
  std::vector<Vec3> rotation;      ///< per particle, rad
};

/// Solves K u = f for the loads at full value (ramps complete) plus gravity; fixed and prescribed
/// DOFs are held at zero. Throws InputError if the structure is not fully constrained.
StaticSolution solve_linear_static(const Model& model);

}  // namespace bpm
