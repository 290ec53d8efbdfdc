#pragma once
/// The registry of bond models. A model is data (Chen Tables 8-9): a contact-point rule and a
/// stiffness rule, both evaluated once when a bond is created. The DEM kernel, the linearised
/// element and the static solver read only the resulting BondConstants and never branch on the model.
///
/// To add a model: write its stiffness rule in bond_model.cpp, add one row to the table there, add a
/// two-body test in tests/bonds/, and document the key in docs/bond_models.md.
#include <span>
#include <string_view>

#include "bonds/bond_material.hpp"
#include "bonds/bond_stiffness.hpp"

namespace bpm {

/// Initial geometry of one bond.
struct BondGeometry {
  double radius = 0.0;        ///< r_b, m
  double length = 0.0;        ///< L_b = |x_beta - x_alpha| at creation, m
  double radius_alpha = 0.0;  ///< R_alpha, m
  double radius_beta = 0.0;   ///< R_beta, m
};

/// What a bond stores from its model: the stiffness set and the contact-point offset
/// (a_alpha = L/2 + arm_offset, see bond_law::contact_arms).
struct BondConstants {
  BondStiffness stiffness;
  double arm_offset = 0.0;
};

enum class ContactPointRule { beam_centre, gap_centre };

struct BondModelInfo {
  std::string_view key;
  ContactPointRule contact_point;
  BondStiffness (*stiffness)(const BondMaterial&, const BondGeometry&);
  std::string_view description;
};

/// All registered models, in documentation order.
std::span<const BondModelInfo> bond_models();

/// The model with this key; throws InputError listing the valid keys otherwise.
const BondModelInfo& find_bond_model(std::string_view key, std::string_view where = "bond model");

/// Stiffness set and contact-point offset of one bond (Chen Table 9 and variants).
BondConstants make_bond_constants(const BondMaterial& material, const BondGeometry& geometry);

/// Timoshenko shear coefficient Phi_s = 20 r_b^2 (1 + nu) / (3 L_b^2) (Chen Eq. 25).
double timoshenko_phi(double radius, double length, double poisson_ratio);

}  // namespace bpm
