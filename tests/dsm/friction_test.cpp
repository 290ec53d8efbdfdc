// Friction at the contacts in the nonlinear DSM (the static core's tangential springs with slip
// and history), on the small cylinder example (847 particles, bonds superimposed
// on Hertz-Mindlin contacts with mu = 0.3): slip can only soften the sample, more of it the lower
// mu, and a mu no contact reaches gives back the no-slip answer.
#include <gtest/gtest.h>

#include <string>

#include "compress/platen_loading.hpp"
#include "dsm/dsm_nonlinear.hpp"
#include "scenario/scenario.hpp"

namespace bpm {
namespace {

double nonlinear_stiffness(double friction) {
  Scenario s = load_scenario(std::string(BPMKIT_EXAMPLES_DIR) +
                             "/04_compression/small_cylinder/compression.yaml");
  for (ContactMaterial& m : s.model.contacts.materials) {
    if (m.name == "grain") m.friction = friction;
  }
  return solve_dsm_nonlinear(s.model, make_platen_loading(s.model, *s.compression)).stiffness;
}

TEST(DsmNonlinearFriction, SlipSoftensTheSampleMoreAtLowerFriction) {
  const double no_slip = nonlinear_stiffness(1e6), grains = nonlinear_stiffness(0.3),
               slippery = nonlinear_stiffness(0.05), frictionless = nonlinear_stiffness(0.0),
               huge = nonlinear_stiffness(1e3);
  RecordProperty("K_no_slip", std::to_string(no_slip));
  RecordProperty("K_mu_0.3", std::to_string(grains));
  // Lowering the grains' friction lowers the grain-platen pair's too (its mean with steel's 0).
  EXPECT_LT(grains, (1.0 - 3e-3) * no_slip);
  EXPECT_LT(slippery, (1.0 - 5e-4) * grains);
  EXPECT_LT(frictionless, slippery);
  EXPECT_NEAR(huge, no_slip, 1e-6 * no_slip);
}

}  // namespace
}  // namespace bpm
