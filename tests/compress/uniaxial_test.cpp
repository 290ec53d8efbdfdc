// The uniaxial compression test (compress/): the sample's length and cross-section are measured as
// Jarolin does, and compressing a regular bonded lattice between frictionless platens gives the
// analytical lattice stiffness: N columns of (n_z - 1) bonds in series, each column also in series
// with its two particle-platen contacts. A weak jittered lattice runs to failure and reports its peak.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "compress/mass_scaling.hpp"
#include "compress/sample_geometry.hpp"
#include "compress/uniaxial_compression.hpp"
#include "model/contact_material.hpp"
#include "bonds/bond_model.hpp"
#include "compress/compress_helpers.hpp"
#include "core/error.hpp"

namespace bpm {
namespace {

using test::lattice;

TEST(SampleGeometry, BoxOfSpheresHasItsFaceArea) {
  // 4 x 3 x 5 touching spheres of R = 1 mm: the hull of the discs of the top view is a 8 x 6 mm
  // rectangle with rounded corners: area 8*6 - (4 - pi) R^2.
  ParticleStore p;
  const double R = 1e-3;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 5; ++k) p.add(0, {2 * R * i, 2 * R * j, 2 * R * k}, R, 1000.0);
  const SampleGeometry g = measure_sample(p, {0, 0, 1});
  EXPECT_NEAR(g.length, 10 * R, 1e-15);
  EXPECT_NEAR(g.bottom, -R, 1e-15);
  EXPECT_NEAR(g.area / (48 * R * R - (4 - std::numbers::pi) * R * R), 1.0, 1e-4);
  // Along x the cross-section is 6 x 10 mm, the length 8 mm.
  const SampleGeometry gx = measure_sample(p, {1, 0, 0});
  EXPECT_NEAR(gx.length, 8 * R, 1e-15);
  EXPECT_NEAR(gx.area / (60 * R * R - (4 - std::numbers::pi) * R * R), 1.0, 1e-4);
}

TEST(SampleGeometry, CylinderOfRandomSpheres) {
  // Spheres with centres in a cylinder of radius 9 mm, plus a ring of spheres (R = 1 mm) on the
  // rim: the hull is the circle of radius 10 mm to within the circumscribed-polygon error.
  ParticleStore p;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 2000; ++i) {
    double x, y;
    do {
      x = 8e-3 * u(rng);
      y = 8e-3 * u(rng);
    } while (x * x + y * y > 64e-6);
    p.add(i, {x, y, 0.02 * u(rng)}, 1e-3, 1000.0);
  }
  for (int k = 0; k < 720; ++k) {
    const double t = 2 * std::numbers::pi * k / 720.0;
    p.add(5000 + k, {9e-3 * std::cos(t), 9e-3 * std::sin(t), 0.0}, 1e-3, 1000.0);
  }
  const SampleGeometry g = measure_sample(p, {0, 0, 1});
  EXPECT_NEAR(g.area / (std::numbers::pi * 1e-4), 1.0, 2e-4);
}

TEST(UniaxialCompression, RegularLatticeGivesTheAnalyticalStiffness) {
  const int nx = 4, ny = 4, nz = 10;
  const double k_n = 200e9 * std::numbers::pi * 1e-6 / 2e-3;  // E_b A_b / L_b
  for (const double k_c : {3e9, 1e8}) {  // stiff platen contacts, then ones as soft as the bonds
    Model model = lattice(nx, ny, nz, k_c);
    // The pair constant the wall contact really uses (pair rules of contact_material.hpp).
    const double k_wall = ContactTable(model.contacts)(0, 0).k_n;
    UniaxialCompression s;
    s.strain_rate = 5.0;
    s.target_strain = 1e-3;
    s.fit_from = 0.3;
    const CompressionResult r = run_uniaxial_compression(model, s);
    // Per column: nz - 1 bonds and two platen contacts in series; nx * ny columns in parallel.
    const double column = 1.0 / ((nz - 1) / k_n + 2.0 / k_wall);
    const double analytical = nx * ny * column;
    EXPECT_NEAR(r.stiffness / analytical, 1.0, 1e-3) << "k_c " << k_c;
    EXPECT_GT(r.fit_r2, 0.9999);
    EXPECT_LT(r.max_kinetic_ratio, 1e-2) << "the test must be quasi-static";
    EXPECT_NEAR(r.sample.length, 2e-3 * nz, 1e-12);
    EXPECT_NEAR(r.youngs_modulus, r.stiffness * r.sample.length / r.sample.area, 1e-6 * r.youngs_modulus);
    EXPECT_EQ(r.stop, "target_strain");
    EXPECT_NEAR(r.curve.back().strain, 1e-3, 1e-5);
    // The body's E (strain gauges on the middle third) is the bonds' alone, whatever the platen
    // contacts: nx ny k_n L / A with L = 2R; a simple cubic lattice has no lateral strain.
    ASSERT_TRUE(r.body.valid);
    EXPECT_EQ(r.gauge_particles, static_cast<std::size_t>(nx * ny * 4));  // layers at z = 6R ... 12R
    EXPECT_NEAR(r.body.youngs_modulus / (nx * ny * k_n * 2e-3 / r.sample.area), 1.0, 2e-3) << "k_c " << k_c;
    EXPECT_NEAR(r.body.poissons_ratio, 0.0, 1e-3);
  }
}

TEST(UniaxialCompression, MassScalingKeepsTheStiffnessInFewerSteps) {
  // Density scaling by f = 25: the stable step grows by 5, the test takes a fifth of the steps,
  // and the quasi-static stiffness stays the lattice's (the mass does not enter K). The model gets
  // its own masses back.
  const int nx = 4, ny = 4, nz = 10;
  auto run = [&](double f) {
    Model model = lattice(nx, ny, nz, 1e8);
    const std::vector<double> mass = model.particles.mass, inertia = model.particles.inertia;
    UniaxialCompression s;
    s.strain_rate = 5.0;
    s.target_strain = 1e-3;
    s.fit_from = 0.3;
    s.mass_scaling = f;
    const CompressionResult r = run_uniaxial_compression(model, s);
    EXPECT_EQ(model.particles.mass, mass);
    EXPECT_EQ(model.particles.inertia, inertia);
    EXPECT_EQ(r.mass_scaling, f);
    return r;
  };
  const CompressionResult real = run(1.0), scaled = run(25.0);
  EXPECT_NEAR(scaled.time_step / real.time_step, 5.0, 1e-9);
  EXPECT_NEAR(static_cast<double>(scaled.run.steps) / static_cast<double>(real.run.steps), 0.2, 0.01);
  EXPECT_NEAR(scaled.stiffness / real.stiffness, 1.0, 5e-3);
  EXPECT_LT(scaled.max_kinetic_ratio, 0.1) << "still quasi-static by the test's own measure (refuse_stiffness)";
}

TEST(UniaxialCompression, MassScalingKeepsEachWeight) {
  Model model = lattice(2, 2, 2, 1e9);
  model.gravity = {0.0, 0.0, -9.81};
  const std::vector<double> mass = model.particles.mass;
  {
    const ScaledMasses scaled(model, 16.0);
    for (std::size_t i = 0; i < mass.size(); ++i) {
      EXPECT_DOUBLE_EQ(model.particles.mass[i], 16.0 * mass[i]);
      EXPECT_NEAR(model.particles.mass[i] * model.gravity.z, mass[i] * -9.81, 1e-15 * mass[i]);
    }
  }
  EXPECT_EQ(model.particles.mass, mass);
  EXPECT_EQ(model.gravity.z, -9.81);
}

TEST(UniaxialCompression, BadSettingsAreReported) {
  Model model = lattice(2, 2, 2, 1e9);
  UniaxialCompression s;
  s.strain_rate = 0.0;
  s.target_strain = 1e-3;
  try {
    run_uniaxial_compression(model, s);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("compression.strain_rate"), std::string::npos) << e.what();
  }
  s.strain_rate = 1.0;
  s.mass_scaling = 0.5;
  try {
    run_uniaxial_compression(model, s);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("compression.mass_scaling"), std::string::npos) << e.what();
  }
  s.mass_scaling = 1.0;
  s.platen_material = 3;
  EXPECT_THROW(run_uniaxial_compression(model, s), InputError);
}

TEST(UniaxialCompression, StepFarBelowTheTestDurationIsRefused) {
  // 1e-3 strain at 1/s takes 1e-3 s; a step of 1e-30 s is 1e27 steps (an endless run).
  Model model = lattice(2, 2, 2, 1e9);
  UniaxialCompression s;
  s.strain_rate = 1.0;
  s.target_strain = 1e-3;
  s.time_step = 1e-30;
  try {
    run_uniaxial_compression(model, s);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("compression.time_step"), std::string::npos) << message;
    EXPECT_NE(message.find("1e+27 steps"), std::string::npos) << message;
  }
}

TEST(UniaxialCompression, RunsToFailureAndReportsThePeak) {
  // A jittered lattice: under compression the bonds also shear and bend, and with weak bonds (and no
  // particle-particle contacts to catch the pieces) the sample fails. The run must stop on the drop
  // of the stress below half its peak, after the peak, with bonds broken.
  Model model = lattice(3, 3, 8, 1e9);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (auto& x : model.particles.position) x += 0.1e-3 * Vec3{u(rng), u(rng), 0.0};
  BondMaterial weak;
  weak.tensile_strength.value = 30e6;
  weak.shear_strength.value = 30e6;
  model.bonds.draw_strengths({weak}, 1);
  model.finalize();
  UniaxialCompression s;
  s.strain_rate = 5.0;
  s.target_strain = 1e-3;
  s.failure_drop = 0.5;
  s.max_strain = 0.05;
  const CompressionResult r = run_uniaxial_compression(model, s);
  EXPECT_EQ(r.stop, "failure");
  EXPECT_GT(r.peak_strain, 0.5 * s.target_strain) << "the sample carried load before it failed";
  EXPECT_GT(r.curve.back().strain, r.peak_strain);
  EXPECT_LT(r.curve.back().force, 0.5 * r.peak_stress * r.sample.area);
  EXPECT_GT(r.curve.back().bonds_broken, 0u);
  // The peak is the largest stress on the curve.
  for (const CompressionPoint& p : r.curve) EXPECT_LE(p.force / r.sample.area, r.peak_stress * (1 + 1e-12));
}

}  // namespace
}  // namespace bpm
