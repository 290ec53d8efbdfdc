#pragma once
/// The nonlinear direct stiffness method (Jarolin sections 3.1.2-3.1.3): the bonds' linear stiffness
/// plus the nonlinear particle-particle and particle-platen contacts,
///   f = K u + h(u)   (Jarolin Eq. 10),
/// solved by the static core (statics/static_problem.hpp) along the DEM's loading path: the platen
/// travel in steps from zero, each step's equilibrium found by Newton's method from the last one's
/// (a secant predictor), the contacts' tangential springs carried from step to step as the DEM
/// carries them (stick, Coulomb slip, dropped on opening). As in the paper, the potential contacts
/// are listed once and keep their initial normal; whether a listed pair touches is decided at every
/// evaluation. Slip is on by default (the DEM slides); DsmOptions::slip = false is the paper's
/// no-slip DSM. The platens are walls with the DEM's grain-platen contact law, friction included.
#include "dsm/dsm_linear.hpp"

namespace bpm {

/// Nonlinear DSM with platen walls; the result's stiffness is the least-squares slope of the upper
/// platen force over the DEM's fit window (from the force at the two nodes of the window's
/// three-point rule, exact for F up to quartic: fit_window.hpp), as the DEM reports it (Jarolin
/// section 4.2: "based on the resulting force field, the reaction force"). The steps are
/// DsmOptions::load_steps equal steps of the travel with the rule's nodes added.
DsmResult solve_dsm_nonlinear(const Model& model, const PlatenLoading& load, const DsmOptions& options = {});

}  // namespace bpm
