// Two-body analytic tests of the DEM bond kernel (bpm::update_bond_loads) for every registered model:
// one bonded pair, alpha held still, beta given a small prescribed displacement or rotation over one
// step (velocity = increment / dt), and the end loads compared with the unified law written out by
// hand (Chen Tables 1-2 and 6-8): axial k_n d, shear k_s d with its lever-arm moments at the two
// centres, twist k_tor phi, bending k_ben phi.
//
// Sign convention (bond_law.hpp): n points from alpha to beta; the load reported is the one the bond
// exerts on alpha (beta receives the opposite force). Stretching the bond therefore pulls alpha
// towards beta: F_alpha = +k_n d n.
//
// Also: carry_with_bond keeps the stored load attached to the bond under finite rigid rotations and
// twists, and rigid motions create no load.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "common/bond_model_keys.hpp"
#include "bonds/bond_law.hpp"
#include "bonds/bond_model.hpp"
#include "dem/bond_forces.hpp"
#include "model/model.hpp"

namespace bpm {
namespace {

Vec3 unit(const Vec3& v) { return v / norm(v); }

/// Rodrigues rotation of v about unit axis k by angle t (an independent reference, not rotate_gibbs).
Vec3 rotate(const Vec3& v, const Vec3& k, double t) {
  return std::cos(t) * v + std::sin(t) * cross(k, v) + (1.0 - std::cos(t)) * dot(k, v) * k;
}

void expect_vec(const Vec3& actual, const Vec3& expected, double tol, const std::string& what) {
  EXPECT_LE(norm(actual - expected), tol) << what << ": got (" << actual.x << ", " << actual.y << ", "
                                          << actual.z << "), expected (" << expected.x << ", "
                                          << expected.y << ", " << expected.z << ")";
}

using test::model_keys;

/// A bonded pair along an oblique axis n with a right-handed orthonormal frame (n, e1, e2).
/// Unequal radii so that the parallel bond's contact point is off-centre.
struct Pair {
  Model model;
  Vec3 n, e1, e2;
  double length = 0.0;
  BondStiffness k;
  bond_law::Arms arms;  ///< at the rest length

  explicit Pair(const std::string& key, double r_alpha = 1.3e-3, double r_beta = 0.8e-3) {
    n = unit({0.48, -0.64, 0.6});
    e1 = unit(cross(n, {0.0, 0.0, 1.0}));
    e2 = cross(n, e1);
    length = r_alpha + r_beta + 0.3e-3;  // a small gap
    const Vec3 x_alpha{0.01, -0.02, 0.005};
    model.particles.add(0, x_alpha, r_alpha, 7850.0);
    model.particles.add(1, x_alpha + length * n, r_beta, 7850.0);
    BondMaterial m;
    m.model = key;
    m.youngs_modulus = 60e9;
    m.poisson_ratio = 0.25;
    const double r_b = 0.8 * std::min(r_alpha, r_beta);
    const BondConstants c = make_bond_constants(m, {r_b, length, r_alpha, r_beta});
    k = c.stiffness;
    arms = bond_law::contact_arms(length, c.arm_offset);
    model.bonds.add(0, 1, c, r_b, length);
    model.fix(0, {1, 1, 1}, {1, 1, 1});
    model.finalize();
  }

  ParticleStore& p() { return model.particles; }
  BondStore& b() { return model.bonds; }

  /// One kernel call moving beta by (du, dtheta) over dt, as the integrator does: drift the
  /// positions, then update with velocity = increment / dt.
  void move_beta(const Vec3& du, const Vec3& dtheta, double dt = 1e-7) {
    p().position[1] += du;
    p().velocity[1] = du / dt;
    p().angular_velocity[1] = dtheta / dt;
    update_bond_loads(p(), b(), dt);
  }
};

class TwoBodyTest : public ::testing::TestWithParam<std::string> {};

// Increments of 1e-8 L: the geometric (second-order) terms are then ~1e-8 of the loads.
constexpr double kSmall = 1e-8;
constexpr double kRel = 1e-6;

TEST_P(TwoBodyTest, AxialStretch) {
  Pair pair(GetParam());
  const double d = kSmall * pair.length;
  pair.move_beta(d * pair.n, {});
  const double f = pair.k.k_n * d;
  const BondStore& b = pair.b();
  expect_vec(b.end_force_alpha[0], f * pair.n, kRel * f, "force on alpha (pulled towards beta)");
  expect_vec(b.end_moment_alpha[0], {}, kRel * f * pair.length, "moment on alpha");
  expect_vec(b.end_moment_beta[0], {}, kRel * f * pair.length, "moment on beta");
  EXPECT_NEAR(dot(b.force[0], pair.n), f, kRel * f) << "stored normal force";
  // Compression pushes alpha away.
  Pair push(GetParam());
  push.move_beta(-d * push.n, {});
  expect_vec(push.b().end_force_alpha[0], -f * push.n, kRel * f, "compression");
}

TEST_P(TwoBodyTest, ShearWithLeverArms) {
  Pair pair(GetParam());
  const double d = kSmall * pair.length;
  pair.move_beta(d * pair.e1, {});
  const double f = pair.k.k_s * d;
  const BondStore& b = pair.b();
  // Force at the contact point on alpha drags it along e1; each centre takes the lever arm of its own
  // distance to the contact point (Chen Table 2): a_alpha n x F and a_beta n x F, same sense.
  expect_vec(b.end_force_alpha[0], f * pair.e1, kRel * f, "shear force on alpha");
  expect_vec(b.end_moment_alpha[0], pair.arms.alpha * f * pair.e2, kRel * f * pair.length, "moment alpha");
  expect_vec(b.end_moment_beta[0], pair.arms.beta * f * pair.e2, kRel * f * pair.length, "moment beta");
  expect_vec(b.moment[0], {}, kRel * f * pair.length, "no bending moment at the contact point");
  // Total moment about the origin vanishes: x_alpha x F - x_beta x F + M_alpha + M_beta = 0.
  const Vec3 balance = cross(pair.p().position[0], b.end_force_alpha[0]) -
                       cross(pair.p().position[1], b.end_force_alpha[0]) + b.end_moment_alpha[0] +
                       b.end_moment_beta[0];
  expect_vec(balance, {}, 1e-12 * f * pair.length, "moment balance");
}

TEST_P(TwoBodyTest, Twist) {
  Pair pair(GetParam());
  const double phi = kSmall;
  pair.move_beta({}, phi * pair.n);
  const double m = pair.k.k_tor * phi;
  const BondStore& b = pair.b();
  expect_vec(b.end_moment_alpha[0], m * pair.n, kRel * m, "twist moment on alpha");
  expect_vec(b.end_moment_beta[0], -m * pair.n, kRel * m, "twist moment on beta");
  expect_vec(b.end_force_alpha[0], {}, kRel * m / pair.length, "no force from twist");
}

TEST_P(TwoBodyTest, PureBending) {
  // Rotate beta about e2 and translate it so that its material point at the contact does not move:
  // only the relative rotation remains, and the contact moment is k_ben phi.
  Pair pair(GetParam());
  const double phi = kSmall;
  const Vec3 dtheta = phi * pair.e2;
  pair.move_beta(pair.arms.beta * cross(dtheta, pair.n), dtheta);
  const double m = pair.k.k_ben * phi;
  const BondStore& b = pair.b();
  expect_vec(b.end_moment_alpha[0], m * pair.e2, kRel * m, "bending moment on alpha");
  expect_vec(b.end_moment_beta[0], -m * pair.e2, kRel * m, "bending moment on beta");
  expect_vec(b.end_force_alpha[0], {}, kRel * m / pair.length, "no force from pure bending");
}

TEST_P(TwoBodyTest, EndRotationCouplesShearAndBending) {
  // Rotating beta about its centre by phi about e2 moves its contact point by phi e2 x (-a_beta n)
  // = -a_beta phi e1 (frame: e2 x n = e1): shear -k_s a_beta phi e1 on alpha plus bending k_ben phi.
  // For the beams (a = L/2) the centre moments are the Timoshenko element's -k6 phi on alpha and
  // -k5 phi on beta (Chen Eq. 21-22; checked against the element in tests/linear).
  Pair pair(GetParam());
  const double phi = kSmall;
  pair.move_beta({}, phi * pair.e2);
  const double a = pair.arms.alpha, c = pair.arms.beta;
  const double ks = pair.k.k_s, kb = pair.k.k_ben;
  const BondStore& b = pair.b();
  const double scale = (kb + ks * pair.length * pair.length) * phi;
  expect_vec(b.end_force_alpha[0], -ks * c * phi * pair.e1, kRel * scale / pair.length, "force");
  expect_vec(b.end_moment_alpha[0], (kb - ks * a * c) * phi * pair.e2, kRel * scale, "moment alpha");
  expect_vec(b.end_moment_beta[0], -(kb + ks * c * c) * phi * pair.e2, kRel * scale, "moment beta");
}

TEST_P(TwoBodyTest, ResponseIsLinearAndAdditive) {
  // Sum of the single-DOF responses equals the response to the combined increment.
  Pair all(GetParam());
  const double d = kSmall * all.length, phi = kSmall;
  const Vec3 du = d * (0.3 * all.n - 0.7 * all.e1 + 0.2 * all.e2), dth = phi * (0.5 * all.n + 0.4 * all.e1 - 0.9 * all.e2);
  all.move_beta(du, dth);
  Pair u(GetParam()), t(GetParam());
  u.move_beta(du, {});
  t.move_beta({}, dth);
  const double scale = norm(all.b().end_moment_beta[0]);
  expect_vec(all.b().end_force_alpha[0], u.b().end_force_alpha[0] + t.b().end_force_alpha[0],
             kRel * norm(all.b().end_force_alpha[0]), "force");
  expect_vec(all.b().end_moment_beta[0], u.b().end_moment_beta[0] + t.b().end_moment_beta[0], kRel * scale,
             "moment");
}

INSTANTIATE_TEST_SUITE_P(AllModels, TwoBodyTest, ::testing::ValuesIn(model_keys()),
                         [](const ::testing::TestParamInfo<std::string>& param_info) { return param_info.param; });

// ----------------------------------------------------------------------------------------------
// carry_with_bond: rigid motions of a loaded pair.

struct LocalLoads {
  Vec3 force, moment;  ///< components along (n, e1, e2) of the rigidly rotated frame
};

LocalLoads local(const Vec3& f, const Vec3& m, const Vec3& n, const Vec3& e1, const Vec3& e2) {
  return {{dot(f, n), dot(f, e1), dot(f, e2)}, {dot(m, n), dot(m, e1), dot(m, e2)}};
}

/// Loads the pair with every component (axial, both shears, twist, both bendings), then rotates it
/// rigidly about `axis` (through the midpoint) by `total` radians in `steps` kernel calls, with the
/// velocities of the rigid motion at the end of each step and angular velocity Omega for both.
/// Returns the largest relative change of the local components of the stored and the end loads.
struct RigidRotationResult {
  double stored = 0.0, ends = 0.0, magnitude = 0.0;
  /// The one error the kernel makes by design, relative like the fields above: it takes the lever
  /// arm's motion as omega x d_mid dt, while a rotation by phi moves it by 2 tan(phi/2) x d_mid, so
  /// each step adds a transverse force k_s L phi^3 / 12; after total = steps * phi that is
  /// k_s L total phi^2 / 12 (and L times it in the end moments). Second order in phi.
  double chord_bound = 0.0;
};

RigidRotationResult rotate_loaded_pair(const std::string& key, const Vec3& axis, double total, int steps,
                                       bool loaded = true) {
  Pair pair(key);
  ParticleStore& p = pair.p();
  BondStore& b = pair.b();
  if (loaded) {
    const double d = 1e-3 * pair.length;
    pair.move_beta(d * (0.5 * pair.n + 0.8 * pair.e1 - 0.6 * pair.e2), 1e-3 * (0.7 * pair.n - 0.4 * pair.e1 + 0.9 * pair.e2));
  }
  p.velocity[1] = {};
  p.angular_velocity[1] = {};
  const LocalLoads s0 = local(b.force[0], b.moment[0], pair.n, pair.e1, pair.e2);
  const LocalLoads e0 = local(b.end_force_alpha[0], b.end_moment_beta[0], pair.n, pair.e1, pair.e2);
  const Vec3 x0[2] = {p.position[0], p.position[1]};
  const Vec3 centre = 0.5 * (x0[0] + x0[1]);
  const double dt = 1e-6, step = total / steps;
  const Vec3 omega = (step / dt) * axis;
  for (int s = 1; s <= steps; ++s) {
    const double angle = step * s;
    for (int i = 0; i < 2; ++i) {
      // As in velocity Verlet, the kernel sees the positions at the end of the step and the
      // half-step velocities, i.e. the chord of the step divided by dt.
      const Vec3 x_new = centre + rotate(x0[i] - centre, axis, angle);
      p.velocity[i] = (x_new - p.position[i]) / dt;
      p.position[i] = x_new;
      p.angular_velocity[i] = omega;
    }
    update_bond_loads(p, b, dt);
  }
  // The loaded pair's own frame, rotated rigidly. n itself is taken from the final positions.
  const Vec3 n = rotate(pair.n, axis, total), e1 = rotate(pair.e1, axis, total), e2 = rotate(pair.e2, axis, total);
  const LocalLoads s1 = local(b.force[0], b.moment[0], n, e1, e2);
  const LocalLoads e1l = local(b.end_force_alpha[0], b.end_moment_beta[0], n, e1, e2);
  RigidRotationResult r;
  const double f0 = loaded ? norm(s0.force) : pair.k.k_n * pair.length;
  const double m0 = loaded ? norm(s0.moment) : pair.k.k_ben;
  const double fe = loaded ? norm(e0.force) : f0, me = loaded ? norm(e0.moment) : m0;
  r.stored = std::max(norm(s1.force - s0.force) / f0, norm(s1.moment - s0.moment) / m0);
  r.ends = std::max(norm(e1l.force - e0.force) / fe, norm(e1l.moment - e0.moment) / me);
  r.magnitude = std::max(std::abs(norm(b.force[0]) - norm(s0.force)) / f0,
                         std::abs(norm(b.moment[0]) - norm(s0.moment)) / m0);
  const double chord_force = pair.k.k_s * pair.length * total * step * step / 12.0;
  r.chord_bound = std::max({chord_force / f0, chord_force / fe, chord_force * pair.length / me});
  return r;
}

class CarryTest : public ::testing::TestWithParam<std::string> {};

TEST_P(CarryTest, RigidSwingKeepsLocalLoads) {
  // Rotation axis perpendicular to the bond: the bond swings through 1 rad.
  const Pair ref(GetParam());
  const RigidRotationResult r = rotate_loaded_pair(GetParam(), ref.e2, 1.0, 20000);
  EXPECT_LT(r.magnitude, 1e-10 + r.chord_bound);
  EXPECT_LT(r.stored, 1e-10 + r.chord_bound);
  EXPECT_LT(r.ends, 1e-10 + r.chord_bound);
  // ... and that error is the chord term: half the step, a quarter of the error.
  const RigidRotationResult fine = rotate_loaded_pair(GetParam(), ref.e2, 1.0, 40000);
  EXPECT_NEAR(r.ends / fine.ends, 4.0, 0.2);
}

TEST_P(CarryTest, RigidTwistKeepsLocalLoads) {
  // Rotation about the bond axis: the stored shear force and bending moment turn with the particles.
  // 1e-5 rad per step: the Gibbs twist's psi^3/12 per step then sums to 1e-11 over 1 rad.
  const Pair ref(GetParam());
  const RigidRotationResult r = rotate_loaded_pair(GetParam(), ref.n, 1.0, 100000);
  EXPECT_LT(r.magnitude, 1e-10);
  EXPECT_LT(r.stored, 1e-10);
  EXPECT_LT(r.ends, 1e-10);
}

TEST_P(CarryTest, RigidObliqueRotationKeepsLocalLoads) {
  const Pair ref(GetParam());
  const Vec3 axis = unit(0.6 * ref.n + 0.3 * ref.e1 - 0.74 * ref.e2);
  const RigidRotationResult r = rotate_loaded_pair(GetParam(), axis, 1.0, 100000);
  EXPECT_LT(r.magnitude, 1e-10 + r.chord_bound);
  EXPECT_LT(r.stored, 1e-10 + r.chord_bound);
  EXPECT_LT(r.ends, 1e-10 + r.chord_bound);
}

TEST_P(CarryTest, RigidMotionCreatesNoLoad) {
  // Unloaded pair: a rigid swing, a rigid twist and a rigid translation leave it unloaded (relative to
  // the loads of a unit strain and a unit rotation), up to the chord term of RigidRotationResult.
  const Pair ref(GetParam());
  for (const Vec3& axis : {ref.e1, ref.n, unit(ref.n + ref.e1 + ref.e2)}) {
    const RigidRotationResult r = rotate_loaded_pair(GetParam(), axis, 0.5, 5000, false);
    EXPECT_LT(r.stored, 1e-14 + r.chord_bound);
    EXPECT_LT(r.ends, 1e-14 + r.chord_bound);
  }
  Pair pair(GetParam());
  const Vec3 v{0.3, -1.2, 0.8};
  const double dt = 1e-6;
  for (int s = 0; s < 1000; ++s) {
    for (int i = 0; i < 2; ++i) {
      pair.p().position[i] += v * dt;
      pair.p().velocity[i] = v;
    }
    update_bond_loads(pair.p(), pair.b(), dt);
  }
  EXPECT_LT(norm(pair.b().force[0]), 1e-13 * pair.k.k_n * pair.length);
  EXPECT_LT(norm(pair.b().moment[0]), 1e-13 * pair.k.k_ben);
}

INSTANTIATE_TEST_SUITE_P(AllModels, CarryTest, ::testing::ValuesIn(model_keys()),
                         [](const ::testing::TestParamInfo<std::string>& param_info) { return param_info.param; });

}  // namespace
}  // namespace bpm
