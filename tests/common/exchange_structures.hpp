#pragma once
// A structure that a text round trip could get wrong, the bitwise comparison of two structures and
// the message of a refused file, for the tests of the exchange formats
// (tests/exchange/formats_test.cpp, tests/io/musen_text_test.cpp).
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <functional>
#include <string>

#include "core/error.hpp"
#include "io/structure_exchange.hpp"

namespace bpm::test {

/// Ids that are neither contiguous nor in order, values a text round trip could get wrong, two
/// materials of each kind, per-bond r_b.
inline ExchangeStructure awkward_structure() {
  ExchangeStructure s;
  ParticleTable& p = s.particles;
  p.id = {7, 0, 3, 12};
  p.position = {{0.1, -0.0, 1e-310},
                {1.0 / 3.0, -2.5e-3, 5e-324},
                {1, 2, 3},
                {-1, -2, std::nextafter(3.0, 4.0)}};
  p.radius = {0.2, std::nextafter(0.2, 1.0), 1e-9, 3.0 / 7.0};
  p.material_names = {"grain", "steel plate"};
  p.material = {1, 0, 0, 1};
  s.density = {2650, 7850.5, 1e3 / 3.0, 2650};
  s.bonds.i = {7, 0, 12};
  s.bonds.j = {0, 3, 3};
  s.bonds.radius = {0.1, 1.0 / 3.0, 2e-7};
  s.bonds.material_names = {"cement", "glue"};
  s.bonds.material = {0, 1, 1};
  return s;
}

inline void expect_bitwise(double a, double b, const std::string& what) {
  EXPECT_EQ(std::bit_cast<std::uint64_t>(a), std::bit_cast<std::uint64_t>(b))
      << what << ": " << a << " vs " << b;
}

inline void expect_same_structure(const ExchangeStructure& a, const ExchangeStructure& b,
                                  bool densities) {
  ASSERT_EQ(a.particles.id, b.particles.id);
  for (std::size_t k = 0; k < a.particles.id.size(); ++k) {
    const std::string row = "particle row " + std::to_string(k);
    expect_bitwise(a.particles.position[k].x, b.particles.position[k].x, row + " x");
    expect_bitwise(a.particles.position[k].y, b.particles.position[k].y, row + " y");
    expect_bitwise(a.particles.position[k].z, b.particles.position[k].z, row + " z");
    expect_bitwise(a.particles.radius[k], b.particles.radius[k], row + " radius");
    if (densities) expect_bitwise(a.density[k], b.density[k], row + " density");
  }
  // Materials by name: a CSV file lists the names in the order of their first row.
  ASSERT_EQ(a.particles.material.size(), b.particles.material.size());
  for (std::size_t k = 0; k < a.particles.material.size(); ++k) {
    EXPECT_EQ(a.particles.material_names[a.particles.material[k]],
              b.particles.material_names[b.particles.material[k]]);
  }
  EXPECT_EQ(a.bonds.i, b.bonds.i);
  EXPECT_EQ(a.bonds.j, b.bonds.j);
  ASSERT_EQ(a.bonds.radius.size(), b.bonds.radius.size());
  for (std::size_t k = 0; k < a.bonds.radius.size(); ++k)
    expect_bitwise(a.bonds.radius[k], b.bonds.radius[k], "r_b");
  ASSERT_EQ(a.bonds.material.size(), b.bonds.material.size());
  for (std::size_t k = 0; k < a.bonds.material.size(); ++k) {
    EXPECT_EQ(a.bonds.material_names[a.bonds.material[k]],
              b.bonds.material_names[b.bonds.material[k]]);
  }
}

/// The InputError message f raises (a test failure if it raises none).
inline std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an InputError";
  return {};
}

}  // namespace bpm::test
