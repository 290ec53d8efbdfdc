#include "calibrate/validation.hpp"

namespace bpm {

std::optional<ValidatedError> validated_error(StiffnessMethod method) {
  // docs/validation.md, "Summary" (cases 1 and 2 together); rerun the study and update both.
  switch (method) {
    case StiffnessMethod::dsm:
      return ValidatedError{0.0, 0.0, 0};
    case StiffnessMethod::dsm_nonlinear:
      return ValidatedError{0.0, 0.0, 0};
    case StiffnessMethod::ste:
      return ValidatedError{0.0, 0.0, 0};
    case StiffnessMethod::dsm_kinematic:
      return ValidatedError{0.0, 0.0, 0};
    case StiffnessMethod::dem:
    case StiffnessMethod::dem_kinematic:
      return std::nullopt;
  }
  return std::nullopt;
}

}  // namespace bpm
