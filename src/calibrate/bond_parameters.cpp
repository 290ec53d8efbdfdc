#include "calibrate/bond_parameters.hpp"

#include <fmt/core.h>

#include "bonds/bond_model.hpp"
#include "core/error.hpp"

namespace bpm {
namespace {

bool is_parallel_bond(const BondMaterial& m) {
  return m.model == "pbm";
}

/// 2 (1 + nu_b): Brendel's kappa (Chen Eq. 8), the default of the parallel bond's kappa.
double brendel_kappa(const BondMaterial& m) {
  return 2.0 * (1.0 + m.poisson_ratio);
}

void require_free_ratio(const BondMaterial& m) {
  const std::string where = "bond_materials." + m.name;
  if (m.shear_override != ShearOverride::none) {
    throw InputError(
        where, "its shear_stiffness override fixes k_s, so k_s / k_n cannot be calibrated for nu",
        "remove shear_stiffness from the bond material");
  }
  if (!is_parallel_bond(m) && m.model != "obermayr") {
    throw InputError(
        where,
        fmt::format(
            "model {} ties k_s to nu_b or to the bond's geometry (Chen Table 9), so k_s / k_n "
            "cannot be calibrated for the sample's Poisson's ratio",
            m.model),
        "use model pbm (k_s = k_n / kappa) or obermayr (k_s = alpha_s k_n / (2(1 + nu_b))), whose "
        "ratio is free; or calibrate E alone");
  }
}

}  // namespace

double shear_to_normal_ratio(const BondMaterial& m) {
  require_free_ratio(m);
  if (is_parallel_bond(m)) return 1.0 / m.kappa.value_or(brendel_kappa(m));
  return m.shear_coefficient.value_or(1.0) / brendel_kappa(m);
}

void set_shear_to_normal_ratio(BondMaterial& m, double ratio) {
  require_free_ratio(m);
  if (!(ratio > 0.0)) throw InputError("bond_materials." + m.name, "k_s / k_n must be > 0", "");
  if (is_parallel_bond(m)) {
    m.kappa = 1.0 / ratio;
  } else {
    m.shear_coefficient = ratio * brendel_kappa(m);
  }
}

std::string shear_ratio_parameter(const BondMaterial& m) {
  require_free_ratio(m);
  return is_parallel_bond(m) ? "kappa" : "shear_coefficient";
}

double shear_ratio_parameter_value(const BondMaterial& m) {
  require_free_ratio(m);
  return is_parallel_bond(m) ? m.kappa.value_or(brendel_kappa(m))
                             : m.shear_coefficient.value_or(1.0);
}

void rederive_bond_stiffness(Model& model, const std::vector<BondMaterial>& materials,
                             double bond_damping) {
  BondStore& b = model.bonds;
  const ParticleStore& p = model.particles;
  for (std::size_t i = 0; i < b.size(); ++i) {
    const BondGeometry g{b.radius[i], b.rest_length[i], p.radius[b.alpha[i]], p.radius[b.beta[i]]};
    b.stiffness[i] =
        make_bond_constants(materials[static_cast<std::size_t>(b.material[i])], g).stiffness;
  }
  // Refresh what depends on the stiffness (bond damping) while keeping the adjacency and axes.
  b.finalize(p, bond_damping);
}

void set_bond_youngs_moduli(Model& model, std::vector<BondMaterial>& materials,
                            const std::vector<double>& youngs_moduli, double bond_damping) {
  if (youngs_moduli.size() != materials.size()) {
    throw InputError("calibrate",
                     "got " + std::to_string(youngs_moduli.size()) + " Young's moduli for " +
                         std::to_string(materials.size()) + " bond materials",
                     "give one per bond material");
  }
  for (std::size_t m = 0; m < materials.size(); ++m) {
    if (!(youngs_moduli[m] > 0.0))
      throw InputError("calibrate", "bond Young's modulus must be > 0", "");
    materials[m].youngs_modulus = youngs_moduli[m];
  }
  rederive_bond_stiffness(model, materials, bond_damping);
}

std::vector<double> bond_youngs_moduli(const std::vector<BondMaterial>& materials) {
  std::vector<double> e;
  for (const auto& m : materials) e.push_back(m.youngs_modulus);
  return e;
}

}  // namespace bpm
