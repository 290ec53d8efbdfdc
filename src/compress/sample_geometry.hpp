#pragma once
/// Length and cross-section of a sample along a loading axis, measured from the body the particles
/// form (Jarolin section 4.2: "calculated from the body formed by the primary particles"):
///   l = max(x.a + R) - min(x.a - R) over the particles, a the unit axis;
///   A = area of the convex hull of the particles' projections onto the plane normal to a, each a
///       disc of its radius. The hull is built from its support function h(u) = max(x.u + R) in
///       `directions` directions; the circumscribed polygon overestimates a circle by
///       (pi/M)^2/3 (2.5e-5 for M = 360).
/// For a cylinder of radius r along a this gives A = pi r^2; for a box, its face. Samples whose
/// cross-section is not convex (or varies along the axis) need the layered model of the STE.
#include "core/vec3.hpp"
#include "model/particle_store.hpp"

namespace bpm {

struct SampleGeometry {
  double bottom = 0.0;  ///< min(x.a - R), m
  double top = 0.0;     ///< max(x.a + R), m
  double length = 0.0;  ///< l = top - bottom, m
  double area = 0.0;    ///< A, m^2
};

SampleGeometry measure_sample(const ParticleStore& particles, const Vec3& axis, int directions = 360);

}  // namespace bpm
