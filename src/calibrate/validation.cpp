#include "calibrate/validation.hpp"

namespace bpm {

std::optional<ValidatedError> validated_error(StiffnessMethod method) {
  // docs/validation.md, "Summary": 12 samples per case, 2026-12-02. Rerun the study after a change
  // to a method and update both.
  switch (method) {
    case StiffnessMethod::dsm:
      return ValidatedError{{0.0033, 0.0053, 12}, {0.0127, 0.0356, 12}};
    case StiffnessMethod::dsm_nonlinear:
      return ValidatedError{{0.0071, 0.0093, 12}, {0.0092, 0.0136, 12}};
    case StiffnessMethod::ste:
      return ValidatedError{{0.1582, 0.1701, 12}, {2.6768, 3.4750, 12}};
    case StiffnessMethod::dsm_kinematic:
      return ValidatedError{{0.8028, 0.8427, 12}, {2.8200, 4.5895, 12}};
    case StiffnessMethod::dem:
    case StiffnessMethod::dem_kinematic:
      return std::nullopt;
  }
  return std::nullopt;
}

}  // namespace bpm
