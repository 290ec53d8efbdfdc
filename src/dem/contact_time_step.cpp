#include "dem/contact_time_step.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "contacts/contact_law.hpp"
#include "core/error.hpp"
#include "dem/time_step.hpp"

namespace bpm {

ContactTimeStep contact_time_step(const Model& model, double max_overlap_ratio, int coordination) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  ContactTimeStep out{kInf, kInf, -1};
  const ContactModel& cm = model.contacts;
  const bool pairs = cm.active();
  if (cm.materials.empty() || (!pairs && model.walls.empty())) return out;
  const ContactTable table(cm);
  const ParticleStore& p = model.particles;
  double m_min = kInf;
  for (const double m : p.mass) m_min = std::min(m_min, m);
  const double root = std::sqrt(2.5);  // R/sqrt(I/m) for a solid sphere
  for (std::size_t i = 0; i < p.size(); ++i) {
    const std::int32_t mat = p.material[i];
    if (mat < 0 || mat >= table.size()) continue;
    const double r = p.radius[i], m = p.mass[i];
    const double delta = max_overlap_ratio * r;
    double row = 0.0, zeta = 0.0;
    auto consider = [&](const ContactPairParameters& c, double r_star, double m_star) {
      // Stiffness as dF/d delta: for Hertz 2 E* sqrt(R* delta) = S_n (Tsuji's S_n).
      const contact_law::Linearised s = contact_law::linearise(c, {r_star, m_star, 0.0}, delta);
      row = std::max(row, std::max(s.normal_tangent + (1.0 + root) * s.tangential, (2.5 + root) * s.tangential));
      zeta = std::max(zeta, -c.beta);
    };
    if (pairs) consider(table(mat, mat), 0.5 * r, 0.5 * m);  // like particle: R* = R/2
    for (const Wall& w : model.walls) {
      if (w.material >= 0 && w.material < table.size()) consider(table(mat, w.material), r, m);
    }
    const double omega = std::sqrt(coordination * row * (1.0 / m + 1.0 / std::sqrt(m * m_min)));
    const double dt = (std::sqrt(1.0 + zeta * zeta) - zeta) * 2.0 / omega;
    if (dt < out.critical) {
      out.critical = dt;
      out.limiting_particle = static_cast<std::int64_t>(i);
    }
    const ContactMaterial& cmat = cm.materials[static_cast<std::size_t>(mat)];
    if (cmat.law == ContactLaw::hertz_mindlin) {
      const double rho = m / (4.0 / 3.0 * std::numbers::pi * r * r * r);
      const double g = cmat.youngs_modulus / (2.0 * (1.0 + cmat.poisson_ratio));
      out.rayleigh = std::min(out.rayleigh, std::numbers::pi * r * std::sqrt(rho / g) /
                                                (0.1631 * cmat.poisson_ratio + 0.8766));
    }
  }
  return out;
}

double combine_time_steps(double a, double b) {
  const double inv = (std::isfinite(a) ? 1.0 / (a * a) : 0.0) + (std::isfinite(b) ? 1.0 / (b * b) : 0.0);
  return inv > 0.0 ? 1.0 / std::sqrt(inv) : std::numeric_limits<double>::infinity();
}

double stability_limit(const Model& model) {
  const bool contacts = !model.contacts.materials.empty();
  double bonds = std::numeric_limits<double>::infinity();
  try {
    bonds = critical_time_step(model).critical;
  } catch (const InputError&) {
    if (!contacts) throw;  // the contacts may bound it alone
  }
  return contacts ? combine_time_steps(bonds, contact_time_step(model).critical) : bonds;
}

}  // namespace bpm
