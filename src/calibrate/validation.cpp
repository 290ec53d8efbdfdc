#include "calibrate/validation.hpp"

namespace bpm {

std::optional<ValidatedError> validated_error(StiffnessMethod method) {
  // docs/validation.md (scripts/validation_fig4.sh): bond-dominated: four case 1 cylinders (the
  // README's and three of ~980 particles) and a case 3 box; contact-dominated: three case 2
  // agglomerates of 2,000; each against an unscaled DEM whose platens balance within 1 %. Rerun
  // the study after a change to a method and update these.
  switch (method) {
    case StiffnessMethod::dsm:
      return ValidatedError{{0.0032, 0.0088, 5}, {0.0023, 0.0039, 3}};
    case StiffnessMethod::dsm_nonlinear:
      return ValidatedError{{0.0012, 0.0015, 5}, {0.0033, 0.0046, 3}};
    case StiffnessMethod::ste:
      return ValidatedError{{0.1310, 0.1563, 5}, {2.9606, 2.9999, 3}};
    case StiffnessMethod::dsm_kinematic:
      return ValidatedError{{0.8963, 1.5210, 5}, {2.7711, 3.3167, 3}};
    case StiffnessMethod::dem:
    case StiffnessMethod::dem_kinematic:
      return std::nullopt;
  }
  return std::nullopt;
}

}  // namespace bpm
