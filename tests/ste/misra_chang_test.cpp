// The per-particle tensor (Jarolin Eq. 11-35) against the analytic simple cubic lattice, the sample
// tensor's symmetries (major symmetry, isotropy of a random packing, rotation), the exclusion of
// particles with too few bonds, and the linearised Hertz contacts.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "core/error.hpp"
#include "ste/stiffness_tensor_estimation.hpp"
#include "ste_helpers.hpp"

namespace bpm {
namespace {

using ste::Fluctuation;
using ste::SteOptions;
using ste::SteResult;
using ste::Voigt6;

/// Particles at least `depth` sites from every face of the lattice.
template <class F>
void for_each_deep(const test::Lattice& g, int depth, F&& f) {
  for (int i = depth; i < g.nx - depth; ++i)
    for (int j = depth; j < g.ny - depth; ++j)
      for (int k = depth; k < g.nz - depth; ++k) f(static_cast<std::size_t>(g.index(i, j, k)));
}

const Model& random_sample() {
  static const Model model = test::random_packing(3000, 7);
  return model;
}

// A simple cubic lattice (spacing L, rotations held) strained affinely: a bond along x carries
// k_n eps_11 L, i.e. sigma_11 = k_n eps_11 L / L^2 (C_11 = k_n / L); a shear gamma_12 gives each
// x and y bond a transverse k_s gamma L / 2 (C_66 = k_s / (2 L)); nothing couples the normal
// directions (C_12 = 0). The Voronoi cell of an inner particle is L^3, and by symmetry every
// fluctuation Gamma vanishes two sites away from a face, so Eq. 32 must give these values exactly.
TEST(MisraChang, CubicLatticeMatchesTheAnalyticTensor) {
  const test::Lattice g{7, 7, 7, 2e-3};
  for (const double k_s : {0.0, 3e5}) {
    const double k_n = 1e6, L = g.spacing;
    const Model model = test::lattice_model(g, k_n, k_s);
    for (const Fluctuation f : {Fluctuation::affine, Fluctuation::first_neighbour, Fluctuation::paper}) {
      SteOptions o;
      o.volumes = ste::VolumeMethod::voronoi;
      o.fluctuation = f;
      const SteResult r = ste::estimate_stiffness(model, o);
      EXPECT_EQ(r.used, model.particles.size()) << "k_s " << k_s;  // even corners have 3 bonds
      int checked = 0;
      for_each_deep(g, 2, [&](std::size_t p) {
        ++checked;
        EXPECT_NEAR(r.particle_volume[p], L * L * L, 1e-12 * L * L * L);
        Voigt6 expected = Voigt6::Zero();
        expected(0, 0) = expected(1, 1) = expected(2, 2) = k_n / L;
        expected(3, 3) = expected(4, 4) = expected(5, 5) = k_s / (2.0 * L);
        EXPECT_LE((r.particle_stiffness[p] - expected).cwiseAbs().maxCoeff(), 1e-12 * k_n / L)
            << "particle " << p << " k_s " << k_s << "\n" << r.particle_stiffness[p];
      });
      EXPECT_EQ(checked, 27);
    }
  }
}

// The sample of the same lattice: E_x = E_y = E_z, nu = 0, and with k_s = 0 no shear stiffness
// (the compliance is the pseudo-inverse; a stress along a diagonal is a mechanism, E = 0).
TEST(MisraChang, CubicLatticeSampleConstants) {
  const test::Lattice g{6, 6, 6, 2e-3};
  const Model model = test::lattice_model(g, 1e6, 0.0);
  SteOptions o;
  o.volumes = ste::VolumeMethod::voronoi;
  o.fluctuation = Fluctuation::affine;
  const SteResult r = ste::estimate_stiffness(model, o);
  const double e = r.constants.E_x;
  EXPECT_GT(e, 0.0);
  EXPECT_NEAR(r.constants.E_y / e, 1.0, 1e-12);
  EXPECT_NEAR(r.constants.E_z / e, 1.0, 1e-12);
  EXPECT_NEAR(r.youngs_modulus_axis / e, 1.0, 1e-12);
  EXPECT_NEAR(r.constants.nu_xy, 0.0, 1e-12);
  EXPECT_NEAR(r.constants.nu_zx, 0.0, 1e-12);
  EXPECT_EQ(r.constants.G_xy, 0.0);
  EXPECT_EQ(ste::directional_modulus(r.stiffness, {1.0, 1.0, 0.0}), 0.0);
  // Affine: sum V^n C^n = sum over bonds of D^T K D, so C_11 = (bonds along x) k_n L^2 / sum V.
  const double x_bonds = 5.0 * 36.0;
  EXPECT_NEAR(r.stiffness(0, 0), x_bonds * 1e6 * 4e-6 / r.volume_used, 1e-12 * r.stiffness(0, 0));
  const SampleGeometry clip = measure_sample(model.particles, {0, 0, 1}, o.hull_planes);
  EXPECT_NEAR(r.volume_used, clip.length * clip.area, 1e-9 * r.volume_used);
  EXPECT_NEAR(r.stiffness_uniform, r.youngs_modulus_axis * r.sample.area / r.sample.length, 1e-9 * r.stiffness_uniform);
}

// Poisson's ratio along any axis of an isotropic tensor is its nu; along z of an orthotropic one
// it is the mean of nu_zx and nu_zy (what the strain gauges of compress/strain_gauge.hpp measure).
TEST(ElasticConstants, DirectionalPoissonsRatio) {
  const double E = 2e9, nu = 0.27, lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  Voigt6 c = Voigt6::Zero();
  c.topLeftCorner<3, 3>().setConstant(lambda);
  for (int i = 0; i < 3; ++i) c(i, i) += 2 * mu, c(i + 3, i + 3) = mu;
  for (const Vec3& a : {Vec3{0, 0, 1}, Vec3{1, 2, -3}, Vec3{1, 1, 0}})
    EXPECT_NEAR(ste::directional_poissons_ratio(c, a), nu, 1e-12);
  c(0, 2) = c(2, 0) = 0.5 * lambda;  // z couples less to x than to y
  const ste::EngineeringConstants k = ste::engineering_constants(c);
  EXPECT_NEAR(ste::directional_poissons_ratio(c, {0, 0, 1}), 0.5 * (k.nu_zx + k.nu_zy), 1e-12);
}

// Summed over a sample in which every particle counts, Eq. 32 pairs each neighbour term with its
// transpose: C is major-symmetric to round-off. A random packing is nearly isotropic.
TEST(MisraChang, RandomPackingIsSymmetricAndNearlyIsotropic) {
  const Model& model = random_sample();
  SteOptions voronoi;
  voronoi.volumes = ste::VolumeMethod::voronoi;
  const SteResult r = ste::estimate_stiffness(model, voronoi);
  ASSERT_EQ(r.excluded_no_volume, 0u);
  // With k_s > 0 only particles without any bond are singular; they have no neighbours either.
  for (std::size_t i = 0; i < model.particles.size(); ++i) {
    if (r.particle_use[i] == ste::ParticleUse::singular) {
      EXPECT_EQ(r.coordination[i], 0) << i;
    }
  }
  EXPECT_LT(r.asymmetry, 1e-12);
  const auto& c = r.constants;
  const double mean = (c.E_x + c.E_y + c.E_z) / 3.0;
  EXPECT_GT(mean, 0.0);
  for (const double e : {c.E_x, c.E_y, c.E_z}) {
    EXPECT_NEAR(e / mean, 1.0, 0.04) << c.E_x << " " << c.E_y << " " << c.E_z;
  }
  EXPECT_NEAR(c.nu_xy / c.E_x, c.nu_yx / c.E_y, 1e-9 / c.E_x);  // S symmetric
  EXPECT_GT(c.nu_xy, 0.0);
  EXPECT_LT(c.nu_xy, 0.5);
  // The fluctuations soften: affine (Voigt bound) > Eq. 33-35 > Eq. 32.
  SteOptions o = voronoi;
  o.fluctuation = Fluctuation::affine;
  const double affine = ste::estimate_stiffness(model, o).youngs_modulus_axis;
  o.fluctuation = Fluctuation::first_neighbour;
  const double first = ste::estimate_stiffness(model, o).youngs_modulus_axis;
  EXPECT_GT(affine, first);
  EXPECT_GT(first, r.youngs_modulus_axis);
}

// Rotating the whole sample rotates every particle's contribution V^n C^n (a tensor of the
// geometry and the bond stiffnesses: exactly) and so the sample tensor and E along the rotated axis
// (up to the clipped volume: the Voronoi container is the spheres' bounding box, which trims the
// turned cube's corners by ~1e-4).
TEST(MisraChang, RotatingTheSampleRotatesTheTensor) {
  const Model& model = random_sample();
  const Eigen::Matrix3d q = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1.0, 2.0, -0.5).normalized()).toRotationMatrix();
  Model rotated = model;
  for (Vec3& x : rotated.particles.position) {
    const Eigen::Vector3d y = q * Eigen::Vector3d(x.x, x.y, x.z);
    x = {y.x(), y.y(), y.z()};
  }
  rotated.finalize();
  const Eigen::Vector3d a = q * Eigen::Vector3d(0, 0, 1);
  SteOptions o;
  o.volumes = ste::VolumeMethod::voronoi;
  const SteResult r0 = ste::estimate_stiffness(model, o);
  o.axis = {a.x(), a.y(), a.z()};
  const SteResult r1 = ste::estimate_stiffness(rotated, o);
  ASSERT_EQ(r0.used, r1.used);
  double worst = 0.0;
  const double scale = r0.particle_volume[0] * r0.particle_stiffness[0].cwiseAbs().maxCoeff();
  for (std::size_t i = 0; i < model.particles.size(); ++i) {
    const Voigt6 expected = test::rotate_voigt(r0.particle_volume[i] * r0.particle_stiffness[i], q);
    worst = std::max(worst, (r1.particle_volume[i] * r1.particle_stiffness[i] - expected).cwiseAbs().maxCoeff());
  }
  EXPECT_LT(worst, 1e-10 * scale);
  const Voigt6 expected = test::rotate_voigt(r0.stiffness, q);
  EXPECT_LT((r1.stiffness - expected).cwiseAbs().maxCoeff(), 3e-4 * r0.stiffness.cwiseAbs().maxCoeff());
  EXPECT_NEAR(r1.youngs_modulus_axis / r0.youngs_modulus_axis, 1.0, 3e-4);
}

// With k_s = 0 a particle needs three bonds spanning space: a dangling particle on one bond, one
// held by two bonds and a free one are left out and counted.
TEST(MisraChang, ParticlesWithTooFewBondsAreExcludedAndCounted) {
  const test::Lattice g{5, 5, 5, 2e-3};
  Model model = test::lattice_model(g, 1e6, 0.0);
  const double L = g.spacing;
  const BondConstants k{{1e6, 0.0, 1e-3, 1e-3}, 0.0};
  const auto one = model.particles.add(1000, {-L, 2 * L, 2 * L}, 0.5 * L, 2500.0);
  model.bonds.add(g.index(0, 2, 2), one, k, 0.25 * L, L);
  const auto two = model.particles.add(1001, {5 * L, 5 * L, 2 * L}, 0.5 * L, 2500.0);
  model.bonds.add(g.index(4, 4, 2), two, k, 0.25 * L, std::sqrt(2.0) * L);
  model.bonds.add(g.index(4, 3, 2), two, k, 0.25 * L, std::sqrt(5.0) * L);
  model.particles.add(1002, {10 * L, 10 * L, 10 * L}, 0.5 * L, 2500.0);
  model.finalize();
  const SteResult r = ste::estimate_stiffness(model);
  EXPECT_EQ(r.excluded_singular, 3u);
  EXPECT_EQ(r.used, 125u);
  EXPECT_EQ(r.particle_use[static_cast<std::size_t>(one)], ste::ParticleUse::singular);
  EXPECT_EQ(r.particle_use[static_cast<std::size_t>(two)], ste::ParticleUse::singular);
  EXPECT_EQ(r.particle_stiffness[static_cast<std::size_t>(one)], Voigt6::Zero());
}

// Hertz contacts linearised at their overlap: a lattice held only by contacts (spacing 2R - delta)
// has C_11 = dF/d delta / L = 2 E* sqrt(R* delta) / L and C_44 = 8 G* sqrt(R* delta) / (2 L).
TEST(MisraChang, LinearisedHertzContacts) {
  const double r = 1e-3, delta = 1e-6, L = 2 * r - delta;
  Model model;
  const test::Lattice g{6, 6, 6, L};
  for (int i = 0; i < g.nx; ++i)
    for (int j = 0; j < g.ny; ++j)
      for (int k = 0; k < g.nz; ++k) model.particles.add(g.index(i, j, k), {L * i, L * j, L * k}, r, 2500.0);
  ContactMaterial m;
  m.name = "glass";
  m.youngs_modulus = 7e10;
  m.poisson_ratio = 0.2;
  model.contacts.materials = {m};
  model.contacts.particle_particle = true;
  model.finalize();
  SteOptions voronoi;
  voronoi.volumes = ste::VolumeMethod::voronoi;
  const SteResult res = ste::estimate_stiffness(model, voronoi);  // contacts on by default
  EXPECT_EQ(res.contacts, 3u * 36u * 5u);
  const double e_star = 1.0 / (2.0 * (1.0 - 0.04) / 7e10);
  const double g_star = 1.0 / (2.0 * 2.0 * (2.0 - 0.2) * 1.2 / 7e10);
  const double root = std::sqrt(0.5 * r * delta);
  for_each_deep(g, 2, [&](std::size_t p) {
    EXPECT_NEAR(res.particle_stiffness[p](0, 0), 2.0 * e_star * root / L, 1e-9 * e_star * root / L);
    EXPECT_NEAR(res.particle_stiffness[p](3, 3), 8.0 * g_star * root / (2.0 * L), 1e-9 * e_star * root / L);
    EXPECT_NEAR(res.particle_stiffness[p](0, 1), 0.0, 1e-9 * e_star * root / L);
  });
  SteOptions off;
  off.include_contacts = false;
  const SteResult none = ste::estimate_stiffness(model, off);
  EXPECT_EQ(none.contacts, 0u);
  EXPECT_EQ(none.used, 0u);
  EXPECT_EQ(none.excluded_singular, model.particles.size());
  // Bonded pairs under the `replace` rule have no contact while the bond holds.
  Model bonded = model;
  bonded.contacts.bonded = BondedContacts::replace;
  bonded.bonds.add(0, 1, BondConstants{{1e6, 1e5, 1e-3, 1e-3}, 0.0}, 0.5 * r, L);
  bonded.finalize();
  EXPECT_EQ(ste::estimate_stiffness(bonded).contacts, res.contacts - 1);
  bonded.bonds.intact[0] = 0;  // broken: the contact is back
  EXPECT_EQ(ste::estimate_stiffness(bonded).contacts, res.contacts);
}

TEST(MisraChang, BadInputIsAnInputError) {
  const Model model = test::lattice_model({3, 3, 3, 1e-3}, 1e6, 1e5);
  SteOptions o;
  o.axis = {0, 0, 0};
  EXPECT_THROW(ste::estimate_stiffness(model, o), InputError);
  EXPECT_THROW(ste::estimate_stiffness(Model{}, SteOptions{}), InputError);
  EXPECT_THROW(ste::parse_volume_method("cells", "--volumes"), InputError);
  EXPECT_EQ(ste::parse_volume_method("solid-fraction", "--volumes"), ste::VolumeMethod::solid_fraction);
}

}  // namespace
}  // namespace bpm
