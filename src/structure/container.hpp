#pragma once
/// The region a packing fills (Jarolin 2020 §2: particles are placed at random inside the sample's
/// shape). A container answers three questions: its volume (m^3, for the porosity), its bounding
/// box (where to draw random centres) and, for a sphere of radius R centred at c, the nearest centre
/// that keeps the whole sphere inside (the wall constraint of the relaxation). All lengths in m.
#include <memory>
#include <string>

#include "core/vec3.hpp"
#include "spatial/aabb.hpp"

namespace bpm {

class Container {
 public:
  virtual ~Container() = default;
  virtual double volume() const = 0;                 ///< m^3
  virtual Aabb bounds() const = 0;                   ///< axis-aligned bounding box
  virtual bool contains(const Vec3& point) const = 0;  ///< the point is inside (boundary included)
  /// The centre nearest to `centre` at which a sphere of `radius` lies wholly inside. If the
  /// container is too small for the sphere in some direction, the centre goes to the middle there.
  virtual Vec3 keep_inside(const Vec3& centre, double radius) const = 0;
  /// One line for messages and the summary, e.g. "cylinder r=0.01 h=0.02".
  virtual std::string describe() const = 0;
};

/// Axis-aligned box [min, max].
class BoxContainer final : public Container {
 public:
  BoxContainer(const Vec3& min, const Vec3& max);
  double volume() const override;
  Aabb bounds() const override { return {min_, max_}; }
  bool contains(const Vec3& p) const override;
  Vec3 keep_inside(const Vec3& centre, double radius) const override;
  std::string describe() const override;

 private:
  Vec3 min_, max_;
};

/// Circular cylinder with axis +z: base centre `base`, radius, height (z from base.z to base.z + h).
class CylinderContainer final : public Container {
 public:
  CylinderContainer(const Vec3& base, double radius, double height);
  double volume() const override;
  Aabb bounds() const override;
  bool contains(const Vec3& p) const override;
  Vec3 keep_inside(const Vec3& centre, double radius) const override;
  std::string describe() const override;

 private:
  Vec3 base_;
  double radius_, height_;
};

class SphereContainer final : public Container {
 public:
  SphereContainer(const Vec3& centre, double radius);
  double volume() const override;
  Aabb bounds() const override;
  bool contains(const Vec3& p) const override;
  Vec3 keep_inside(const Vec3& centre, double radius) const override;
  std::string describe() const override;

 private:
  Vec3 centre_;
  double radius_;
};

}  // namespace bpm
