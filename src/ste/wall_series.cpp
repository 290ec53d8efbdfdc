#include "ste/wall_series.hpp"

#include <cmath>
#include <string>

#include "contacts/contact_law.hpp"
#include "core/error.hpp"

namespace bpm::ste {
namespace {

constexpr const char* kWhere = "stiffness tensor estimation: walls";

/// F(delta) = c delta^p for one platen's contact set.
struct ContactSet {
  std::size_t particles = 0;
  double c = 0.0;  ///< Hertz: 4/3 E* sum sqrt(R_i); linear: N k_n
  double p = 1.0;  ///< exponent: 1.5 (Hertz) or 1 (linear)

  double overlap(double force) const { return std::pow(force / c, 1.0 / p); }
  double d_overlap(double force) const { return force > 0.0 ? overlap(force) / (p * force) : HUGE_VAL; }
};

ContactSet contact_set(const ParticleStore& particles, const std::vector<std::int32_t>& list,
                       const ContactPairParameters& contact, const char* platen) {
  ContactSet s;
  s.particles = list.size();
  if (list.empty()) throw InputError(kWhere, std::string("no particle touches the ") + platen + " platen", "widen the band or list them");
  // Each contact's F_n(delta) = F_n(1 m) delta^p (contact_law.hpp); against a rigid wall R* = R.
  s.p = contact_law::normal_exponent(contact);
  for (const std::int32_t i : list) {
    s.c += contact_law::linearise(contact, {particles.radius[static_cast<std::size_t>(i)], 0.0, 0.0}, 1.0).force;
  }
  return s;
}

std::vector<std::int32_t> touching(const ParticleStore& p, const Vec3& a, const SampleGeometry& g, double band, bool top) {
  std::vector<std::int32_t> list;
  const double limit = band + 1e-12 * g.length;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double s = dot(p.position[i], a);
    const double gap = top ? g.top - (s + p.radius[i]) : (s - p.radius[i]) - g.bottom;
    if (gap <= limit) list.push_back(static_cast<std::int32_t>(i));
  }
  return list;
}

void check_indices(const std::vector<std::int32_t>& list, std::size_t n) {
  for (const std::int32_t i : list) {
    if (i < 0 || static_cast<std::size_t>(i) >= n) {
      throw InputError(kWhere, "platen particle index " + std::to_string(i) + " is not a particle", "use 0..N-1");
    }
  }
}

}  // namespace

WallSeries wall_series(const ParticleStore& particles, const Vec3& axis, const SampleGeometry& sample,
                       double sample_stiffness, const WallSeriesOptions& o) {
  if (!(o.displacement > 0.0)) throw InputError(kWhere, "the platen displacement must be > 0", "strain * l");
  if (!(sample_stiffness > 0.0)) throw InputError(kWhere, "the sample stiffness is not positive", "check the bonds");
  const bool hertz = o.contact.law == ContactLaw::hertz_mindlin;
  if (!((hertz ? o.contact.e_star : o.contact.k_n) > 0.0)) {
    throw InputError(kWhere, "the platen contact has no normal stiffness", hertz ? "set E* > 0" : "set k_n > 0");
  }
  check_indices(o.bottom_particles, particles.size());
  check_indices(o.top_particles, particles.size());
  const Vec3 a = axis / norm(axis);
  const ContactSet bottom = contact_set(
      particles, o.bottom_particles.empty() ? touching(particles, a, sample, o.band, false) : o.bottom_particles, o.contact, "bottom");
  const ContactSet top = contact_set(
      particles, o.top_particles.empty() ? touching(particles, a, sample, o.band, true) : o.top_particles, o.contact, "top");

  // g(F) = F/K + delta_b(F) + delta_t(F) - w: increasing and concave, g(0) = -w < 0 <= g(K w).
  const double w = o.displacement;
  auto residual = [&](double f) { return f / sample_stiffness + bottom.overlap(f) + top.overlap(f) - w; };
  double lo = 0.0, hi = sample_stiffness * w, f = hi;
  WallSeries r;
  for (r.iterations = 1; r.iterations <= 200; ++r.iterations) {
    const double g = residual(f);
    if (std::abs(g) <= 1e-14 * w) break;
    (g > 0.0 ? hi : lo) = f;
    const double slope = 1.0 / sample_stiffness + bottom.d_overlap(f) + top.d_overlap(f);
    const double next = f - g / slope;
    f = next > lo && next < hi ? next : 0.5 * (lo + hi);
  }
  r.sample_stiffness = sample_stiffness;
  r.displacement = w;
  r.force = f;
  auto platen = [&](const ContactSet& s) {
    PlatenContacts c;
    c.particles = s.particles;
    c.overlap = s.overlap(f);
    c.secant = f / c.overlap;
    c.tangent = s.p * c.secant;  // d(c delta^p)/d delta = p F / delta
    return c;
  };
  r.bottom = platen(bottom);
  r.top = platen(top);
  r.secant = f / w;
  r.tangent = 1.0 / (1.0 / sample_stiffness + 1.0 / r.bottom.tangent + 1.0 / r.top.tangent);
  r.total = o.stiffness == WallStiffness::secant ? r.secant : r.tangent;
  return r;
}

}  // namespace bpm::ste
