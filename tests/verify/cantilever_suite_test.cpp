#include <gtest/gtest.h>

#include <cmath>

#include "verify/cantilever.hpp"

namespace bpm::verify {

/// Relative error of PBM against Timoshenko for each variant of a case, in order.
std::vector<double> pbm_errors(int case_number) {
  std::vector<double> errors;
  for (const auto& spec : cantilever_case(case_number)) {
    errors.push_back(std::abs(run_cantilever(spec, "pbm").error_vs_timoshenko()));
  }
  return errors;
}

TEST(CantileverSuite, EveryCaseAndModelWithinTolerance) {
  for (int c = 1; c <= 5; ++c) {
    for (const auto& spec : cantilever_case(c)) {
      for (const auto& model : cantilever_models()) {
        const CantileverResult r = run_cantilever(spec, model);
        SCOPED_TRACE(spec.case_name + " " + spec.variant + " " + model);
        EXPECT_EQ(r.run.reason, StopReason::rest);
        EXPECT_LT(std::abs(r.error_vs_discrete()), 1e-3);
        if (model == "tbbm") {
      EXPECT_LT(std::abs(r.error_vs_timoshenko()), 1e-3);
    }
        if (model == "ebbm") {
      EXPECT_LT(std::abs(r.error_vs_euler_bernoulli()), 1e-3);
    }
      }
    }
  }
}

TEST(CantileverSuite, PbmConvergesWithResolution) {
  // Chen Fig. 12 (gaps) and Fig. 14 (touching): the PBM error falls as bonds are added, from about
  // 25 % with one bond to under 0.5 % with ten.
  for (int c : {3, 4}) {
    const std::vector<double> e = pbm_errors(c);
    for (std::size_t i = 1; i < e.size(); ++i) EXPECT_LT(e[i], e[i - 1]) << "case " << c << " step " << i;
    EXPECT_GT(e.front(), 0.2);
    EXPECT_LT(e.back(), 0.005);
  }
}

}  // namespace bpm::verify
