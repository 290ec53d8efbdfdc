#pragma once
/// How far each method's sample stiffness K has been measured from the explicit DEM with real
/// platens, the reference a careful user would trust: the study of scripts/validation_study.py,
/// tabulated in docs/validation.md (cases 1 and 2 of Jarolin section 4, generated here). The
/// calibration prints these beside every stage, since a stage's own error is measured against its
/// own method only.
#include <optional>

#include "calibrate/stiffness_methods.hpp"

namespace bpm {

struct ValidatedError {
  double mean_abs = 0.0;  ///< mean |K / K_DEM - 1| over the samples
  double max_abs = 0.0;   ///< largest |K / K_DEM - 1|
  int samples = 0;
};

/// The measured error against the DEM with platens; none for the DEM itself and for the kinematic
/// DEM (whose platens are not the DEM's).
std::optional<ValidatedError> validated_error(StiffnessMethod method);

}  // namespace bpm
