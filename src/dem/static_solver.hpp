#pragma once
/// The exact static solution of the linearised discrete model: the bond elements assembled into the
/// global stiffness (6 DOF per particle), fixed DOFs removed, loads at full value, solved directly.
/// This is the reference the DEM steady state must reach; the direct stiffness method of Jarolin
/// section 3.1 builds on the same assembly.
#include <Eigen/SparseCore>
#include <vector>

#include "model/model.hpp"

namespace bpm {

/// Global stiffness K (6N x 6N, DOF 6p+k: k<3 translation, k>=3 rotation) at the current positions.
Eigen::SparseMatrix<double> assemble_stiffness(const Model& model);

struct StaticSolution {
  std::vector<Vec3> displacement;  ///< per particle, m
  std::vector<Vec3> rotation;      ///< per particle, rad
};

/// Solves K u = f for the loads at full value (ramps complete) plus gravity; fixed and prescribed
/// DOFs are held at zero. Throws InputError if the structure is not fully constrained.
StaticSolution solve_linear_static(const Model& model);

}  // namespace bpm
