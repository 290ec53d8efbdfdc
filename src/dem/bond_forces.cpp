#include "dem/bond_forces.hpp"

#include <algorithm>
#include <cstdint>
#include <functional>

#if defined(__AVX512F__) || defined(__AVX__)
#include <immintrin.h>
#endif

#include "bonds/bond_law.hpp"
#include "bonds/bond_strength.hpp"
#include "core/parallel.hpp"
#include "dem/block_transpose.hpp"

namespace bpm {

namespace {

/// Bonds are updated in blocks of kLanes: the particle data and bond state of a block are copied
/// into component arrays (one array per x, y, z) so that the bond law runs vectorised across the
/// bonds of the block (`omp simd`), then the results are copied back. Every bond, including those
/// of the last, partial block, goes through the same instructions, so a bond's result does not
/// depend on its position in the block, on the block's thread or on the number of threads.
constexpr int kLanes = 8;  // one AVX-512 register of doubles

using Lanes = double[kLanes];
using Vec3Lanes = double[3][kLanes];

/// One block's inputs, gathered from the particles and the bond store.
struct alignas(64) BlockIn {
  Vec3Lanes d;   ///< x_beta - x_alpha (end of step)
  Vec3Lanes dv;  ///< v_beta - v_alpha (over the step)
  Vec3Lanes w_alpha, w_beta;
  Vec3Lanes force, moment, axis;  ///< stored state of the last step
  Lanes k_n, k_s, k_tor, k_ben, arm_offset, damping_force, damping_moment;
};

/// Mid-step chord and the two lengths: a separate pass because the square roots do not
/// vectorise inside an `omp simd` loop (std::sqrt may set errno), see take_roots.
struct alignas(64) BlockAxes {
  Vec3Lanes d_mid;
  Lanes length, length_mid;
};

/// One block's results, scattered back to the bond store.
struct alignas(64) BlockOut {
  Vec3Lanes force, moment, axis;
  Vec3Lanes end_force_alpha, end_moment_alpha, end_moment_beta;
};

inline Vec3 lane(const Vec3Lanes& c, int k) {
  return {c[0][k], c[1][k], c[2][k]};
}

inline void set_lane(Vec3Lanes& c, int k, const Vec3& v) {
  c[0][k] = v.x;
  c[1][k] = v.y;
  c[2][k] = v.z;
}

/// Copies bond i's data into lane k.
[[gnu::always_inline]] inline void gather_lane(const ParticleStore& particles,
                                               const BondStore& bonds, std::size_t i, int k,
                                               BlockIn& in) {
  const Vec3* x = particles.position.data();
  const Vec3* v = particles.velocity.data();
  const Vec3* w = particles.angular_velocity.data();
  const std::int32_t a = bonds.alpha[i], b = bonds.beta[i];
  set_lane(in.d, k, x[b] - x[a]);
  set_lane(in.dv, k, v[b] - v[a]);
  set_lane(in.w_alpha, k, w[a]);
  set_lane(in.w_beta, k, w[b]);
  set_lane(in.force, k, bonds.force[i]);
  set_lane(in.moment, k, bonds.moment[i]);
  set_lane(in.axis, k, bonds.axis[i]);
  const BondStiffness& s = bonds.stiffness[i];
  in.k_n[k] = s.k_n;
  in.k_s[k] = s.k_s;
  in.k_tor[k] = s.k_tor;
  in.k_ben[k] = s.k_ben;
  in.arm_offset[k] = bonds.arm_offset[i];
  in.damping_force[k] = bonds.damping_force[i];
  in.damping_moment[k] = bonds.damping_moment[i];
}

#if defined(BPMKIT_BLOCK_TRANSPOSE)
static_assert(kLanes == 8, "block_transpose moves blocks of eight");

/// Copies the data of the full block starting at bond `first` in: the rows are loaded whole and
/// transposed in registers (block_transpose.hpp), the same numbers as gather_lane's.
inline void gather_block(const ParticleStore& particles, const BondStore& bonds, std::int64_t first,
                         BlockIn& in) {
  namespace bt = block_transpose;
  const auto i = static_cast<std::size_t>(first);
  const std::int32_t* alpha = bonds.alpha.data() + i;
  const std::int32_t* beta = bonds.beta.data() + i;
  const auto differences = [&](const Vec3* rows, bt::Components& c) {
    __m256d r[kLanes];
    for (int k = 0; k < kLanes; ++k)
      r[k] = _mm256_sub_pd(bt::row(rows, beta[k]), bt::row(rows, alpha[k]));
    bt::rows_to_components(r, c);
  };
  const auto rows_of = [&](const Vec3* rows, const std::int32_t* index, bt::Components& c) {
    __m256d r[kLanes];
    for (int k = 0; k < kLanes; ++k) r[k] = bt::row(rows, index[k]);
    bt::rows_to_components(r, c);
  };
  differences(particles.position.data(), in.d);
  differences(particles.velocity.data(), in.dv);
  rows_of(particles.angular_velocity.data(), alpha, in.w_alpha);
  rows_of(particles.angular_velocity.data(), beta, in.w_beta);
  bt::aos_to_components(bonds.force.data() + i, in.force);
  bt::aos_to_components(bonds.moment.data() + i, in.moment);
  bt::aos_to_components(bonds.axis.data() + i, in.axis);
  bt::stiffness_to_components(bonds.stiffness.data() + i, in.k_n, in.k_s, in.k_tor, in.k_ben);
  _mm512_store_pd(in.arm_offset, _mm512_loadu_pd(bonds.arm_offset.data() + i));
  _mm512_store_pd(in.damping_force, _mm512_loadu_pd(bonds.damping_force.data() + i));
  _mm512_store_pd(in.damping_moment, _mm512_loadu_pd(bonds.damping_moment.data() + i));
}
#else
/// Copies the data of the full block starting at bond `first` in, vectorised: written lane by lane
/// with scalar stores, the arrays would be read back by vector loads before those stores have left
/// the store buffer, which stalls (failed store forwarding; 15 % of the kernel when it was so).
inline void gather_block(const ParticleStore& particles, const BondStore& bonds, std::int64_t first,
                         BlockIn& in) {
#pragma omp simd
  for (int k = 0; k < kLanes; ++k)
    gather_lane(particles, bonds, static_cast<std::size_t>(first + k), k, in);
}
#endif

/// The last, partial block: lanes past the last bond repeat it (valid numbers, never stored).
inline void gather_tail(const ParticleStore& particles, const BondStore& bonds, std::int64_t first,
                        std::int64_t last, BlockIn& in) {
  for (int k = 0; k < kLanes; ++k) {
    gather_lane(particles, bonds, static_cast<std::size_t>(std::min(first + k, last - 1)), k, in);
  }
}

/// values[k] = sqrt(values[k]), correctly rounded (IEEE) on every path, so the same bits as
/// std::sqrt; the intrinsics only make it one vector instruction.
inline void take_roots(Lanes& values) {
#if defined(__AVX512F__)
  static_assert(kLanes % 8 == 0);
  for (int k = 0; k < kLanes; k += 8)
    _mm512_store_pd(values + k, _mm512_sqrt_pd(_mm512_load_pd(values + k)));
#elif defined(__AVX__)
  static_assert(kLanes % 4 == 0);
  for (int k = 0; k < kLanes; k += 4)
    _mm256_store_pd(values + k, _mm256_sqrt_pd(_mm256_load_pd(values + k)));
#else
  for (double& value : values) value = std::sqrt(value);
#endif
}

/// The half-step velocities are the chord of the step, so the relative motion is taken in the
/// mid-step configuration d - (v_b - v_a) dt/2. On the end-of-step axis a rigid spin by phi per
/// step would show an axial chord L (1 - cos phi) and ratchet the normal force (first-order energy
/// drift); on the mid-step axis the chord of a rotation has no axial part.
[[gnu::always_inline]] inline void lane_axes(const BlockIn& in, double dt, BlockAxes& axes, int k) {
  const Vec3 d = lane(in.d, k);
  const Vec3 d_mid = d - (0.5 * dt) * lane(in.dv, k);
  set_lane(axes.d_mid, k, d_mid);
  axes.length[k] = norm2(d);
  axes.length_mid[k] = norm2(d_mid);
}

/// The lanes' mid-step chords and lengths (lane_axes is a function of its own for the reason
/// given at lane_law). The lengths go through vector stores and loads only (no failed forwarding).
inline void block_axes(const BlockIn& in, double dt, BlockAxes& axes) {
#pragma omp simd
  for (int k = 0; k < kLanes; ++k) lane_axes(in, dt, axes, k);
  take_roots(axes.length);
  take_roots(axes.length_mid);
}

/// Chen Table 8 (incremental) for lane k of the block: carry the stored load with the bond, add
/// the elastic increment of the step's relative motion, and transfer the total (elastic plus
/// viscous bond damping, Chen Eq. 9-10, which acts on the rates and is not stored) to the centres.
/// A function of its own so that its locals (passed by reference to the law) are not OpenMP simd
/// privates of block_law's loop: GCC would keep those in memory and not vectorise.
[[gnu::always_inline]] inline void lane_law(const BlockIn& in, const BlockAxes& axes, double dt,
                                            BlockOut& out, int k) {
  const double length = axes.length[k], length_mid = axes.length_mid[k];
  const Vec3 n = lane(in.d, k) * (1.0 / length);
  const Vec3 n_mid = lane(axes.d_mid, k) * (1.0 / length_mid);
  const Vec3 w_alpha = lane(in.w_alpha, k), w_beta = lane(in.w_beta, k);
  Vec3 force = lane(in.force, k), moment = lane(in.moment, k);
  bond_law::carry_with_bond(force, moment, lane(in.axis, k), n,
                            0.5 * dot(w_alpha + w_beta, n_mid) * dt);
  // The law is linear in the velocities: alpha's is passed as zero and beta's as the difference.
  const bond_law::RelativeMotion rate =
      bond_law::relative_motion(n_mid, bond_law::contact_arms(length_mid, in.arm_offset[k]), Vec3{},
                                w_alpha, lane(in.dv, k), w_beta);
  const BondStiffness stiffness{in.k_n[k], in.k_s[k], in.k_tor[k], in.k_ben[k]};
  const bond_law::BondLoads increment = bond_law::elastic_response(stiffness, n_mid, rate);
  force += increment.force * dt;
  moment += increment.moment * dt;
  const bond_law::BondLoads total{force + in.damping_force[k] * rate.translation,
                                  moment + in.damping_moment[k] * rate.rotation};
  const bond_law::EndLoads ends =
      bond_law::transfer_to_centres(n, bond_law::contact_arms(length, in.arm_offset[k]), total);
  set_lane(out.force, k, force);
  set_lane(out.moment, k, moment);
  set_lane(out.axis, k, n);
  set_lane(out.end_force_alpha, k, ends.force_alpha);
  set_lane(out.end_moment_alpha, k, ends.moment_alpha);
  set_lane(out.end_moment_beta, k, ends.moment_beta);
}

/// The law for all lanes, vectorised across the bonds of the block.
inline void block_law(const BlockIn& in, const BlockAxes& axes, double dt, BlockOut& out) {
#pragma omp simd
  for (int k = 0; k < kLanes; ++k) lane_law(in, axes, dt, out, k);
}

/// target = lane k of c, component by component (a whole-struct copy does not vectorise).
[[gnu::always_inline]] inline void copy_lane(const Vec3Lanes& c, int k, Vec3& target) {
  target.x = c[0][k];
  target.y = c[1][k];
  target.z = c[2][k];
}

/// Writes lane k's results to bond i.
[[gnu::always_inline]] inline void store_lane(const BlockOut& out, int k, BondStore& bonds,
                                              std::size_t i) {
  copy_lane(out.force, k, bonds.force[i]);
  copy_lane(out.moment, k, bonds.moment[i]);
  copy_lane(out.axis, k, bonds.axis[i]);
  copy_lane(out.end_force_alpha, k, bonds.end_force_alpha[i]);
  copy_lane(out.end_moment_alpha, k, bonds.end_moment_alpha[i]);
  copy_lane(out.end_moment_beta, k, bonds.end_moment_beta[i]);
}

/// Stores the full block starting at bond `first` (all of its bonds intact).
inline void scatter_block(const BlockOut& out, BondStore& bonds, std::int64_t first) {
#if defined(BPMKIT_BLOCK_TRANSPOSE)
  const auto i = static_cast<std::size_t>(first);
  block_transpose::components_to_aos(out.force, bonds.force.data() + i);
  block_transpose::components_to_aos(out.moment, bonds.moment.data() + i);
  block_transpose::components_to_aos(out.axis, bonds.axis.data() + i);
  block_transpose::components_to_aos(out.end_force_alpha, bonds.end_force_alpha.data() + i);
  block_transpose::components_to_aos(out.end_moment_alpha, bonds.end_moment_alpha.data() + i);
  block_transpose::components_to_aos(out.end_moment_beta, bonds.end_moment_beta.data() + i);
#else
#pragma omp simd
  for (int k = 0; k < kLanes; ++k) store_lane(out, k, bonds, static_cast<std::size_t>(first + k));
#endif
}

/// Stores the bonds [first, first + count) of the last, partial block.
inline void scatter_tail(const BlockOut& out, BondStore& bonds, std::int64_t first, int count) {
  for (int k = 0; k < count; ++k) store_lane(out, k, bonds, static_cast<std::size_t>(first + k));
}

/// The breakable variant: skips broken bonds (their end loads were zeroed when they broke) and
/// checks the strength of the others. Returns whether one broke.
bool scatter_breakable_block(const BlockOut& out, BondStore& bonds, std::int64_t first, int count) {
  bool any_broke = false;
  for (int k = 0; k < count; ++k) {
    const auto i = static_cast<std::size_t>(first + k);
    if (bonds.intact[i] != 1) continue;
    const Vec3 n = lane(out.axis, k);
    if (const std::uint8_t mode = failure_mode(n, lane(out.force, k), lane(out.moment, k),
                                               bonds.radius[i], bonds.strength[i])) {
      bonds.intact[i] = 2;  // recorded (and set to 0) by record_breaks after the loop
      bonds.break_mode[i] = mode;
      bonds.axis[i] = n;
      bonds.force[i] = bonds.moment[i] = Vec3{};
      bonds.end_force_alpha[i] = bonds.end_moment_alpha[i] = bonds.end_moment_beta[i] = Vec3{};
      any_broke = true;
      continue;
    }
    store_lane(out, k, bonds, i);
  }
  return any_broke;
}

/// The bond loop, over blocks. Without breakable bonds the strength check compiles away.
template <bool kBreakable>
bool update_bond_loads_impl(const ParticleStore& particles, BondStore& bonds, double dt) {
  const auto n_bonds = static_cast<std::int64_t>(bonds.size());
  const std::int64_t n_blocks = (n_bonds + kLanes - 1) / kLanes;
  const auto block_loads = [&](std::int64_t block) {
    const std::int64_t first = block * kLanes;
    const int count = static_cast<int>(std::min<std::int64_t>(kLanes, n_bonds - first));
    BlockIn in;
    BlockAxes axes;
    BlockOut out;
    if (count == kLanes) {
      gather_block(particles, bonds, first, in);
    } else {
      gather_tail(particles, bonds, first, n_bonds, in);
    }
    block_axes(in, dt, axes);
    block_law(in, axes, dt, out);
    if constexpr (kBreakable) {
      return scatter_breakable_block(out, bonds, first, count);
    } else if (count == kLanes) {
      scatter_block(out, bonds, first);
    } else {
      scatter_tail(out, bonds, first, count);
    }
    return false;
  };
  return parallel_reduce(n_blocks, n_bonds > kParallelMinItems, false, block_loads,
                         std::logical_or<>());
}

/// Logs the bonds the last update broke, in bond order (so the log is the same for any thread
/// count).
void record_breaks(const ParticleStore& particles, BondStore& bonds) {
  for (std::size_t i = 0; i < bonds.size(); ++i) {
    if (bonds.intact[i] != 2) continue;
    bonds.intact[i] = 0;
    const Vec3 xa = particles.position[bonds.alpha[i]], xb = particles.position[bonds.beta[i]];
    const double length = norm(xb - xa);
    const bond_law::Arms arms = bond_law::contact_arms(length, bonds.arm_offset[i]);
    bonds.breaks.push_back({static_cast<std::int32_t>(i), bonds.updates,
                            static_cast<BreakMode>(bonds.break_mode[i]),
                            xa + (arms.alpha / length) * (xb - xa)});
  }
}

}  // namespace

void update_bond_loads(const ParticleStore& particles, BondStore& bonds, double dt) {
  ++bonds.updates;
  if (!bonds.breakable) {
    update_bond_loads_impl<false>(particles, bonds, dt);
  } else if (update_bond_loads_impl<true>(particles, bonds, dt)) {
    record_breaks(particles, bonds);
  }
}

void gather_bond_loads(ParticleStore& particles, const BondStore& bonds) {
  const auto n_particles = static_cast<std::int64_t>(particles.size());
  parallel_for(n_particles, [&](std::int64_t p) {
    Vec3 force, torque;  // locals: the arrays might alias the bonds' loads
    sum_bond_loads(bonds, p, force, torque);
    particles.force[p] = force;
    particles.torque[p] = torque;
  });
}

}  // namespace bpm
