#pragma once
/// Contact materials and the rules that turn two of them into the constants of one contact
/// (Jarolin section 2: particle-particle and particle-wall interactions, Hertz-Mindlin after
/// Mindlin & Deresiewicz and Tsuji et al. 1992). A contact material is indexed like the particle
/// materials (ParticleStore::material) and walls name one too (Wall::material), so a particle-wall
/// contact is just another material pair with a rigid partner.
///
/// Pair rules (documented choices):
/// - 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2 and 1/G* = 2(2-nu1)(1+nu1)/E1 + 2(2-nu2)(1+nu2)/E2
///   (Hertz; Mindlin with G = E/(2(1+nu))).
/// - Linear law: k_n and k_t of the pair are the two materials' springs in series,
///   1/k = 1/k1 + 1/k2 (as PFC's ball-stiffness linear model), so two equal materials give k/2.
/// - Restitution e, sliding friction mu and rolling friction mu_r: the arithmetic mean of the two
///   materials unless a ContactPairRule gives them for the pair. (The mean keeps a symmetric,
///   order-independent rule; calibrated values belong in a pair rule.)
/// - Both materials must use the same law unless a pair rule names it.
/// - Per contact (not stored here): R* = R1R2/(R1+R2), m* = m1m2/(m1+m2), I* = I1I2/(I1+I2);
///   against a rigid wall R* = R, m* = m, I* = I.
#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

namespace bpm {

enum class ContactLaw : std::uint8_t {
  hertz_mindlin,  ///< F_n = 4/3 E* sqrt(R*) delta^1.5, k_t = 8 G* sqrt(R* delta), Tsuji damping
  linear,         ///< spring-dashpot: F_n = k_n delta, k_t constant, damping from e
};

/// What a bond does to the contact of the pair it joins while it is intact (Jarolin section 2:
/// "bonds can replace the particle-particle interaction or they can superimpose" it). In both cases
/// the contact law acts only while the particles physically overlap (Chen section 2.1: PBM's
/// non-bonded component), and a broken bond hands the pair to the contact law.
enum class BondedContacts : std::uint8_t {
  superimpose,  ///< contact and bond act in parallel
  replace,      ///< no contact force while the bond is intact
};

struct ContactMaterial {
  std::string name;
  ContactLaw law = ContactLaw::hertz_mindlin;
  double youngs_modulus = 0.0;  ///< E, Pa (Hertz-Mindlin)
  double poisson_ratio = 0.0;   ///< nu (Hertz-Mindlin)
  double k_n = 0.0;             ///< N/m (linear law)
  double k_t = 0.0;             ///< N/m (linear law)
  double restitution = 1.0;     ///< e in (0, 1]; 1 is elastic
  double friction = 0.0;        ///< mu, sliding (Coulomb)
  double rolling_friction = 0.0;  ///< mu_r, dimensionless (torque mu_r R* F_n)
};

/// Overrides for one (unordered) pair of contact materials; unset fields follow the pair rules.
struct ContactPairRule {
  std::int32_t a = 0, b = 0;
  std::optional<ContactLaw> law;
  std::optional<double> restitution, friction, rolling_friction;
  std::optional<BondedContacts> bonded;
};

/// The constants of one material pair, evaluated once (the kernel never branches on materials,
/// only on `law`).
struct ContactPairParameters {
  ContactLaw law = ContactLaw::hertz_mindlin;
  double e_star = 0.0;  ///< E*, Pa
  double g_star = 0.0;  ///< G*, Pa
  double k_n = 0.0;     ///< N/m (linear)
  double k_t = 0.0;     ///< N/m (linear)
  double beta = 0.0;    ///< Tsuji: ln e / sqrt(ln^2 e + pi^2), <= 0 (0: elastic)
  double friction = 0.0;
  double rolling_friction = 0.0;
  BondedContacts bonded = BondedContacts::superimpose;
  bool no_tension = false;  ///< clamp the total normal force at zero (contact_law.hpp)
};

/// Everything the particle contacts of a model need. Particle-particle contacts are on when
/// `particle_particle` is set and there are materials; walls need materials as well.
struct ContactModel {
  bool particle_particle = false;
  std::vector<ContactMaterial> materials;  ///< indexed by ParticleStore::material and Wall::material
  std::vector<ContactPairRule> pair_rules;
  BondedContacts bonded = BondedContacts::superimpose;  ///< default for pairs without a rule
  /// Verlet skin, m: pairs closer than this (surface gap) are listed; the list is rebuilt once a
  /// particle has moved half of it. <= 0 picks 0.1 * (largest radius).
  double skin = 0.0;
  /// false (default, as Tsuji et al.): the normal dashpot may pull near the end of a rebound and
  /// the rebound speed ratio is e. true: the total normal force is clamped at zero (no pulling);
  /// the rebound is then faster than e. See contacts/contact_law.hpp.
  bool no_tension = false;

  bool active() const { return particle_particle && !materials.empty(); }
};

namespace contact_rules {

/// Tsuji et al. (1992) damping exponent: beta = ln e / sqrt(ln^2 e + pi^2); 0 for e >= 1, and -1
/// in the limit e -> 0 (critical damping of the linear analogue).
inline double damping_beta(double e) {
  if (e >= 1.0) return 0.0;
  if (e <= 0.0) return -1.0;
  const double l = std::log(e);
  return l / std::sqrt(l * l + std::numbers::pi * std::numbers::pi);
}

/// 1/E* of one side: (1 - nu^2)/E.
inline double inverse_e_star(const ContactMaterial& m) {
  return (1.0 - m.poisson_ratio * m.poisson_ratio) / m.youngs_modulus;
}
/// 1/G* of one side: 2 (2 - nu)(1 + nu)/E = (2 - nu)/G.
inline double inverse_g_star(const ContactMaterial& m) {
  return 2.0 * (2.0 - m.poisson_ratio) * (1.0 + m.poisson_ratio) / m.youngs_modulus;
}

inline double series(double k1, double k2) { return k1 > 0.0 && k2 > 0.0 ? k1 * k2 / (k1 + k2) : 0.0; }

/// Reduced value x1 x2/(x1 + x2) (R*, m*, I*).
inline double reduced(double x1, double x2) { return x1 * x2 / (x1 + x2); }

}  // namespace contact_rules

/// Pair constants for every ordered pair of materials (n x n, symmetric), built once.
class ContactTable {
 public:
  ContactTable() = default;
  /// Validates the materials and rules (InputError naming the material or pair) and evaluates all
  /// pairs.
  explicit ContactTable(const ContactModel& model);

  std::int32_t size() const { return n_; }
  const ContactPairParameters& operator()(std::int32_t a, std::int32_t b) const { return pairs_[index(a, b)]; }
  /// The pair of materials a and b as one number, for loops that keep it per contact.
  std::int32_t index(std::int32_t a, std::int32_t b) const { return a * n_ + b; }
  const ContactPairParameters& operator[](std::int32_t index) const { return pairs_[static_cast<std::size_t>(index)]; }

 private:
  std::int32_t n_ = 0;
  std::vector<ContactPairParameters> pairs_;
};

}  // namespace bpm
