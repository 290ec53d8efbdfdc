// The Jarolin case-1-scale example (examples/02_generate/cylinder_1e5.yml): about 1e5 particles
// and 4e5 bonds, relaxed to the tolerance, inside the cylinder. (Its time is a benchmark figure,
// not a test: a wall-clock bound failed under the sanitizers on a loaded machine.)
#include <gtest/gtest.h>

#include <cmath>

#include "structure/generate.hpp"
#include "structure/generate_spec.hpp"

namespace bpm {
namespace {

TEST(StructureSlow, Cylinder1e5) {
  const GenerateSpec spec = load_generate_spec(std::string(BPMKIT_EXAMPLES_DIR) + "/02_generate/cylinder_1e5.yml");
  const GeneratedStructure g = generate_structure(spec);
  EXPECT_NEAR(static_cast<double>(g.packing.size()), 1e5, 5e3);
  EXPECT_NEAR(static_cast<double>(g.bonds.size()), 4e5, 2e4);
  EXPECT_TRUE(g.relaxation.converged);
  EXPECT_LE(g.stats.max_overlap, spec.relaxation.overlap_tolerance);
  EXPECT_NEAR(g.stats.porosity, 0.4, 2e-3);
  const Aabb box = spec.container->bounds();
  const double rc = 0.5 * box.size().x;
  for (std::size_t i = 0; i < g.packing.size(); ++i) {
    const Vec3 x = g.packing.position[i];
    const double r = g.packing.radius[i];
    EXPECT_LE(std::hypot(x.x, x.y), rc - r + 1e-12);
    EXPECT_GE(x.z, r - 1e-12);
    EXPECT_LE(x.z, box.max.z - r + 1e-12);
  }
}

}  // namespace
}  // namespace bpm
