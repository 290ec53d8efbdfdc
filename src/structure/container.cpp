#include "structure/container.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <numbers>

namespace bpm {
namespace {

/// Clamp x into [lo + r, hi - r]; if that interval is empty, the middle of [lo, hi].
double clamp_inset(double x, double lo, double hi, double r) {
  if (hi - lo <= 2.0 * r) return 0.5 * (lo + hi);
  return std::clamp(x, lo + r, hi - r);
}

}  // namespace

BoxContainer::BoxContainer(const Vec3& min, const Vec3& max) : min_(min), max_(max) {}

double BoxContainer::volume() const {
  const Vec3 s = max_ - min_;
  return s.x * s.y * s.z;
}

bool BoxContainer::contains(const Vec3& p) const {
  return p.x >= min_.x && p.x <= max_.x && p.y >= min_.y && p.y <= max_.y && p.z >= min_.z && p.z <= max_.z;
}

Vec3 BoxContainer::keep_inside(const Vec3& c, double r) const {
  return {clamp_inset(c.x, min_.x, max_.x, r), clamp_inset(c.y, min_.y, max_.y, r), clamp_inset(c.z, min_.z, max_.z, r)};
}

std::string BoxContainer::describe() const {
  return fmt::format("box [{}, {}, {}] - [{}, {}, {}] m", min_.x, min_.y, min_.z, max_.x, max_.y, max_.z);
}

CylinderContainer::CylinderContainer(const Vec3& base, double radius, double height)
    : base_(base), radius_(radius), height_(height) {}

double CylinderContainer::volume() const { return std::numbers::pi * radius_ * radius_ * height_; }

Aabb CylinderContainer::bounds() const {
  return {{base_.x - radius_, base_.y - radius_, base_.z}, {base_.x + radius_, base_.y + radius_, base_.z + height_}};
}

bool CylinderContainer::contains(const Vec3& p) const {
  const double dx = p.x - base_.x, dy = p.y - base_.y;
  return p.z >= base_.z && p.z <= base_.z + height_ && dx * dx + dy * dy <= radius_ * radius_;
}

Vec3 CylinderContainer::keep_inside(const Vec3& c, double r) const {
  Vec3 out = c;
  out.z = clamp_inset(c.z, base_.z, base_.z + height_, r);
  const double dx = c.x - base_.x, dy = c.y - base_.y;
  const double rho = std::sqrt(dx * dx + dy * dy);
  const double rho_max = std::max(radius_ - r, 0.0);
  if (rho > rho_max) {
    const double s = rho > 0.0 ? rho_max / rho : 0.0;
    out.x = base_.x + s * dx;
    out.y = base_.y + s * dy;
  }
  return out;
}

std::string CylinderContainer::describe() const {
  return fmt::format("cylinder (axis z) base [{}, {}, {}] m, radius {} m, height {} m", base_.x, base_.y, base_.z,
                     radius_, height_);
}

SphereContainer::SphereContainer(const Vec3& centre, double radius) : centre_(centre), radius_(radius) {}

double SphereContainer::volume() const { return 4.0 / 3.0 * std::numbers::pi * radius_ * radius_ * radius_; }

Aabb SphereContainer::bounds() const {
  const Vec3 r{radius_, radius_, radius_};
  return {centre_ - r, centre_ + r};
}

bool SphereContainer::contains(const Vec3& p) const { return norm2(p - centre_) <= radius_ * radius_; }

Vec3 SphereContainer::keep_inside(const Vec3& c, double r) const {
  const Vec3 d = c - centre_;
  const double dist = norm(d);
  const double dist_max = std::max(radius_ - r, 0.0);
  if (dist <= dist_max) return c;
  return dist > 0.0 ? centre_ + (dist_max / dist) * d : centre_;
}

std::string SphereContainer::describe() const {
  return fmt::format("sphere centre [{}, {}, {}] m, radius {} m", centre_.x, centre_.y, centre_.z, radius_);
}

}  // namespace bpm
