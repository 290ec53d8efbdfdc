#pragma once
/// The volume V^n each particle represents (Jarolin Eq. 12: "the volume of the sub-domain the
/// particle is representing"), by one of two methods:
/// - radical (Laguerre) Voronoi cells of the spheres (voro++ container_poly: radii differ), clipped
///   to the sample's convex body (SampleHull), so that boundary cells end at the sample surface and
///   the cells tile the body exactly: sum V^n = SampleHull::volume() (that is measure_sample's l A
///   for the same M directions when the sample's faces are among them);
/// - the solid fraction: V^n = (4/3 pi R_n^3) / phi with phi = sum of sphere volumes / (l A), the
///   same fraction for every particle (fast; ignores local density variations).
#include <vector>

#include "compress/sample_geometry.hpp"
#include "core/vec3.hpp"
#include "model/particle_store.hpp"

namespace bpm::ste {

/// The sample's convex body as half-spaces normal . x <= offset:
/// - the bottom and top planes normal to the loading axis at the sample's extremes
///   (min(x.a - R), max(x.a + R), as measure_sample);
/// - side planes tangent to the particles' discs in the cross-section (support function
///   h(u) = max(x.u + R)): `side_planes` directions evenly spaced, at the angles and in the basis
///   measure_sample uses (so with no other planes the prism has measure_sample's l and A), plus the
///   outer tangents of consecutive discs on the convex hull of the projected centres (edges longer
///   than the largest diameter, longest first, at most `face_planes`). Those make flat faces exact
///   whatever their orientation; evenly spaced directions alone overestimate a flat face's area to
///   first order in the angle step (up to Delta/8 of its length squared for a face lying between
///   two directions: ~0.3 % of A for a turned box with 360 directions, ~3 % with 36).
/// The Voronoi container is the bounding box of the spheres, so the cells fill the prism cut by
/// that box (the prism itself when the axis is a coordinate axis of a box-like or cylindrical sample).
struct SampleHull {
  Vec3 axis, e1, e2;              ///< unit axis and cross-section basis (measure_sample's)
  double bottom = 0.0, top = 0.0;  ///< m
  double area = 0.0;              ///< of the cross-section polygon of the side planes, m^2
  std::vector<Vec3> normal;       ///< unit, outward: bottom, top, then the side planes
  std::vector<double> offset;     ///< m

  double volume() const { return (top - bottom) * area; }  ///< of the prism, m^3
};

SampleHull sample_hull(const ParticleStore& particles, const Vec3& axis, int side_planes, int face_planes = 32);

/// A part of a computation divided between processes (the ranks of an mpirun): this process does
/// part `part` of `parts`.
struct WorkShare {
  int part = 0;
  int parts = 1;
};

/// Radical Voronoi cell volume of every particle clipped to the hull, m^3 (0 for a particle whose
/// cell vanishes, which a much smaller particle squeezed between large ones can have). Bitwise the
/// same for any thread count (each cell is computed alone, the blocks do not depend on threads).
/// With a share, only the cells of that share of voro++'s blocks (contiguous ranges) are computed
/// and the others' volumes are 0: every particle is in one block, so the sum over the parts is the
/// whole result, bit for bit.
std::vector<double> voronoi_volumes(const ParticleStore& particles, const SampleHull& hull, WorkShare share = {});

/// V^n = (4/3 pi R_n^3) / phi, phi = sum(4/3 pi R^3) / sample_volume; m^3.
std::vector<double> solid_fraction_volumes(const ParticleStore& particles, double sample_volume);

/// Solid fraction phi = sum(4/3 pi R^3) / sample_volume.
double solid_fraction(const ParticleStore& particles, double sample_volume);

}  // namespace bpm::ste
