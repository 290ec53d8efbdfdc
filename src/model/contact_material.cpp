#include "model/contact_material.hpp"

#include <cmath>
#include <string>

#include "core/error.hpp"

namespace bpm {

namespace {

void validate(const ContactMaterial& m, std::size_t index) {
  const std::string where = "contact material " + std::to_string(index) + (m.name.empty() ? "" : " '" + m.name + "'");
  if (m.law == ContactLaw::hertz_mindlin) {
    if (!(m.youngs_modulus > 0.0) || !std::isfinite(m.youngs_modulus)) {
      throw InputError(where, "Young's modulus must be positive and finite", "give E in Pa");
    }
    if (!(m.poisson_ratio > -1.0 && m.poisson_ratio < 0.5)) {
      throw InputError(where, "Poisson's ratio must lie in (-1, 0.5)");
    }
  } else {
    if (!(m.k_n > 0.0) || !(m.k_t >= 0.0)) {
      throw InputError(where, "the linear law needs k_n > 0 and k_t >= 0", "give them in N/m");
    }
  }
  if (!(m.restitution > 0.0 && m.restitution <= 1.0)) {
    throw InputError(where, "the coefficient of restitution must lie in (0, 1]");
  }
  if (!(m.friction >= 0.0) || !(m.rolling_friction >= 0.0)) {
    throw InputError(where, "friction coefficients must be >= 0");
  }
}

}  // namespace

ContactTable::ContactTable(const ContactModel& model) : n_(static_cast<std::int32_t>(model.materials.size())) {
  for (std::size_t i = 0; i < model.materials.size(); ++i) validate(model.materials[i], i);
  for (const ContactPairRule& r : model.pair_rules) {
    if (r.a < 0 || r.b < 0 || r.a >= n_ || r.b >= n_) {
      throw InputError("contact pair rule", "names a material index outside 0.." + std::to_string(n_ - 1));
    }
  }
  pairs_.resize(static_cast<std::size_t>(n_) * static_cast<std::size_t>(n_));
  for (std::int32_t a = 0; a < n_; ++a) {
    for (std::int32_t b = 0; b < n_; ++b) {
      const ContactMaterial& m1 = model.materials[static_cast<std::size_t>(a)];
      const ContactMaterial& m2 = model.materials[static_cast<std::size_t>(b)];
      const ContactPairRule* rule = nullptr;
      for (const ContactPairRule& r : model.pair_rules) {
        if ((r.a == a && r.b == b) || (r.a == b && r.b == a)) rule = &r;
      }
      ContactPairParameters p;
      if (rule && rule->law) {
        p.law = *rule->law;
      } else if (m1.law == m2.law) {
        p.law = m1.law;
      } else {
        throw InputError("contact materials '" + m1.name + "' and '" + m2.name + "'",
                         "use different contact laws", "give the pair's law in a pair rule");
      }
      if (p.law == ContactLaw::hertz_mindlin) {
        if (!(m1.youngs_modulus > 0.0 && m2.youngs_modulus > 0.0)) {
          throw InputError("contact materials '" + m1.name + "' and '" + m2.name + "'",
                           "a Hertz-Mindlin pair needs Young's modulus and Poisson's ratio on both");
        }
        p.e_star = 1.0 / (contact_rules::inverse_e_star(m1) + contact_rules::inverse_e_star(m2));
        p.g_star = 1.0 / (contact_rules::inverse_g_star(m1) + contact_rules::inverse_g_star(m2));
      } else {
        p.k_n = contact_rules::series(m1.k_n, m2.k_n);
        p.k_t = contact_rules::series(m1.k_t, m2.k_t);
        if (!(p.k_n > 0.0)) {
          throw InputError("contact materials '" + m1.name + "' and '" + m2.name + "'",
                           "a linear pair needs k_n > 0 on both");
        }
      }
      const double e = rule && rule->restitution ? *rule->restitution : 0.5 * (m1.restitution + m2.restitution);
      if (!(e > 0.0 && e <= 1.0)) {
        throw InputError("contact pair rule for '" + m1.name + "' and '" + m2.name + "'",
                         "the coefficient of restitution must lie in (0, 1]");
      }
      p.beta = contact_rules::damping_beta(e);
      p.friction = rule && rule->friction ? *rule->friction : 0.5 * (m1.friction + m2.friction);
      p.rolling_friction =
          rule && rule->rolling_friction ? *rule->rolling_friction : 0.5 * (m1.rolling_friction + m2.rolling_friction);
      p.bonded = rule && rule->bonded ? *rule->bonded : model.bonded;
      p.no_tension = model.no_tension;
      pairs_[static_cast<std::size_t>(a) * static_cast<std::size_t>(n_) + static_cast<std::size_t>(b)] = p;
    }
  }
}

}  // namespace bpm
