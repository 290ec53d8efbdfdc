// The contact stability limit (contact_time_step.hpp): the Rayleigh step of a known material, the
// Gershgorin bound lies below the exact single-contact limit 2/omega and above a tenth of it, an
// impact run at the bound stays stable and conserves energy, and combine_time_steps adds the
// squared frequencies.
#include <gtest/gtest.h>

#include <cmath>

#include "contact_helpers.hpp"
#include "dem/contact_time_step.hpp"
#include "dem/simulation.hpp"

namespace bpm {
namespace {

Model sphere_on_floor(double v) {
  Model model;
  model.particles.add(0, {0.0, 0.0, 1e-3 + 1e-7}, 1e-3, 2500.0);
  model.particles.velocity[0] = {0.0, 0.0, -v};
  model.contacts.materials = {test::hertz_material(1e8, 0.3, 1.0)};
  model.walls.push_back(test::plane({}, {0.0, 0.0, 1.0}, 0));
  model.finalize();
  return model;
}

TEST(ContactTimeStepTest, RayleighStepOfAKnownMaterial) {
  Model model = sphere_on_floor(0.0);
  // pi R sqrt(rho/G) / (0.1631 nu + 0.8766), G = E / (2 (1 + nu)).
  const double g = 1e8 / 2.6;
  const double expected = std::numbers::pi * 1e-3 * std::sqrt(2500.0 / g) / (0.1631 * 0.3 + 0.8766);
  EXPECT_NEAR(contact_time_step(model).rayleigh / expected, 1.0, 1e-12);
  EXPECT_TRUE(std::isinf(contact_time_step(Model{}).critical));  // nothing to bound
}

TEST(ContactTimeStepTest, BoundBracketsTheSingleContactLimitAndIsStable) {
  const double v = 1.0;
  Model model = sphere_on_floor(v);
  const double mass = model.particles.mass[0];
  const double e_star = 1e8 / (2.0 * (1.0 - 0.09));
  const double delta_max = test::hertz_max_overlap(mass, 1e-3, e_star, v);
  const ContactTimeStep limit = contact_time_step(model, delta_max / 1e-3, 1);
  // Exact limit of the normal oscillation alone at the largest overlap: 2 / sqrt(k_n / m).
  const double k_n = 2.0 * e_star * std::sqrt(1e-3 * delta_max);
  const double exact = 2.0 / std::sqrt(k_n / mass);
  EXPECT_LT(limit.critical, exact);
  EXPECT_GT(limit.critical, 0.1 * exact);
  EXPECT_EQ(limit.limiting_particle, 0);
  Simulation sim(model, 0.9 * limit.critical);
  const double e0 = sim.energies().kinetic;
  for (int s = 0; s < 2000; ++s) sim.step();
  EXPECT_GT(model.particles.velocity[0].z, 0.0);  // bounced
  // Coarse steps (a handful per contact): energy within a few per cent, no blow-up.
  EXPECT_NEAR(sim.energies().kinetic / e0, 1.0, 0.05);
}

TEST(ContactTimeStepTest, CombineAddsSquaredFrequencies) {
  EXPECT_NEAR(combine_time_steps(3.0, 4.0), 12.0 / 5.0, 1e-15);
  EXPECT_EQ(combine_time_steps(2.0, std::numeric_limits<double>::infinity()), 2.0);
}

}  // namespace
}  // namespace bpm
