#pragma once
/// Particles as structure of arrays: one contiguous array per field, indexed by the particle's
/// position in the store (0..size-1). User ids are kept for input and output only.
#include <cstdint>
#include <vector>

#include "core/quaternion.hpp"
#include "core/vec3.hpp"

namespace bpm {

struct ParticleStore {
  std::vector<std::int64_t> id;          ///< user id (from the scenario), for I/O
  std::vector<double> radius;            ///< R, m
  std::vector<double> mass;              ///< m, kg
  std::vector<double> inertia;           ///< I = 2/5 m R^2 (solid sphere), kg m^2
  std::vector<std::int32_t> material;    ///< index into the scenario's particle materials
  std::vector<Vec3> reference_position;  ///< x at t = 0, for displacements
  std::vector<Vec3> position;            ///< x, m
  std::vector<Vec3> velocity;            ///< U, m/s
  std::vector<Vec3> angular_velocity;    ///< omega, rad/s (global frame)
  std::vector<Quat> orientation;         ///< rotation from the reference state
  std::vector<Vec3> force;               ///< total force of the last evaluation, N
  std::vector<Vec3> torque;              ///< total moment of the last evaluation, N m
  /// 1 for a free degree of freedom, 0 for a fixed one (fixed or velocity-prescribed). Multiplying
  /// the acceleration by the mask keeps the integrator branch-free.
  std::vector<Vec3> translation_free;
  std::vector<Vec3> rotation_free;

  std::size_t size() const { return radius.size(); }

  /// Appends a solid sphere of the given density at rest; returns its index.
  std::int32_t add(std::int64_t user_id, const Vec3& x, double r, double density, std::int32_t mat = 0);

  /// Puts particle old_at[k] at index k, every field with it (model/spatial_order.hpp). Indices
  /// held elsewhere (bonds, loads, probes) are not renumbered: reorder before handing them out.
  void reorder(const std::vector<std::int32_t>& old_at);
};

}  // namespace bpm
