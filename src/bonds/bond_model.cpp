#include "bonds/bond_model.hpp"

#include <array>
#include <numbers>
#include <string>

#include "core/error.hpp"

namespace bpm {
namespace {

double area(double r) { return std::numbers::pi * r * r; }            // A_b, Chen Eq. 23
double second_moment(double r) { return 0.25 * std::numbers::pi * r * r * r * r; }  // I_b, Eq. 24

double normal_stiffness(const BondMaterial& m, const BondGeometry& g) {
  return m.youngs_modulus * area(g.radius) / g.length;  // k_n = E_b pi r_b^2 / L_b (Table 9)
}

double euler_bernoulli_shear(const BondMaterial& m, const BondGeometry& g) {
  return 12.0 * m.youngs_modulus * second_moment(g.radius) /
         (g.length * g.length * g.length);  // Chen Eq. 26
}

double timoshenko_shear(const BondMaterial& m, const BondGeometry& g) {  // Chen Eq. 18
  return euler_bernoulli_shear(m, g) / (1.0 + timoshenko_phi(g.radius, g.length, m.poisson_ratio));
}

/// The model's own k_s unless the user overrides it (Chen case 5).
double shear_or_override(const BondMaterial& m, const BondGeometry& g, double model_value) {
  switch (m.shear_override) {
    case ShearOverride::value: return m.shear_stiffness;
    case ShearOverride::euler_bernoulli: return euler_bernoulli_shear(m, g);
    case ShearOverride::timoshenko: return timoshenko_shear(m, g);
    case ShearOverride::none: break;
  }
  return model_value;
}

/// Beam models share k_n, k_ben = 0.25 k_n r_b^2 = E I / L and k_tor = 0.25 k_n r_b^2 / (1 + nu)
/// = G J / L (Chen Table 9); only k_s differs.
BondStiffness beam(const BondMaterial& m, const BondGeometry& g, double k_s) {
  const double k_n = normal_stiffness(m, g);
  const double r2 = g.radius * g.radius;
  return {k_n, shear_or_override(m, g, k_s), 0.25 * k_n * r2 / (1.0 + m.poisson_ratio), 0.25 * k_n * r2};
}

/// Parallel bond (Chen Table 1): k_s = k_n / kappa, k_tor = 0.5 k_s r_b^2, k_ben = 0.25 k_n r_b^2.
BondStiffness parallel_bond(const BondMaterial& m, const BondGeometry& g, double kappa) {
  const double k_n = normal_stiffness(m, g);
  const double k_s = shear_or_override(m, g, k_n / kappa);
  const double r2 = g.radius * g.radius;
  return {k_n, k_s, 0.5 * k_s * r2, 0.25 * k_n * r2};
}

double brendel_kappa(const BondMaterial& m) { return 2.0 * (1.0 + m.poisson_ratio); }  // Eq. 8

BondStiffness pbm_rule(const BondMaterial& m, const BondGeometry& g) {
  return parallel_bond(m, g, m.kappa.value_or(brendel_kappa(m)));
}
BondStiffness brendel_rule(const BondMaterial& m, const BondGeometry& g) {
  return parallel_bond(m, g, brendel_kappa(m));
}
BondStiffness ebbm_rule(const BondMaterial& m, const BondGeometry& g) {
  return beam(m, g, euler_bernoulli_shear(m, g));
}
BondStiffness tbbm_rule(const BondMaterial& m, const BondGeometry& g) {
  return beam(m, g, timoshenko_shear(m, g));
}
BondStiffness obermayr_rule(const BondMaterial& m, const BondGeometry& g) {
  // k_s = alpha_s G_b A_b / L_b = alpha_s k_n / (2(1 + nu)) (Chen Eq. 45). Obermayr's model is a
  // beam model, so it takes the beam centre and the beam twisting stiffness.
  const double alpha_s = m.shear_coefficient.value_or(1.0);
  return beam(m, g, alpha_s * normal_stiffness(m, g) / brendel_kappa(m));
}

constexpr std::array<BondModelInfo, 5> kModels{{
    {"pbm", ContactPointRule::gap_centre, pbm_rule,
     "parallel bond (Potyondy-Cundall, Chen Table 1); kappa = k_n/k_s, default 2(1+nu)"},
    {"brendel", ContactPointRule::gap_centre, brendel_rule,
     "parallel bond with kappa = 2(1+nu) fixed (Brendel et al., Chen Eq. 8)"},
    {"ebbm", ContactPointRule::beam_centre, ebbm_rule,
     "Euler-Bernoulli beam bond (Chen Table 9, k_s from Eq. 26)"},
    {"tbbm", ContactPointRule::beam_centre, tbbm_rule,
     "Timoshenko beam bond (Chen Table 6/9, k_s from Eq. 18 and 25)"},
    {"obermayr", ContactPointRule::beam_centre, obermayr_rule,
     "Obermayr beam bond, k_s = alpha_s k_n / (2(1+nu)) (Chen Eq. 45), shear_coefficient alpha_s"},
}};

}  // namespace

double timoshenko_phi(double radius, double length, double poisson_ratio) {
  return 20.0 * radius * radius * (1.0 + poisson_ratio) / (3.0 * length * length);
}

std::span<const BondModelInfo> bond_models() { return kModels; }

const BondModelInfo& find_bond_model(std::string_view key, std::string_view where) {
  std::string keys;
  for (const auto& model : kModels) {
    if (model.key == key) return model;
    keys += (keys.empty() ? "" : ", ") + std::string(model.key);
  }
  throw InputError(std::string(where), "unknown bond model '" + std::string(key) + "'",
                   "use one of: " + keys);
}

BondConstants make_bond_constants(const BondMaterial& material, const BondGeometry& geometry) {
  const BondModelInfo& model = find_bond_model(material.model);
  const double offset = model.contact_point == ContactPointRule::gap_centre
                            ? 0.5 * (geometry.radius_alpha - geometry.radius_beta)  // Chen Eq. 1-2
                            : 0.0;                                                   // Chen Eq. 44
  return {model.stiffness(material, geometry), offset};
}

}  // namespace bpm
