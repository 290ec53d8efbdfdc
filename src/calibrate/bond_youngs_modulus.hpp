#pragma once
/// The calibration parameter of Jarolin section 2: one bond Young's modulus E_b per bond material
/// (component); geometry, Poisson ratio and model stay fixed. Changing E_b means evaluating every
/// bond's stiffness rule again (Chen Table 9), so the shear-stiffness override and every model
/// variant keep their own dependence on E_b.
#include <vector>

#include "bonds/bond_material.hpp"
#include "model/model.hpp"

namespace bpm {

/// Sets E_b of material m to youngs_moduli[m] in `materials` and re-derives the stiffness of every
/// bond of the model from it (at the bonds' creation geometry), and the bond damping. The model
/// must be at its initial state (bonds unloaded).
void set_bond_youngs_moduli(Model& model, std::vector<BondMaterial>& materials, const std::vector<double>& youngs_moduli,
                            double bond_damping);

/// E_b of each material, in order.
std::vector<double> bond_youngs_moduli(const std::vector<BondMaterial>& materials);

}  // namespace bpm
