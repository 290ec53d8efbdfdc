#pragma once
/// Boundary conditions of the direct stiffness method as prescribed degrees of freedom
/// (statics/dof_constraints.hpp).
///
/// - Kinematic platens (the linear DSM, Jarolin section 4.2: "a fixed lower wall and a fixed
///   displacement of the upper wall"): the particles of the bottom set are held along the axis, the
///   top set moved by -displacement; with a frictional platen also held across it.
/// - Across frictionless platens (every grain-platen pair without friction) the sample may slide
/// and spin about the axis; these three
///   rigid-body modes are removed by pinning two bottom particles: the one nearest the set's centre
///   in both lateral directions, the one farthest from it in the lateral direction that spin moves
///   most. The pins carry no force (the loads are axial and balanced), so the solution is
///   unchanged.
/// - DOFs the scenario fixes (boundary_conditions: fix) are held at zero as well; where it holds
///   some translation, no pins are added (its constraints must then remove the rigid modes).
/// - Particles not bonded to the largest bonded cluster (loose particles, fragments) carry no load
///   and have no defined position in a static solution: they are held and counted.
#include "compress/platen_loading.hpp"
#include "model/model.hpp"
#include "statics/dof_constraints.hpp"

namespace bpm {

/// kinematic_platens: hold and move the platen sets (linear DSM); otherwise only the pins and the
/// detached particles (the nonlinear DSM, whose wall springs carry the platens).
DofConstraints platen_constraints(const Model& model, const PlatenLoading& load, int dofs,
                                  bool kinematic_platens);

}  // namespace bpm
