// Walls: contact geometry of each shape against hand-computed values; a sphere squeezed between a
// fixed floor and a slowly moving lid (the reaction forces equal the Hertz force of the measured
// overlap, floor and lid balance); the summed wall forces equal the contact forces the particles
// receive, every step, for a moving lid compressing a bed under gravity; a servo lid reaches its
// target force; displacement records the prescribed motion.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "../contacts/contact_helpers.hpp"
#include "core/error.hpp"
#include "dem/simulation.hpp"
#include "model/wall.hpp"

namespace bpm {
namespace {

TEST(WallGeometryTest, EachShapeGivesNormalOverlapAndArm) {
  using wall_geometry::gap;
  const double r = 1.0;
  // Infinite plane z = 0 facing +z: one-sided, a centre below it is deep in contact.
  Wall plane = test::plane({0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, 0);
  EXPECT_DOUBLE_EQ(gap(plane, {3.0, -2.0, 0.75}, r).overlap, 0.25);
  EXPECT_TRUE(gap(plane, {3.0, -2.0, 0.75}, r).n == (Vec3{0.0, 0.0, -1.0}));
  EXPECT_DOUBLE_EQ(gap(plane, {0.0, 0.0, -0.5}, r).overlap, 1.5);
  // Rectangle 4 x 2 in z = 0: face, edge, corner, and the back side (two-sided).
  Wall rect = plane;
  rect.shape = WallShape::rectangle;
  rect.edge = {1.0, 0.0, 0.0};
  rect.half_width = 2.0;
  rect.half_height = 1.0;
  EXPECT_DOUBLE_EQ(gap(rect, {1.5, 0.5, 0.9}, r).overlap, 0.1);
  const wall_geometry::Gap edge = gap(rect, {2.6, 0.0, 0.0}, r);  // beside the edge x = 2
  EXPECT_NEAR(edge.overlap, 0.4, 1e-15);
  EXPECT_TRUE(edge.n == (Vec3{-1.0, 0.0, 0.0}));
  const wall_geometry::Gap corner = gap(rect, {2.0 + 0.6, 1.0 + 0.6, 0.0}, r);
  EXPECT_NEAR(corner.overlap, 1.0 - 0.6 * std::sqrt(2.0), 1e-15);
  EXPECT_LT(gap(rect, {2.8, 1.8, 0.0}, r).overlap, 0.0);
  const wall_geometry::Gap back = gap(rect, {0.0, 0.0, -0.7}, r);
  EXPECT_NEAR(back.overlap, 0.3, 1e-15);
  EXPECT_TRUE(back.n == (Vec3{0.0, 0.0, 1.0}));
  // Disc of radius 2: face and rim.
  Wall disc = plane;
  disc.shape = WallShape::disc;
  disc.radius = 2.0;
  EXPECT_DOUBLE_EQ(gap(disc, {1.0, 1.0, 0.5}, r).overlap, 0.5);
  EXPECT_NEAR(gap(disc, {0.0, 2.5, 0.3}, r).overlap, 1.0 - std::sqrt(0.25 + 0.09), 1e-15);
  // Cylinder of radius 5 about z: inside and outside.
  Wall cyl;
  cyl.shape = WallShape::cylinder;
  cyl.normal = {0.0, 0.0, 1.0};
  cyl.radius = 5.0;
  const wall_geometry::Gap inside = gap(cyl, {0.0, 4.2, 7.0}, r);
  EXPECT_NEAR(inside.overlap, 0.2, 1e-15);
  EXPECT_TRUE(inside.n == (Vec3{0.0, 1.0, 0.0}));
  EXPECT_NEAR(inside.arm, 0.8, 1e-15);
  cyl.inside = false;
  const wall_geometry::Gap outside = gap(cyl, {5.7, 0.0, -3.0}, r);
  EXPECT_NEAR(outside.overlap, 0.3, 1e-15);
  EXPECT_TRUE(outside.n == (Vec3{-1.0, 0.0, 0.0}));
}

/// A sphere (R = 1 mm) on the floor z = 0 under a lid z = 2R facing down.
Model squeeze(const ContactMaterial& material) {
  Model model;
  model.particles.add(0, {0.0, 0.0, 1e-3}, 1e-3, 2500.0);
  model.contacts.materials = {material};
  model.walls.push_back(test::plane({0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, 0));
  model.walls.push_back(test::plane({0.0, 0.0, 2e-3}, {0.0, 0.0, -1.0}, 0));
  model.damping.particle = 0.3;
  model.finalize();
  return model;
}

TEST(WallTest, SqueezedSphereCarriesTheHertzForce) {
  const ContactMaterial m = test::hertz_material(1e8, 0.3, 0.3);
  Model model = squeeze(m);
  // The normal oscillation of the sphere has a period ~1.6e-4 s at the final overlap; the lid takes
  // 0.01 s (60 periods) to travel 2 % of the diameter, and dt = 1e-6 s resolves the oscillation.
  const double speed = 4e-3;  // m/s
  model.walls[1].velocity = {0.0, 0.0, -speed};
  Simulation sim(model, 1e-6);
  const double travel = 4e-5;  // 2 % of the diameter
  while (sim.time() < travel / speed) sim.step();
  const Wall& floor = model.walls[0];
  const Wall& lid = model.walls[1];
  EXPECT_NEAR(lid.displacement.z, -speed * sim.time(), 1e-15);
  EXPECT_EQ(floor.displacement.z, 0.0);
  // Each contact has half the travel as overlap (same material both sides); E* of the pair.
  const double e_star = m.youngs_modulus / (2.0 * (1.0 - 0.09));
  const double delta = 0.5 * -lid.displacement.z;
  const double hertz = 4.0 / 3.0 * e_star * std::sqrt(1e-3) * std::pow(delta, 1.5);
  // Quasi-static: the lag of the centre behind the lid (damped oscillator response to a ramp) is
  // below 1e-3 of the overlap; tolerance 1 %.
  EXPECT_NEAR(lid.force.z / hertz, 1.0, 0.01);
  EXPECT_NEAR(floor.force.z / -hertz, 1.0, 0.01);
  EXPECT_NEAR(lid.force.z, -floor.force.z, 1e-3 * hertz);
}

TEST(WallTest, ServoLidReachesItsTargetForce) {
  const ContactMaterial m = test::hertz_material(1e8, 0.3, 0.3);
  Model model = squeeze(m);
  const double target = 2.0;  // N
  // Gain 0.1 m/(N s) against the two contacts in series (k ~ 1.6e4 N/m at the target): time
  // constant 1/(gain k) ~ 6e-4 s, gain k dt = 1.6e-3 << 1 (stable).
  model.walls[1].servo = {true, target, 0.1, 0.05};
  Simulation sim(model, 1e-6);
  while (sim.time() < 0.02) sim.step();
  const Wall& lid = model.walls[1];
  EXPECT_NEAR(-dot(lid.force, lid.normal) / target, 1.0, 1e-3);
  // The overlap that carries the target: delta = (3 F / (4 E* sqrt R))^(2/3) on each side.
  const double e_star = m.youngs_modulus / (2.0 * (1.0 - 0.09));
  const double delta = std::pow(3.0 * target / (4.0 * e_star * std::sqrt(1e-3)), 2.0 / 3.0);
  EXPECT_NEAR(-lid.displacement.z / (2.0 * delta), 1.0, 2e-3);
  EXPECT_LT(std::abs(lid.velocity.z), 1e-6);
}

TEST(WallTest, WallForcesEqualTheContactForcesOnTheParticles) {
  // A bed of 300 spheres in a cylinder on a floor, gravity on, a lid moving down into it; no
  // particle damping. Particle-particle forces cancel in pairs, so every step
  // sum over walls of F_wall = -(sum_i F_i - sum_i m_i g).
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Model model;
  for (int i = 0; i < 300; ++i) {
    const double angle = 2.0 * std::numbers::pi * u(rng), rho = 4e-3 * std::sqrt(u(rng));
    model.particles.add(i, {rho * std::cos(angle), rho * std::sin(angle), 1e-3 + 15e-3 * u(rng)},
                        0.8e-3 + 0.2e-3 * u(rng), 2500.0);
  }
  model.contacts.particle_particle = true;
  model.contacts.materials = {test::hertz_material(1e7, 0.3, 0.5, 0.4, 0.01)};
  model.gravity = {0.0, 0.0, -9.81};
  model.walls.push_back(test::plane({0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, 0));
  Wall cylinder;
  cylinder.shape = WallShape::cylinder;
  cylinder.radius = 5.5e-3;
  model.walls.push_back(cylinder);
  Wall lid = test::plane({0.0, 0.0, 12e-3}, {0.0, 0.0, -1.0}, 0);
  lid.velocity = {0.0, 0.0, -0.2};
  model.walls.push_back(lid);
  model.finalize();
  Simulation sim(model, 2e-6);
  const ParticleStore& p = model.particles;
  double worst = 0.0, scale = 0.0;
  for (int s = 0; s < 3000; ++s) {
    sim.step();
    Vec3 walls, particles;
    for (const Wall& w : model.walls) walls += w.force;
    for (std::size_t i = 0; i < p.size(); ++i) particles += p.force[i] - p.mass[i] * model.gravity;
    worst = std::max(worst, norm(walls + particles));
    scale = std::max(scale, norm(model.walls[2].force));
  }
  ASSERT_GT(scale, 0.0);                          // the lid did touch the bed
  ASSERT_GT(norm(model.walls[1].force), 0.0);     // and the cylinder was pushed
  EXPECT_LT(worst, 1e-9 * scale);                 // round-off of the sums
}

TEST(WallTest, InvalidWallsAreRejectedWithAnInputError) {
  Model model = squeeze(test::hertz_material(1e8, 0.3, 0.5));
  Model no_materials = model;
  no_materials.contacts.materials.clear();
  EXPECT_THROW(Simulation(no_materials, 1e-6), InputError);
  Model bad_material = model;
  bad_material.walls[0].material = 3;
  EXPECT_THROW(Simulation(bad_material, 1e-6), InputError);
  Model servo_cylinder = model;
  servo_cylinder.walls[0].shape = WallShape::cylinder;
  servo_cylinder.walls[0].radius = 1.0;
  servo_cylinder.walls[0].servo = {true, 1.0, 1e-3, 1.0};
  EXPECT_THROW(Simulation(servo_cylinder, 1e-6), InputError);
  Model flat_rectangle = model;
  flat_rectangle.walls[0].shape = WallShape::rectangle;  // half sizes 0
  EXPECT_THROW(Simulation(flat_rectangle, 1e-6), InputError);
  // A normal of any length is normalised.
  model.walls[0].normal = {0.0, 0.0, 5.0};
  Simulation sim(model, 1e-6);
  EXPECT_TRUE(sim.model().walls[0].normal == (Vec3{0.0, 0.0, 1.0}));
}

}  // namespace
}  // namespace bpm
