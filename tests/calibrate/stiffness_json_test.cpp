// The one JSON form of a stiffness estimate (calibrate/stiffness_methods.hpp): what `bpmkit
// stiffness` writes, `bpmkit compare --reference-from` reads back field for field, and a file
// without a field is refused naming the file.
#include <gtest/gtest.h>

#include "calibrate/stiffness_methods.hpp"
#include "core/error.hpp"

namespace bpm {
namespace {

TEST(StiffnessJson, RoundTripKeepsEveryField) {
  StiffnessEstimate e;
  e.method = StiffnessMethod::dsm_nonlinear;
  e.stiffness = 58651.1421898494;
  e.youngs_modulus = 3.7349038969726e7;
  e.sample.length = 0.002;
  e.sample.area = 3.14070422199563e-06;
  e.seconds = 0.768;
  e.details = {{"newton_iterations", 4}};
  const nlohmann::json j = to_json(e);
  EXPECT_EQ(j.at("method"), "dsm-nonlinear");
  // Through text, as the file goes.
  const StiffnessEstimate back =
      stiffness_estimate_from_json(nlohmann::json::parse(j.dump()), "stiffness.json");
  EXPECT_EQ(back.method, e.method);
  EXPECT_EQ(back.stiffness, e.stiffness);
  EXPECT_EQ(back.youngs_modulus, e.youngs_modulus);
  EXPECT_EQ(back.sample.length, e.sample.length);
  EXPECT_EQ(back.sample.area, e.sample.area);
  EXPECT_EQ(back.seconds, e.seconds);
  EXPECT_EQ(back.details, e.details);
}

TEST(StiffnessJson, AMissingFieldNamesTheFile) {
  nlohmann::json j = to_json(StiffnessEstimate{});
  j.erase("stiffness_N_per_m");
  try {
    (void)stiffness_estimate_from_json(j, "out/dem/stiffness.json");
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("out/dem/stiffness.json"), std::string::npos) << message;
    EXPECT_NE(message.find("stiffness_N_per_m"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace bpm
