#include "verify/elastica.hpp"

#include <gtest/gtest.h>

namespace bpm::verify {

TEST(Elastica, MatchesBisshoppDruckerAtUnitLoadParameter) {
  // Bisshopp & Drucker (1945): tip deflection 0.30172 L at F L^2 / (E I) = 1.
  EXPECT_NEAR(elastica_tip_ratio(1.0) * (1.0 / 3.0), 0.30172, 1e-5);
}

TEST(Elastica, ApproachesLinearTheoryQuadratically) {
  EXPECT_DOUBLE_EQ(elastica_tip_ratio(0.0), 1.0);
  // 1 - ratio ~ c alpha^2: halving alpha divides the correction by four.
  const double c1 = 1.0 - elastica_tip_ratio(0.1), c2 = 1.0 - elastica_tip_ratio(0.05);
  EXPECT_NEAR(c1 / c2, 4.0, 0.01);
  EXPECT_NEAR(c1, 0.00114, 0.00001);
}

}  // namespace bpm::verify
