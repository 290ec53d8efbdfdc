#pragma once
/// The parameters a calibration searches, per bond material (component): the bond Young's modulus
/// E_b (Jarolin section 2) and, to reach a Poisson's ratio, the shear-to-normal stiffness ratio
/// k_s / k_n. Geometry and model stay fixed. Changing either means evaluating every bond's
/// stiffness rule again (Chen Table 9), so every model variant keeps its own dependence on them.
///
/// k_s / k_n is set through the model's own parameter: kappa for the parallel bond (k_s = k_n /
/// kappa, Chen Table 1; the k_n/k_s ratio PFC users calibrate Poisson's ratio with) and the shear
/// coefficient alpha_s for Obermayr's beam (k_s = alpha_s k_n / (2(1 + nu_b)), Chen Eq. 45).
/// Brendel's, the Euler-Bernoulli and the Timoshenko bonds tie k_s to nu_b in [0, 0.5) or to the
/// bond's geometry (Chen Eqs. 8, 26, 18): no free ratio, so they are refused.
#include <string>
#include <vector>

#include "bonds/bond_material.hpp"
#include "model/model.hpp"

namespace bpm {

/// The k_s / k_n ratios a calibration may try: the parallel bond's kappa from 0.1 to 100. On the
/// small cylinder (pbm bonds on Hertz contacts) the linear DSM gives the body nu = -0.57 at
/// kappa = 0.1 and 0.32 at kappa = 100.
constexpr double kMinShearToNormalRatio = 1e-2, kMaxShearToNormalRatio = 1e1;

/// k_s / k_n of a material's stiffness rule; throws InputError naming the material when the model
/// (or a shear_stiffness override) leaves no free ratio.
double shear_to_normal_ratio(const BondMaterial& material);
/// Sets kappa (pbm) or shear_coefficient (obermayr) so that k_s / k_n = ratio.
void set_shear_to_normal_ratio(BondMaterial& material, double ratio);
/// The parameter that carries the ratio: "kappa" or "shear_coefficient".
std::string shear_ratio_parameter(const BondMaterial& material);
/// Its value: kappa or alpha_s.
double shear_ratio_parameter_value(const BondMaterial& material);

/// Re-derives the stiffness of every bond of the model from `materials` (at the bonds' creation
/// geometry), and the bond damping. The model must be at its initial state (bonds unloaded).
void rederive_bond_stiffness(Model& model, const std::vector<BondMaterial>& materials,
                             double bond_damping);

/// Sets E_b of material m to youngs_moduli[m] in `materials` and re-derives the bonds.
void set_bond_youngs_moduli(Model& model, std::vector<BondMaterial>& materials,
                            const std::vector<double>& youngs_moduli, double bond_damping);

/// E_b of each material, in order.
std::vector<double> bond_youngs_moduli(const std::vector<BondMaterial>& materials);

}  // namespace bpm
