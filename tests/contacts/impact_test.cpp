// Normal impacts against Hertz theory: a sphere on a wall and two unequal spheres of different
// materials. Elastic (e = 1): the contact duration equals the Hertz duration
// 2.868 (m*^2/(R* E*^2 v))^(1/5) and kinetic plus contact energy is conserved. Damped: the rebound
// speed ratio equals the input restitution (Tsuji damping) and, for the linear spring-dashpot, the
// closed form of the damped oscillator.
#include <gtest/gtest.h>

#include <cmath>

#include "contact_helpers.hpp"
#include "dem/simulation.hpp"

namespace bpm {
namespace {

struct Impact {
  double duration = 0.0;     ///< s, steps with a contact force times dt
  double restitution = 0.0;  ///< relative normal speed after / before
  double max_energy_error = 0.0;  ///< max |E(t) - E(0)| / E(0), E = kinetic + contact
  double max_overlap = 0.0;
};

/// Runs until the bodies have separated; `touching` says whether there is a contact force,
/// `normal_speed` returns the relative normal speed (approach negative), `overlap` the overlap.
template <class Touching, class Speed, class Overlap>
Impact run_impact(Model& model, double dt, double v_before, Touching touching, Speed normal_speed, Overlap overlap) {
  Simulation sim(model, dt);
  const double e0 = sim.energies().kinetic;
  Impact out;
  bool started = false;
  for (int s = 0; s < 100000; ++s) {
    sim.step();
    const Energies e = sim.energies();
    out.max_energy_error = std::max(out.max_energy_error, std::abs(e.kinetic + e.contact - e0) / e0);
    out.max_overlap = std::max(out.max_overlap, overlap());
    if (touching()) {
      started = true;
      out.duration += dt;
    } else if (started && overlap() < 0.0) {
      break;
    }
  }
  out.restitution = normal_speed() / v_before;
  return out;
}

/// A sphere (R = 1 mm, 2500 kg/m^3) falling at v onto a plane of the same material (E* =
/// E/(2(1 - nu^2)), R* = R, m* = m), no gravity.
Impact sphere_on_wall(const ContactMaterial& material, double v, double dt_fraction, bool no_tension = false) {
  Model model;
  const double r = 1e-3;
  model.particles.add(0, {0.0, 0.0, r + 1e-7}, r, 2500.0);
  model.particles.velocity[0] = {0.0, 0.0, -v};
  model.contacts.materials = {material};
  model.contacts.no_tension = no_tension;
  model.walls.push_back(test::plane({}, {0.0, 0.0, 1.0}, 0));
  model.finalize();
  const ParticleStore& p = model.particles;
  const double e_star = 1.0 / (2.0 * (1.0 - material.poisson_ratio * material.poisson_ratio) / material.youngs_modulus);
  const double t_c = material.law == ContactLaw::hertz_mindlin ? test::hertz_duration(p.mass[0], r, e_star, v)
                                                                : test::linear_impact(0.5 * material.k_n, p.mass[0], 1.0).duration;
  const double dt = dt_fraction * t_c;
  return run_impact(
      model, dt, v, [&] { return model.walls[0].force.z != 0.0; }, [&] { return p.velocity[0].z; },
      [&] { return r - p.position[0].z; });
}

TEST(ImpactTest, ElasticSphereOnWallHasHertzDurationAndConservesEnergy) {
  const ContactMaterial m = test::hertz_material(1e8, 0.3, 1.0);
  for (const double v : {0.1, 1.0}) {
    const Impact impact = sphere_on_wall(m, v, 1.0 / 2000.0);
    const double mass = 2500.0 * 4.0 / 3.0 * std::numbers::pi * 1e-9;
    const double e_star = m.youngs_modulus / (2.0 * (1.0 - 0.09));
    const double t_c = test::hertz_duration(mass, 1e-3, e_star, v);
    // The duration is resolved to one step (t_c / 2000), the integrator error is O((w dt)^2).
    EXPECT_NEAR(impact.duration / t_c, 1.0, 0.01) << "v = " << v;
    EXPECT_NEAR(impact.max_overlap / test::hertz_max_overlap(mass, 1e-3, e_star, v), 1.0, 1e-3);
    EXPECT_NEAR(impact.restitution, 1.0, 1e-4);
    EXPECT_LT(impact.max_energy_error, 1e-4);
    RecordProperty("duration_ratio_v" + std::to_string(v), std::to_string(impact.duration / t_c));
    RecordProperty("energy_error_v" + std::to_string(v), std::to_string(impact.max_energy_error));
  }
}

TEST(ImpactTest, TsujiDampingGivesTheInputRestitution) {
  for (const double e : {0.3, 0.5, 0.7, 0.9}) {
    for (const double v : {0.1, 1.0}) {
      const Impact impact = sphere_on_wall(test::hertz_material(1e8, 0.3, e), v, 1.0 / 2000.0);
      // Tsuji's beta is exact for the linear spring-dashpot; on the Hertz spring (stiffness growing
      // as sqrt(delta)) with the factor 2 sqrt(5/6) it is an approximation, found here to within
      // 0.03 % for e in [0.3, 0.9] and the same for every speed. 1 % leaves room for that model
      // error; the integrator adds < 1e-4 at dt = t_c/2000.
      EXPECT_NEAR(impact.restitution, e, 0.01 * e) << "e = " << e << ", v = " << v;
      RecordProperty("restitution_e" + std::to_string(e), std::to_string(impact.restitution));
    }
  }
}

TEST(ImpactTest, NoTensionMakesTheReboundFasterThanTsuji) {
  // Clamping the normal force at zero lets the sphere leave with the speed it has when the force
  // vanishes, before the overlap closes: the dashpot can no longer pull it back.
  for (const double e : {0.3, 0.7}) {
    const ContactMaterial m = test::hertz_material(1e8, 0.3, e);
    const Impact pulled = sphere_on_wall(m, 1.0, 1.0 / 2000.0, false);
    const Impact clamped = sphere_on_wall(m, 1.0, 1.0 / 2000.0, true);
    EXPECT_GT(clamped.restitution, pulled.restitution + 0.01) << "e = " << e;
    EXPECT_LT(clamped.duration, pulled.duration) << "e = " << e;
  }
}

TEST(ImpactTest, TsujiRestitutionIsIndependentOfSpeed) {
  const ContactMaterial m = test::hertz_material(1e8, 0.3, 0.6);
  const double slow = sphere_on_wall(m, 0.05, 1.0 / 2000.0).restitution;
  const double fast = sphere_on_wall(m, 2.0, 1.0 / 2000.0).restitution;
  // Tsuji et al. 1992: damping ~ sqrt(S_n m*) makes the equation of motion scale-free in v.
  EXPECT_NEAR(slow, fast, 1e-3);
}

TEST(ImpactTest, TwoUnequalSpheresOfDifferentMaterials) {
  for (const double e : {1.0, 0.6}) {
    Model model;
    const double r1 = 1e-3, r2 = 1.5e-3, v = 0.5;
    const Vec3 dir = Vec3{1.0, 1.0, 0.3} / norm(Vec3{1.0, 1.0, 0.3});
    model.particles.add(0, {0.01, 0.02, 0.0}, r1, 2500.0, 0);
    model.particles.add(1, Vec3{0.01, 0.02, 0.0} + (r1 + r2 + 1e-7) * dir, r2, 7800.0, 1);
    model.particles.velocity[0] = 0.5 * v * dir;
    model.particles.velocity[1] = -0.5 * v * dir;
    model.contacts.particle_particle = true;
    model.contacts.materials = {test::hertz_material(1e8, 0.3, e), test::hertz_material(3e8, 0.2, e)};
    model.finalize();
    const ParticleStore& p = model.particles;
    const double m_star = p.mass[0] * p.mass[1] / (p.mass[0] + p.mass[1]);
    const double r_star = r1 * r2 / (r1 + r2);
    const double e_star = 1.0 / ((1.0 - 0.09) / 1e8 + (1.0 - 0.04) / 3e8);  // 1/E* = sum (1-nu^2)/E
    const double t_c = test::hertz_duration(m_star, r_star, e_star, v);
    const Vec3 momentum_before = p.mass[0] * p.velocity[0] + p.mass[1] * p.velocity[1];
    auto normal_speed = [&] { return dot(p.velocity[1] - p.velocity[0], dir); };
    auto overlap = [&] { return r1 + r2 - norm(p.position[1] - p.position[0]); };
    // No gravity and no bonds: a particle carries a force only while it touches the other.
    const Impact impact =
        run_impact(model, t_c / 2000.0, v, [&] { return norm2(p.force[0]) > 0.0; }, normal_speed, overlap);
    if (e == 1.0) {
      EXPECT_NEAR(impact.duration / t_c, 1.0, 0.01);
      EXPECT_NEAR(impact.max_overlap / test::hertz_max_overlap(m_star, r_star, e_star, v), 1.0, 1e-3);
      EXPECT_NEAR(impact.restitution, 1.0, 1e-4);
      EXPECT_LT(impact.max_energy_error, 1e-4);
    } else {
      EXPECT_NEAR(impact.restitution, e, 0.01 * e);
    }
    // Momentum is exchanged in equal and opposite amounts.
    const Vec3 momentum = p.mass[0] * p.velocity[0] + p.mass[1] * p.velocity[1];
    EXPECT_LT(norm(momentum - momentum_before), 1e-12 * (p.mass[0] + p.mass[1]) * v);
  }
}

TEST(ImpactTest, LinearSpringDashpotRestitutionMatchesTheDampedOscillator) {
  const double k_n = 2000.0;  // per material: the pair with the wall is 1000 N/m in series
  const double mass = 2500.0 * 4.0 / 3.0 * std::numbers::pi * 1e-9;
  for (const double e : {0.3, 0.6, 0.9, 1.0}) {
    // The free damped oscillator with c = 2 zeta sqrt(k m*), zeta = -beta: the rebound speed ratio
    // is exactly e and the contact lasts pi/w_d. dt = t_c/4000: integrator error O((w dt)^2) ~ 1e-6.
    const Impact impact = sphere_on_wall(test::linear_material(k_n, 0.0, e), 0.3, 1.0 / 4000.0);
    const double l = std::log(e);
    const double zeta = -l / std::sqrt(l * l + std::numbers::pi * std::numbers::pi);
    const double t_c = std::numbers::pi / (std::sqrt(0.5 * k_n / mass) * std::sqrt(1.0 - zeta * zeta));
    EXPECT_NEAR(impact.restitution, e, 1e-3) << "e = " << e;
    EXPECT_NEAR(impact.duration / t_c, 1.0, 1e-3) << "e = " << e;

    // No tension: the closed form of the clamped oscillator (contact_helpers.hpp).
    const Impact clamped = sphere_on_wall(test::linear_material(k_n, 0.0, e), 0.3, 1.0 / 4000.0, true);
    const test::LinearImpact exact = test::linear_impact(0.5 * k_n, mass, e);
    EXPECT_NEAR(clamped.restitution, exact.restitution, 1e-3) << "e = " << e;
    EXPECT_NEAR(clamped.duration / exact.duration, 1.0, 1e-3) << "e = " << e;
    if (e < 1.0) {
      EXPECT_GT(exact.restitution, e + 0.001);
    }
  }
}

}  // namespace
}  // namespace bpm
