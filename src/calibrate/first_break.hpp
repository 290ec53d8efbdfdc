#pragma once
/// The linear estimate of a strength test's first break: the platen force at which the first bond
/// reaches its strength (bonds/bond_strength.hpp, Potyondy & Cundall's criteria) in the linear
/// DSM's solution of the test (dsm/dsm_linear.hpp; the kinematic one where the walls' finds no
/// equilibrium). Every bond load of a linear solution grows in
/// proportion to the platen force, so one solve at the fit window's travel gives each bond's
/// sigma / sigma_t and tau / tau_s per newton of platen force, and the first break is at the force
/// that brings the most used bond to 1. Cheap (one DSM solve), and a lower bound of the peak: the
/// DEM's peak comes after breaks spread and the contacts take over (docs/calibration.md reports
/// how far below).
#include <cstdint>

#include "bonds/bond_strength.hpp"
#include "compress/uniaxial_compression.hpp"
#include "dsm/dsm_linear.hpp"
#include "model/model.hpp"

namespace bpm {

struct FirstBreakEstimate {
  double stress =
      0.0;             ///< Pa: the test's stress (UCS F / A, BTS 2 F / (pi D t)) at the first break
  double force = 0.0;  ///< N: the platen force there
  std::int32_t bond = -1;  ///< its row in the user's bond list (input_row)
  BreakMode mode = BreakMode::tension;
  const char* method = "dsm";  ///< the linear solution's: "dsm" (walls) or "dsm-kinematic"
};

/// The estimate for the uniaxial or Brazilian test `settings` on `model` (its strengths drawn).
/// Throws InputError for the tension test (grips, not platens: no DSM) or a model without a
/// breakable bond.
FirstBreakEstimate linear_first_break(const Model& model, const UniaxialCompression& settings,
                                      const DsmOptions& options = {});

}  // namespace bpm
