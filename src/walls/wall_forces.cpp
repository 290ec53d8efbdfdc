#include "walls/wall_forces.hpp"

#include <algorithm>
#include <string>

#include "contacts/contact_law.hpp"
#include "core/error.hpp"
#include "core/parallel.hpp"

namespace bpm {

namespace {

constexpr std::int64_t kBlock = 1024;  // particles per partial sum of a wall force

std::string where(const Wall& w, std::size_t index) {
  return "wall " + std::to_string(index) + (w.name.empty() ? "" : " '" + w.name + "'");
}

void validate(Wall& w, std::size_t index, std::int32_t materials) {
  if (w.material < 0 || w.material >= materials) {
    throw InputError(where(w, index), "material " + std::to_string(w.material) + " is not a contact material");
  }
  const double length = norm(w.normal);
  if (!(length > 0.0)) throw InputError(where(w, index), "the normal (axis) must not be zero");
  w.normal *= 1.0 / length;
  if (w.shape == WallShape::rectangle) {
    w.edge -= dot(w.edge, w.normal) * w.normal;
    const double e = norm(w.edge);
    if (!(e > 1e-12)) throw InputError(where(w, index), "the edge must not be parallel to the normal");
    w.edge *= 1.0 / e;
    if (!(w.half_width > 0.0 && w.half_height > 0.0)) {
      throw InputError(where(w, index), "a rectangle needs half_width > 0 and half_height > 0");
    }
  }
  if ((w.shape == WallShape::disc || w.shape == WallShape::cylinder) && !(w.radius > 0.0)) {
    throw InputError(where(w, index), "a disc or cylinder needs radius > 0");
  }
  if (w.servo.enabled) {
    if (w.shape == WallShape::cylinder) throw InputError(where(w, index), "only flat walls can be servo-controlled");
    if (!(w.servo.gain > 0.0) || !(w.servo.max_speed > 0.0)) {
      throw InputError(where(w, index), "a servo needs gain > 0 (m/(N s)) and max_speed > 0");
    }
  }
}

}  // namespace

WallForces::WallForces(const ContactTable& table, std::vector<Wall>& walls, const ParticleStore& particles)
    : table_(table) {
  for (std::size_t k = 0; k < walls.size(); ++k) {
    validate(walls[k], k, table.size());
    walls[k].spring.resize(particles.size());
  }
  for (std::size_t i = 0; i < particles.size(); ++i) {
    if (!walls.empty() && (particles.material[i] < 0 || particles.material[i] >= table.size())) {
      throw InputError("particle " + std::to_string(particles.id[i]),
                       "material " + std::to_string(particles.material[i]) + " has no contact constants",
                       "give one contact material per particle material");
    }
  }
  force_.assign(particles.size(), {});
  torque_.assign(particles.size(), {});
}

void WallForces::compute(std::vector<Wall>& walls, const ParticleStore& particles, double increment_dt, double dt) {
  const auto n = static_cast<std::int64_t>(particles.size());
  const auto n_walls = static_cast<std::int64_t>(walls.size());
  const Vec3* x = particles.position.data();
  const Vec3* v = particles.velocity.data();
  const Vec3* w = particles.angular_velocity.data();
  force_.resize(particles.size());
  torque_.resize(particles.size());
  for (Wall& wall : walls) wall.spring.resize(particles.size());
  // One pass over the particles, each visiting the walls in order: a particle's sums are those of
  // a loop over walls then particles, term by term, but the arrays are written once per step and a
  // particle away from every wall stores nothing but its zero sums (most particles are).
  const std::int64_t blocks = (n + kBlock - 1) / kBlock;
  block_sums_.resize(static_cast<std::size_t>(blocks * n_walls));  // allocates on the first step only
  parallel_for(blocks, n > kParallelMinItems, [&](std::int64_t b) {
    Vec3* wall_sums = block_sums_.data() + b * n_walls;
    std::fill(wall_sums, wall_sums + n_walls, Vec3{});
    for (std::int64_t i = b * kBlock; i < std::min(n, (b + 1) * kBlock); ++i) {
      Vec3 force, torque;
      for (std::int64_t k = 0; k < n_walls; ++k) {
        Wall& wall = walls[static_cast<std::size_t>(k)];
        const wall_geometry::Gap g = wall_geometry::gap(wall, x[i], particles.radius[i]);
        if (!(g.overlap > 0.0)) {
          if (!all_bits_zero(wall.spring[i])) wall.spring[i] = {};  // the spring is lost
          continue;
        }
        const ContactPairParameters& c = table_(particles.material[i], wall.material);
        // The wall is the rigid partner j: R* = R, m* = m, I* = I; it translates without spin.
        const Vec3 v_rel = wall.velocity - (v[i] + g.arm * cross(w[i], g.n));
        const contact_law::ContactLoad load =
            contact_law::evaluate(c, {particles.radius[i], particles.mass[i], particles.inertia[i]},
                                  {g.n, g.overlap, v_rel, w[i]}, wall.spring[i], increment_dt, dt);
        force += load.force;
        torque += g.arm * cross(g.n, load.force) + load.rolling_torque;
        wall_sums[k] -= load.force;  // the wall receives the opposite
      }
      force_[i] = force;
      torque_[i] = torque;
    }
  });
  // Each wall's force: the fixed blocks' sums, added in block order.
  for (std::int64_t k = 0; k < n_walls; ++k) {
    Vec3 total;
    for (std::int64_t b = 0; b < blocks; ++b) total += block_sums_[static_cast<std::size_t>(b * n_walls + k)];
    walls[static_cast<std::size_t>(k)].force = total;
  }
}

void WallForces::gather(ParticleStore& particles) const {
  const auto n = static_cast<std::int64_t>(std::min(particles.size(), force_.size()));
  parallel_for(n, [&](std::int64_t i) {
    particles.force[i] += force_[i];
    particles.torque[i] += torque_[i];
  });
}

double WallForces::elastic_energy(const std::vector<Wall>& walls, const ParticleStore& particles) const {
  double energy = 0.0;
  for (const Wall& wall : walls) {
    for (std::size_t i = 0; i < particles.size(); ++i) {
      const wall_geometry::Gap g = wall_geometry::gap(wall, particles.position[i], particles.radius[i]);
      if (!(g.overlap > 0.0)) continue;
      energy += contact_law::elastic_energy(table_(particles.material[i], wall.material),
                                            {particles.radius[i], particles.mass[i], particles.inertia[i]},
                                            g.overlap, i < wall.spring.size() ? wall.spring[i] : Vec3{});
    }
  }
  return energy;
}

void advance_walls(std::vector<Wall>& walls, double dt) {
  for (Wall& w : walls) {
    w.point += w.velocity * dt;
    w.displacement += w.velocity * dt;
  }
}

void control_walls(std::vector<Wall>& walls) {
  for (Wall& w : walls) {
    if (!w.servo.enabled) continue;
    const double compressive = -dot(w.force, w.normal);
    const double speed = std::clamp(w.servo.gain * (w.servo.target_force - compressive), -w.servo.max_speed,
                                    w.servo.max_speed);
    w.velocity = speed * w.normal;
  }
}

}  // namespace bpm
