// The linear first-break estimate (calibrate/first_break.hpp) against the DEM on a bonded
// tetrahedron between platens (linear springs, no particle contacts): pressed on its apex, its
// inclined bonds push the base apart and the base ring carries tension, about F / (3 sqrt 6) a bond
// as a truss. The DEM is linear until the first bond breaks, so the estimate must name that bond
// and its platen force.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "calibrate/first_break.hpp"
#include "compress/compress_helpers.hpp"
#include "compress/uniaxial_compression.hpp"
#include "core/error.hpp"

namespace bpm {
namespace {

constexpr double kR = 1e-3;  // m

/// Three spheres in a triangle of side 2R on the base, one on top touching all three; the six
/// touching pairs bonded (TBBM, steel, r_b = R). Tensile strengths drawn from N(30, 3) MPa, shear
/// unbreakable.
Model tetrahedron() {
  Model model = test::lattice(1, 1, 1, 1e9);  // its contact and damping settings, one particle
  model.particles = {};
  model.bonds = {};
  const double s = 2 * kR, h = s * std::sqrt(2.0 / 3.0);
  const Vec3 base[3] = {{0, 0, 0}, {s, 0, 0}, {s / 2, s * std::sqrt(3.0) / 2, 0}};
  for (int i = 0; i < 3; ++i) model.particles.add(i, base[i], kR, 7850.0);
  model.particles.add(3, {s / 2, s * std::sqrt(3.0) / 6, h}, kR, 7850.0);
  BondMaterial m;
  m.model = "tbbm";
  m.youngs_modulus = 200e9;
  m.poisson_ratio = 0.3;
  for (const auto& [a, b] : {std::pair{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}})
    model.bonds.add(a, b, make_bond_constants(m, BondGeometry{kR, s, kR, kR}), kR, s);
  m.tensile_strength = {StrengthDistribution::Kind::normal, 30e6, 3e6};
  model.bonds.draw_strengths({m}, 7);
  model.finalize();
  return model;
}

UniaxialCompression to_failure() {
  UniaxialCompression s;
  s.strain_rate = 0.05;
  s.target_strain = 1e-5;
  s.failure_drop = 0.5;
  s.max_strain = 5e-4;
  s.curve_points = 200;
  return s;
}

TEST(FirstBreak, NamesTheDemsFirstBrokenBondAndItsForce) {
  const Model model = tetrahedron();
  const UniaxialCompression s = to_failure();
  const FirstBreakEstimate e = linear_first_break(model, s);
  EXPECT_STREQ(e.method, "dsm");
  EXPECT_EQ(e.mode, BreakMode::tension);
  EXPECT_LT(e.bond, 3) << "a base bond";  // rows 0-2: the base ring
  // As a truss the ring breaks at F = 3 sqrt(6) sigma_t A_b of its weakest bond; the stocky
  // beams' bending adds 4 |M_ben| / r_b to the ring's sigma A_b, so they break below that force.
  const double weakest = std::min({model.bonds.strength[0].tensile, model.bonds.strength[1].tensile,
                                   model.bonds.strength[2].tensile});
  EXPECT_LT(e.force, 3.0 * std::sqrt(6.0) * weakest);
  EXPECT_GT(e.force, 0.5 * 3.0 * std::sqrt(6.0) * weakest);

  Model dem = model;
  const CompressionResult r = run_uniaxial_compression(dem, s);
  ASSERT_FALSE(dem.bonds.breaks.empty());
  EXPECT_EQ(dem.bonds.input_row[static_cast<std::size_t>(dem.bonds.breaks.front().bond)], e.bond);
  EXPECT_EQ(dem.bonds.breaks.front().mode, BreakMode::tension);
  EXPECT_NEAR(r.peak_force / e.force, 1.0, 0.01) << "the DEM's peak is its first break";
  EXPECT_NEAR(r.strength / e.stress, 1.0, 0.01);
}

TEST(FirstBreak, RefusesTheTensionTestAndUnbreakableBonds) {
  Model model = tetrahedron();
  UniaxialCompression s = to_failure();
  s.test = LabTest::tension;
  EXPECT_THROW(linear_first_break(model, s), InputError);
  model.bonds.draw_strengths({BondMaterial{}}, 7);  // infinite strengths
  EXPECT_THROW(linear_first_break(model, to_failure()), InputError);
}

}  // namespace
}  // namespace bpm
