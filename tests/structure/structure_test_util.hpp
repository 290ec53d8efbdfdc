#pragma once
// Helpers for the structure tests: a scratch directory per test, small STL writers, and the
// message of an InputError.
#include <gtest/gtest.h>

#include <unistd.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "common/test_files.hpp"
#include "core/error.hpp"
#include "core/vec3.hpp"

namespace bpm::test {


/// The message of the InputError that f() raises (a test failure if none).
inline std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "expected InputError, got: " << e.what();
    return {};
  }
  ADD_FAILURE() << "expected an InputError, but nothing was thrown";
  return {};
}

using Triangle = std::array<Vec3, 3>;

/// Unit cube [0, 1]^3, two triangles per face, outward (counter-clockwise) orientation.
inline std::vector<Triangle> cube_triangles() {
  const Vec3 v[8] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  const int f[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                        {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
  std::vector<Triangle> t;
  for (const auto& face : f) t.push_back({v[face[0]], v[face[1]], v[face[2]]});
  return t;
}

/// Icosahedron subdivided `levels` times, vertices on the sphere of `radius` about the origin.
inline std::vector<Triangle> icosphere_triangles(int levels, double radius) {
  const double g = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Vec3> v = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0}, {0, -1, g}, {0, 1, g},
                         {0, -1, -g}, {0, 1, -g}, {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
  std::vector<std::array<int, 3>> f = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                       {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                       {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                       {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  std::vector<Triangle> tri;
  for (const auto& t : f) tri.push_back({v[static_cast<std::size_t>(t[0])], v[static_cast<std::size_t>(t[1])], v[static_cast<std::size_t>(t[2])]});
  auto on_sphere = [&](const Vec3& p) { return (radius / norm(p)) * p; };
  for (auto& t : tri)
    for (auto& p : t) p = on_sphere(p);
  for (int l = 0; l < levels; ++l) {
    std::vector<Triangle> next;
    for (const auto& t : tri) {
      const Vec3 a = on_sphere(0.5 * (t[0] + t[1])), b = on_sphere(0.5 * (t[1] + t[2])), c = on_sphere(0.5 * (t[2] + t[0]));
      next.push_back({t[0], a, c});
      next.push_back({t[1], b, a});
      next.push_back({t[2], c, b});
      next.push_back({a, b, c});
    }
    tri = std::move(next);
  }
  return tri;
}

inline std::string ascii_stl(const std::vector<Triangle>& tris) {
  std::ostringstream s;
  s.precision(17);
  s << "solid test\n";
  for (const auto& t : tris) {
    s << "  facet normal 0 0 0\n    outer loop\n";
    for (const auto& p : t) s << "      vertex " << p.x << " " << p.y << " " << p.z << "\n";
    s << "    endloop\n  endfacet\n";
  }
  s << "endsolid test\n";
  return s.str();
}

inline std::string binary_stl(const std::vector<Triangle>& tris) {
  std::string s(80, ' ');
  const auto n = static_cast<std::uint32_t>(tris.size());
  s.append(reinterpret_cast<const char*>(&n), 4);
  for (const auto& t : tris) {
    float rec[12] = {0, 0, 0};
    for (int k = 0; k < 3; ++k) {
      rec[3 + 3 * k] = static_cast<float>(t[static_cast<std::size_t>(k)].x);
      rec[4 + 3 * k] = static_cast<float>(t[static_cast<std::size_t>(k)].y);
      rec[5 + 3 * k] = static_cast<float>(t[static_cast<std::size_t>(k)].z);
    }
    s.append(reinterpret_cast<const char*>(rec), sizeof rec);
    s.append(2, '\0');
  }
  return s;
}

}  // namespace bpm::test
