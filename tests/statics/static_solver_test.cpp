// solve_linear_static (src/dem/static_solver.*) on Chen's reference cantilever (case 1, Table 4).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "statics/static_solver.hpp"
#include "verify/cantilever.hpp"

namespace bpm {
namespace {

const verify::CantileverSpec& case1() {
  static const verify::CantileverSpec spec = verify::cantilever_case(1).front();
  return spec;
}

TEST(StaticSolverTest, TbbmCantileverMatchesTimoshenkoTipDeflection) {
  // Chen Eq. 29 with F = 100 kN, L0 = 4 m, r = 0.2 m, E = 200 GPa, nu = 0.3 and f_s = 10/9:
  // F L^3/(3EI) + 10 F L/(9 G A) = 8.488264e-3 + 4.597876e-5 = 8.534242e-3 m (Table 4: 8.534 mm).
  // The TBBM element is exact for a tip-loaded Timoshenko beam, so the discrete answer is that
  // number at every node, not only at the tip.
  const Model model = verify::build_cantilever(case1(), "tbbm", 0.0);
  const StaticSolution s = solve_linear_static(model);
  const double tip = -s.displacement.back().y;
  EXPECT_NEAR(tip, 8.534242e-3, 1e-6 * 8.534242e-3);
  const double r = 0.2, E = 200e9, G = E / 2.6, F = 1e5;
  const double A = std::numbers::pi * r * r, I = 0.25 * std::numbers::pi * std::pow(r, 4);
  for (std::size_t i = 0; i < s.displacement.size(); ++i) {
    const double x = model.particles.position[i].x;
    const double exact =
        F * x * x / (6.0 * E * I) * (12.0 - x) + 10.0 * F * x / (9.0 * G * A);  // Eq. 28
    EXPECT_NEAR(-s.displacement[i].y, exact, 1e-9 * 8.534242e-3) << "node " << i;
    EXPECT_NEAR(s.displacement[i].x, 0.0, 1e-15);
    EXPECT_NEAR(s.displacement[i].z, 0.0, 1e-15);
  }
  // Bending rotation at the tip: -F L^2 / (2 E I) about z (the load is along -y).
  EXPECT_NEAR(s.rotation.back().z, -F * 16.0 / (2.0 * E * I), 1e-9 * F * 16.0 / (2.0 * E * I));
  EXPECT_EQ(s.displacement.front().y, 0.0);
}

TEST(StaticSolverTest, EbbmCantileverMatchesEulerBernoulli) {
  const Model model = verify::build_cantilever(case1(), "ebbm", 0.0);
  const double tip = -solve_linear_static(model).displacement.back().y;
  EXPECT_NEAR(tip, verify::timoshenko_deflection(case1(), 4.0, false),
              1e-9 * tip);  // 8.488 mm, Table 4
}

TEST(StaticSolverTest, ThrowsWhenNothingIsFixed) {
  Model model = verify::build_cantilever(case1(), "tbbm", 0.0);
  model.particles.translation_free[0] = {1, 1, 1};
  model.particles.rotation_free[0] = {1, 1, 1};
  EXPECT_THROW(solve_linear_static(model), InputError);
  // Still singular with only the translations held: the beam can spin about its own axis.
  model.particles.translation_free[0] = {0, 0, 0};
  EXPECT_THROW(solve_linear_static(model), InputError);
}

}  // namespace
}  // namespace bpm
