#include "calibrate/first_break.hpp"

#include "bonds/bond_law.hpp"
#include "compress/platen_loading.hpp"
#include "core/error.hpp"

namespace bpm {

FirstBreakEstimate linear_first_break(const Model& model, const UniaxialCompression& settings,
                                      const DsmOptions& options) {
  if (settings.test == LabTest::tension) {
    throw InputError("compression.test", "tension has no linear first-break estimate",
                     "estimate the uniaxial or brazilian test (platens, which the DSM models)");
  }
  const PlatenLoading load = make_platen_loading(model, settings);
  FirstBreakEstimate e;
  // The DSM with the platens as walls, as the DEM loads the sample; where its static solve finds
  // no equilibrium (a disc between frictionless platens is free to roll about its own axis, a
  // mode the solve does not pin) the kinematic DSM, whose held platen particles pin every mode.
  DsmResult field;
  try {
    field = solve_dsm_linear(model, load, options);
    e.method = "dsm";
  } catch (const InputError&) {
    field = solve_dsm_kinematic(model, load, options);
    e.method = "dsm-kinematic";
  }
  if (!(field.force_top > 0.0)) {
    throw InputError("compression", "the linear DSM carried no platen force",
                     "check the scenario: the sample between the platens, bonds present");
  }
  // The largest use of a strength in the solution; each bond's load is the law's response to the
  // field's relative motion at its contact point (one increment from the unloaded bond).
  const ParticleStore& p = model.particles;
  const BondStore& b = model.bonds;
  double most = 0.0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    if (b.intact[i] != 1) continue;
    const auto alpha = static_cast<std::size_t>(b.alpha[i]),
               beta = static_cast<std::size_t>(b.beta[i]);
    const Vec3 d = p.position[beta] - p.position[alpha];
    const double length = norm(d);
    const Vec3 n = d / length;
    const bond_law::Arms arms = bond_law::contact_arms(length, b.arm_offset[i]);
    const auto motion =
        bond_law::relative_motion(n, arms, field.displacement[alpha], field.rotation[alpha],
                                  field.displacement[beta], field.rotation[beta]);
    const auto loads = bond_law::elastic_response(b.stiffness[i], n, motion);
    const StrengthUse use = strength_use(n, loads.force, loads.moment, b.radius[i], b.strength[i]);
    if (use.tensile > most || use.shear > most) {
      most = std::max(use.tensile, use.shear);
      e.bond = b.input_row[i];
      e.mode = use.tensile >= use.shear ? BreakMode::tension : BreakMode::shear;
    }
  }
  if (!(most > 0.0)) {
    throw InputError("bond_materials", "no bond of the sample can break",
                     "give the bond materials tensile_strength and shear_strength");
  }
  e.force = field.force_top / most;
  const double thickness = settings.test == LabTest::brazilian ? disc_thickness(p, settings) : 0.0;
  e.stress = test_stress(settings.test, e.force, load.sample.length, load.sample.area, thickness);
  return e;
}

}  // namespace bpm
