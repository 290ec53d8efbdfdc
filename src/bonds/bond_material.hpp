#pragma once
/// A bond material: which model (a key of the registry) and the numbers its stiffness rule reads.
#include <optional>
#include <string>

#include "bonds/bond_strength.hpp"

namespace bpm {

/// Chen case 5: the shear stiffness may be set by the user instead of the model's own rule.
enum class ShearOverride { none, value, euler_bernoulli, timoshenko };

struct BondMaterial {
  std::string name;
  std::string model = "tbbm";           ///< registry key: pbm, brendel, ebbm, tbbm, obermayr
  double youngs_modulus = 0.0;          ///< E_b, Pa
  double poisson_ratio = 0.0;           ///< nu_b, in [0, 0.5)
  std::optional<double> kappa;          ///< PBM k_n/k_s; default 2(1+nu_b) (Chen Eq. 8)
  std::optional<double> shear_coefficient;  ///< Obermayr alpha_s (Chen Eq. 45)
  ShearOverride shear_override = ShearOverride::none;
  double shear_stiffness = 0.0;         ///< k_s in N/m when shear_override == value
  std::optional<double> radius;         ///< r_b, m; else radius_multiplier * min(R_alpha, R_beta)
  double radius_multiplier = 1.0;
  StrengthDistribution tensile_strength;  ///< sigma_t, Pa; infinite (unbreakable) by default
  StrengthDistribution shear_strength;    ///< tau_s, Pa; infinite (unbreakable) by default
};

}  // namespace bpm
