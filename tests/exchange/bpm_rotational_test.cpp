// Our bonds as LAMMPS's bond_style bpm/rotational (scenario/lammps_export.hpp): K_r = k_n, K_s =
// k_s, K_t = k_tor, K_b = k_ben gives the same stiffnesses.
//
// The reference is bpm/rotational linearised for small motions, written here from its definition
// (LAMMPS src/BPM/bond_bpm_rotational.cpp, after Wang 2009): F_r = K_r (r - r_0) along the bond; a
// shear force K_s r gamma from the bond's turn seen from particle 2 plus 0.5 K_s r theta from the
// relative rotation, i.e. K_s times the lateral displacement of the point midway between the
// centres, and the torques 0.5 r x F_s it exerts on each particle; bending K_b theta and twisting
// K_t psi of the relative rotation. As an energy:
//   1/2 K_r dn^2 + 1/2 K_s |P d|^2 + 1/2 K_b |P (phi_b - phi_a)|^2 + 1/2 K_t (n . (phi_b -
//   phi_a))^2, d = u_b - u_a + L/2 n x (phi_a + phi_b),  P = I - n n^T,
// whose Hessian is compared with our 12x12 element (linear/bond_element.hpp), built from the
// unified law the DEM runs.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <numbers>
#include <random>

#include "bonds/bond_model.hpp"
#include "common/test_files.hpp"
#include "io/lammps_data.hpp"
#include "linear/bond_element.hpp"
#include "scenario/lammps_export.hpp"

namespace bpm {
namespace {

using Matrix12 = Eigen::Matrix<double, 12, 12>;
using Row12 = Eigen::Matrix<double, 1, 12>;
using Rows3x12 = Eigen::Matrix<double, 3, 12>;

Matrix12 bpm_rotational_element(const BpmRotationalStiffness& k, const Eigen::Vector3d& n,
                                double length) {
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  const Eigen::Matrix3d P = I - n * n.transpose();
  Eigen::Matrix3d S;  // S v = n x v
  S << 0, -n.z(), n.y(), n.z(), 0, -n.x(), -n.y(), n.x(), 0;
  Row12 axial = Row12::Zero(), twist = Row12::Zero();
  axial << -n.transpose(), 0, 0, 0, n.transpose(), 0, 0, 0;
  twist << 0, 0, 0, -n.transpose(), 0, 0, 0, n.transpose();
  Rows3x12 shear, bend;
  shear << -P, 0.5 * length * S, P, 0.5 * length * S;
  bend << Eigen::Matrix3d::Zero(), -P, Eigen::Matrix3d::Zero(), P;
  return k.k_r * axial.transpose() * axial + k.k_s * shear.transpose() * shear +
         k.k_b * bend.transpose() * bend + k.k_t * twist.transpose() * twist;
}

BondMaterial material(const std::string& model, double E, double nu, double r_b) {
  BondMaterial m;
  m.name = "bond";
  m.model = model;
  m.youngs_modulus = E;
  m.poisson_ratio = nu;
  m.radius = r_b;
  return m;
}

TEST(BpmRotational, PbmStiffnessesAreTheParallelBondsFormulas) {
  const double E = 30e9, nu = 0.25, r_b = 0.004, L = 0.02;
  const BondConstants c = make_bond_constants(material("pbm", E, nu, r_b), {r_b, L, 0.01, 0.01});
  const BpmRotationalStiffness k = bpm_rotational_stiffness(c.stiffness);
  const double A = std::numbers::pi * r_b * r_b, I = 0.25 * std::numbers::pi * std::pow(r_b, 4),
               G = E / (2 * (1 + nu));
  EXPECT_NEAR(k.k_r, E * A / L, 1e-12 * k.k_r);
  EXPECT_NEAR(k.k_s, G * A / L, 1e-12 * k.k_s);  // kappa = k_n / k_s = 2 (1 + nu), Chen Eq. 8
  EXPECT_NEAR(k.k_t, G * 2 * I / L, 1e-12 * k.k_t);
  EXPECT_NEAR(k.k_b, E * I / L, 1e-12 * k.k_b);
}

/// Every model whose contact point is the midpoint (the beam models; the parallel bond between
/// equal radii): our element and bpm/rotational's are the same matrix.
TEST(BpmRotational, SameElementAsOurLawForEveryModelWithTheMidpointContact) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (const char* model : {"pbm", "brendel", "ebbm", "tbbm"}) {
    for (int trial = 0; trial < 10; ++trial) {
      Eigen::Vector3d n(unit(rng), unit(rng), unit(rng));
      n.normalize();
      const double R = 0.01 * (1.5 + unit(rng)), L = 2 * R * (1.0 + 0.05 * unit(rng)),
                   r_b = 0.5 * R;
      const BondConstants c = make_bond_constants(material(model, 70e9, 0.3, r_b), {r_b, L, R, R});
      ASSERT_EQ(c.arm_offset, 0.0) << model;
      const Matrix12 ours = bond_element_stiffness(c.stiffness, {n.x(), n.y(), n.z()},
                                                   bond_law::contact_arms(L, 0.0));
      const Matrix12 theirs = bpm_rotational_element(bpm_rotational_stiffness(c.stiffness), n, L);
      const double scale = ours.cwiseAbs().maxCoeff();
      EXPECT_LE((ours - theirs).cwiseAbs().maxCoeff(), 1e-12 * scale)
          << model << " trial " << trial << "\nours =\n"
          << ours << "\nbpm/rotational =\n"
          << theirs;
    }
  }
}

/// The parallel bond between unequal radii puts the contact point in the middle of the gap, which
/// bpm/rotational cannot: the elements differ (the export says so), by about the arm offset.
TEST(BpmRotational, PbmBetweenUnequalRadiiDiffersAsTheNoteSays) {
  const double R_a = 0.01, R_b = 0.006, L = R_a + R_b, r_b = 0.005;
  const BondConstants c = make_bond_constants(material("pbm", 70e9, 0.3, r_b), {r_b, L, R_a, R_b});
  ASSERT_GT(c.arm_offset, 0.0);
  const Eigen::Vector3d n(1, 0, 0);
  const Matrix12 ours =
      bond_element_stiffness(c.stiffness, {1, 0, 0}, bond_law::contact_arms(L, c.arm_offset));
  const Matrix12 theirs = bpm_rotational_element(bpm_rotational_stiffness(c.stiffness), n, L);
  // Measured against the rotational block: the axial k_n dwarfs everything else.
  const double rotational = ours.block<3, 3>(3, 3).cwiseAbs().maxCoeff();
  EXPECT_GT((ours - theirs).cwiseAbs().maxCoeff(), 1e-2 * rotational);
  // The translational block (both rotations held) does not depend on the contact point.
  const Eigen::Matrix3d translational = ours.block<3, 3>(0, 0) - theirs.block<3, 3>(0, 0);
  EXPECT_LE(translational.cwiseAbs().maxCoeff(), 1e-12 * ours.cwiseAbs().maxCoeff());
}

TEST(BpmRotational, ExportWritesTheScenarioAndItsCoefficients) {
  test::TempDir dir;
  const std::string scenario_path = dir.write("s.yaml", R"(particle_materials:
  rock: {density: 2650}
  steel: {density: 7850}
bond_materials:
  glue: {model: pbm, youngs_modulus: 30e9, poisson_ratio: 0.25, radius: 0.2}
particles:
  list:
    - {id: 4, position: [0, 0, 0], radius: 0.2, material: rock}
    - {id: 9, position: [0.4, 0, 0], radius: 0.2, material: steel}
    - {id: 2, position: [0.8, 0, 0], radius: 0.2, material: rock}
bonds:
  material: glue
  list: [[4, 9], [9, 2]]
integrator: {time_step: 1e-5}
stop: {end_time: 1e-3}
output: {vtk: false}
)");
  const Scenario scenario = load_scenario(scenario_path);
  const LammpsExport e = export_lammps(scenario);
  EXPECT_EQ(e.bond_types, 1u);  // equal bonds share one coefficient line
  const double A = std::numbers::pi * 0.04, L = 0.4;
  const BpmRotationalStiffness k = bpm_rotational_stiffness(scenario.model.bonds.stiffness[0]);
  EXPECT_NEAR(k.k_r, 30e9 * A / L, 1e-9 * k.k_r);
  EXPECT_NE(e.deck.find("bond_style      bpm/rotational break no"), std::string::npos) << e.deck;
  EXPECT_NE(e.deck.find("run             100\n"), std::string::npos) << e.deck;
  const ExchangeStructure back = read_lammps_data(dir.write("structure.data", e.data));
  const ParticleStore& p = scenario.model.particles;
  ASSERT_EQ(back.particles.id, p.id);
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_EQ(back.particles.position[i].x, p.position[i].x);
    EXPECT_EQ(back.particles.radius[i], p.radius[i]);
    EXPECT_EQ(back.density[i], p.material[i] == 0 ? 2650.0 : 7850.0);
    EXPECT_EQ(back.particles.material_names[back.particles.material[i]],
              scenario.particle_material_names[p.material[i]]);
  }
  EXPECT_EQ(back.bonds.i.size(), 2u);
  EXPECT_EQ(back.bonds.radius, std::vector<double>(2, 0.2));
}

}  // namespace
}  // namespace bpm
