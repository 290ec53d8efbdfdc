// The sample stiffness models: the layered springs-in-series model (Jarolin 4.2) against the
// uniform K = E A / l and the series formula for two stacked blocks, and the platens in series
// (Jarolin 3.2.3) against their closed forms.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "ste/stiffness_tensor_estimation.hpp"
#include "ste_helpers.hpp"

namespace bpm {
namespace {

using ste::SteOptions;
using ste::SteResult;

constexpr double kN = 1e6, kS = 3e5;

/// Two blocks stacked along z: bonds starting in rows below `split` have k_n = kN, the others
/// `ratio` kN (shear stiffness scaled alike).
Model two_blocks(const test::Lattice& g, int split, double ratio) {
  return test::lattice_model(g, [&](int, int, int k, int) {
    const double f = k < split ? 1.0 : ratio;
    return BondStiffness{f * kN, f * kS, 1e-3, 1e-3};
  });
}

// A sample of constant cross-section: when its layers are alike the series of layers is the
// uniform E A / l. With every particle following the average strain (affine) only the outer half
// bonds make the end layers softer (3/4): within 2 % for 10 layers. With the fluctuations
// (Jarolin Eq. 32) the particles of the loaded end faces relax like a free surface (a face
// particle keeps ~15 % of its C_33 here), so the end layers are softer still and the series,
// which weights them more, gives ~10 % less than the uniform model for this 20-row lattice.
TEST(LayeredStiffness, ConstantCrossSectionEqualsTheUniformModel) {
  const test::Lattice g{8, 8, 20, 1e-3};
  const Model model = test::lattice_model(g, kN, kS);
  SteOptions o;
  o.layered = true;
  o.fluctuation = ste::Fluctuation::affine;
  const SteResult affine = ste::estimate_stiffness(model, o);
  ASSERT_TRUE(affine.layered);
  EXPECT_NEAR(affine.layered->stiffness / affine.stiffness_uniform, 1.0, 0.02);

  o.fluctuation = ste::Fluctuation::paper;
  const SteResult r = ste::estimate_stiffness(model, o);
  EXPECT_EQ(r.layered->layers.size(), 10u);  // 20 rows, layers of 2 diameters
  EXPECT_NEAR(r.layered->height * 10.0, r.sample.length, 1e-12);
  std::size_t particles = 0;
  double compliance = 0.0;
  for (const ste::Layer& l : r.layered->layers) {
    EXPECT_EQ(l.particles, 128u);
    EXPECT_NEAR(l.area / r.sample.area, 1.0, 2e-3);  // sum V / h: the clipped cross-section
    particles += l.particles;
    compliance += 1.0 / l.stiffness;
  }
  EXPECT_EQ(particles, r.particles);
  EXPECT_NEAR(r.layered->stiffness * compliance, 1.0, 1e-12);
  const auto& layers = r.layered->layers;
  for (std::size_t k = 2; k + 2 < layers.size(); ++k) {
    EXPECT_NEAR(layers[k].youngs_modulus / layers[1].youngs_modulus, 1.0, 1e-12) << k;
  }
  EXPECT_LT(layers[0].youngs_modulus, 0.5 * layers[1].youngs_modulus);
  EXPECT_NEAR(layers[9].youngs_modulus / layers[0].youngs_modulus, 1.0, 1e-12);
  EXPECT_LT(r.layered->stiffness, r.stiffness_uniform);
  EXPECT_GT(r.layered->stiffness, 0.85 * r.stiffness_uniform);
  EXPECT_EQ(r.sample_stiffness(), r.layered->stiffness);
}

// Two equal blocks of bond stiffness k and 4k: in series 1/K = (l/2)/(E1 A) + (l/2)/(E2 A), so
// K = 1.6 K_1 (K_1 the all-k sample); the uniform model averages E and gives about 2.5 K_1.
TEST(LayeredStiffness, TwoStackedBlocksActInSeries) {
  const test::Lattice g{8, 8, 20, 1e-3};
  SteOptions o;
  o.layered = true;
  const SteResult soft = ste::estimate_stiffness(two_blocks(g, 99, 1.0), o);
  const SteResult stacked = ste::estimate_stiffness(two_blocks(g, 10, 4.0), o);
  EXPECT_NEAR(stacked.layered->stiffness / soft.layered->stiffness, 1.6, 0.03 * 1.6);
  EXPECT_GT(stacked.stiffness_uniform / soft.stiffness_uniform, 2.2);
  // Layers wholly inside a block have that block's modulus ratio.
  EXPECT_NEAR(stacked.layered->layers[7].youngs_modulus / stacked.layered->layers[2].youngs_modulus, 4.0, 1e-9);
}

/// The same lattice sample with the platens: bottom and top rows (8 x 8 particles) touch them.
SteResult with_walls(const ContactPairParameters& contact, double displacement) {
  SteOptions o;
  ste::WallSeriesOptions w;
  w.contact = contact;
  w.displacement = displacement;
  o.walls = w;
  return ste::estimate_stiffness(test::lattice_model({8, 8, 20, 1e-3}, kN, kS), o);
}

TEST(WallSeries, AStiffWallLeavesTheSampleStiffness) {
  ContactPairParameters hard;
  hard.e_star = 1e30;
  const SteResult r = with_walls(hard, 2e-4);
  ASSERT_TRUE(r.walls);
  EXPECT_EQ(r.walls->bottom.particles, 64u);
  EXPECT_EQ(r.walls->top.particles, 64u);
  EXPECT_NEAR(r.walls->total / r.stiffness_uniform, 1.0, 1e-6);
  EXPECT_EQ(r.sample_stiffness(), r.walls->total);
}

// Linear platen contacts: each platen is N springs k_n in parallel, so exactly
// 1/K = 1/K_sample + 2 / (N k_n).
TEST(WallSeries, LinearContactsGiveTheSeriesFormula) {
  ContactPairParameters linear;
  linear.law = ContactLaw::linear;
  linear.k_n = 2e4;
  const SteResult r = with_walls(linear, 2e-4);
  const double expected = 1.0 / (1.0 / r.stiffness_uniform + 2.0 / (64.0 * linear.k_n));
  EXPECT_NEAR(r.walls->secant / expected, 1.0, 1e-12);
  EXPECT_NEAR(r.walls->tangent / expected, 1.0, 1e-12);
}

// Hertz platen contacts: F = 64 * 4/3 E* sqrt(R) delta^1.5 per platen and the travel
// w = F/K + 2 delta. A soft platen lowers K; the tangent contact stiffness is 3/2 the secant.
TEST(WallSeries, SoftHertzWallsLowerTheStiffnessAsTheSeriesSays) {
  ContactPairParameters hertz;
  hertz.e_star = 2e8;
  const double w = 2e-4;
  const SteResult r = with_walls(hertz, w);
  const ste::WallSeries& s = *r.walls;
  const double k = r.stiffness_uniform, c = 64.0 * (4.0 / 3.0) * hertz.e_star * std::sqrt(0.5e-3);
  const double delta = std::pow(s.force / c, 2.0 / 3.0);
  EXPECT_NEAR(s.bottom.overlap, delta, 1e-12 * delta);
  EXPECT_NEAR(s.force / k + 2.0 * delta, w, 1e-12 * w);
  EXPECT_NEAR(s.secant, s.force / w, 1e-9 * s.secant);
  EXPECT_NEAR(s.bottom.tangent, 1.5 * s.force / delta, 1e-9 * s.bottom.tangent);
  EXPECT_NEAR(s.tangent, 1.0 / (1.0 / k + 2.0 / s.bottom.tangent), 1e-12 * s.tangent);
  EXPECT_LT(s.secant, 0.9 * k);  // the soft platens matter here
  EXPECT_GT(s.tangent, s.secant);
  EXPECT_LT(s.iterations, 50);
  // Stiffer platens: closer to K.
  hertz.e_star = 2e10;
  EXPECT_GT(with_walls(hertz, w).walls->secant, s.secant);
}

TEST(WallSeries, BadOptionsAreInputErrors) {
  ContactPairParameters hertz;
  hertz.e_star = 2e6;
  EXPECT_THROW(with_walls(hertz, 0.0), InputError);
  EXPECT_THROW(with_walls(ContactPairParameters{}, 1e-4), InputError);
  SteOptions o;
  ste::WallSeriesOptions w;
  w.contact = hertz;
  w.displacement = 1e-4;
  w.bottom_particles = {100000};
  o.walls = w;
  EXPECT_THROW(ste::estimate_stiffness(test::lattice_model({3, 3, 3, 1e-3}, kN, kS), o), InputError);
}

}  // namespace
}  // namespace bpm
