#pragma once
/// How far each method's sample stiffness K has been measured from the explicit DEM with real
/// platens, the reference a careful user would trust: the study of scripts/validation_fig4.sh,
/// tabulated in docs/validation.md (Jarolin section 4's cases 1-3). The
/// calibration prints these beside every stage, since a stage's own error is measured against its
/// own method only.
#include <optional>

#include "calibrate/stiffness_methods.hpp"

namespace bpm {

/// |K / K_DEM - 1| over the samples of one case.
struct MeasuredError {
  double mean_abs = 0.0;
  double max_abs = 0.0;
  int samples = 0;
};

struct ValidatedError {
  MeasuredError bond_dominated;  ///< cases 1 and 3: cylinders, contacts superimposed; a porous box
  MeasuredError contact_dominated;  ///< case 2: bi-component agglomerates, contacts carry most load
};

/// The measured errors against the DEM with platens; none for the DEM itself and for the
/// kinematic DEM (whose platens are not the DEM's).
std::optional<ValidatedError> validated_error(StiffnessMethod method);

}  // namespace bpm
