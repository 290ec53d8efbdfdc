#include "verify/cantilever.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace bpm::verify {

TEST(Cantilever, AnalyticalReferencesMatchChenTable4) {
  const CantileverSpec spec = cantilever_case(1).front();
  EXPECT_NEAR(timoshenko_deflection(spec, 4.0, true), 8.534e-3, 0.5e-6);   // Chen Table 4
  EXPECT_NEAR(timoshenko_deflection(spec, 4.0, false), 8.488e-3, 0.5e-6);
}

TEST(Cantilever, Case1EveryModelReachesRestAtItsStaticSolution) {
  // Chen Table 4: TBBM 8.537, EBBM 8.489, PBM 8.508 mm (their DEM); ours must sit on the exact
  // discrete solution and, for the beam models, on the beam theories.
  const CantileverSpec spec = cantilever_case(1).front();
  for (const std::string model : {"pbm", "ebbm", "tbbm"}) {
    const CantileverResult r = run_cantilever(spec, model);
    SCOPED_TRACE(model);
    EXPECT_EQ(r.run.reason, StopReason::rest);
    EXPECT_LT(std::abs(r.error_vs_discrete()), 1e-4);
    if (model == "tbbm") {
      EXPECT_LT(std::abs(r.error_vs_timoshenko()), 1e-4);
    }
    if (model == "ebbm") {
      EXPECT_LT(std::abs(r.error_vs_euler_bernoulli()), 1e-4);
    }
    if (model == "pbm") {
      EXPECT_NEAR(r.tip_dem, 8.508e-3, 1e-6);
    }  // Chen Table 4, PFC3D
  }
}

TEST(Cantilever, Case1DeflectionAlongTheBeamFollowsTimoshenko) {
  // Chen Fig. 8: TBBM on Eq. 28 at every particle, not only at the tip.
  const CantileverSpec spec = cantilever_case(1).front();
  const CantileverResult r = run_cantilever(spec, "tbbm");
  for (std::size_t i = 1; i < spec.x.size(); ++i) {
    const double reference = timoshenko_deflection(spec, spec.x[i], true);
    EXPECT_NEAR(r.deflection_dem[i] / reference, 1.0, 1e-4) << "particle " << i;
  }
}

TEST(Cantilever, Case4DeviationFromLinearTheoryIsGeometricOnly) {
  // At 1/100 of Chen's load the large-deflection factor is 1 - 1e-7: the DEM must then sit on the
  // linear discrete solution; at the full load it differs by the elastica correction.
  CantileverSpec spec = cantilever_case(4).back();  // 10 bonds, r_b = 0.1 m
  spec.load *= 0.01;
  const CantileverResult small = run_cantilever(spec, "tbbm");
  EXPECT_LT(std::abs(small.linear_error_vs_discrete()), 1e-5);
  EXPECT_LT(std::abs(small.linear_error_vs_timoshenko()), 1e-5);
}

TEST(Cantilever, Case5PbmErrorGrowsWithPolydispersityBeamModelsDoNot) {
  // Chen Fig. 16: PBM with the Euler-Bernoulli k_s is right for equal radii, wrong as the middle
  // particle grows (its contact point moves off the beam centre); TBBM stays within 0.1%.
  const auto specs = cantilever_case(5);
  double previous = 0.0;
  for (const auto& spec : specs) {
    const double pbm = std::abs(run_cantilever(spec, "pbm").error_vs_euler_bernoulli());
    const double tbbm = std::abs(run_cantilever(spec, "tbbm").error_vs_timoshenko());
    EXPECT_GT(pbm, previous) << spec.variant;
    EXPECT_LT(tbbm, 1e-3) << spec.variant;
    previous = pbm;
  }
  EXPECT_LT(std::abs(run_cantilever(specs.front(), "pbm").error_vs_euler_bernoulli()), 1e-4);
  EXPECT_GT(previous, 0.05);
}

}  // namespace bpm::verify
