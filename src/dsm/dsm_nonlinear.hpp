#pragma once
/// The nonlinear direct stiffness method (Jarolin sections 3.1.2-3.1.3): the bonds' linear stiffness
/// plus the nonlinear particle-particle contacts and frictionless particle-wall springs,
///   f = K u + h(u)   (Jarolin Eq. 10),
/// solved for the static displacement with a Jacobian-free Newton-Krylov method (SUNDIALS KINSOL:
/// Newton with line search, GMRES on finite-difference Jacobian-vector products), started from the
/// linear DSM solution (Jarolin section 4.2).
///
/// The paper's assumptions, kept here:
/// - potential contacts are listed once, before the solve (pairs whose gap is below the platen
///   displacement plus a tenth of the mean radius); whether a listed pair touches is decided at
///   every evaluation;
/// - contact directions stay constant (the initial branch vector); the whole tangential
///   displacement s at the contact point loads the tangential spring, F_t = k_t(delta) s.
/// One departure: the paper's contacts do not slip; here F_t is capped at the Coulomb force
/// mu F_n as in the DEM (contact_law::coulomb_capped; a monotonic load path, no history). On the
/// validation study's contact-dominated agglomerates (case 2) the mean |error| against the DEM fell
/// from 1.66 % to 0.92 % (max 3.84 -> 1.36 %); on its bonded cylinders (case 1) the error kept its
/// size and changed sign (+0.36..+0.90 % -> -0.52..-0.93 %): the DEM's slip lies between none and
/// this path-independent cap (docs/validation.md, 2026-12-02).
/// - the platens are frictionless walls: Hertz (or linear) springs along the axis only, the lower
///   wall held, the upper moved by the platen displacement (a "moving imaginary wall").
/// Particle pairs overlapping at the start are taken as prestressed in equilibrium (the bonds were
/// made at these positions): only the change of their contact force counts.
/// The preconditioner is the assembled Jacobian: the bonds, every listed contact as the element of
/// its tangent at the current overlap, and the platen springs' tangents, set up once per Newton
/// setup: CHOLMOD's factor or one AMG V-cycle, by size (SpdPreconditioner, DsmOptions::solver).
/// (With the contacts on the diagonal blocks only, KINSOL's line search failed on every
/// contact-dominated agglomerate of the validation study.)
#include "dsm/dsm_linear.hpp"

namespace bpm {

/// Nonlinear DSM with wall springs; the result's stiffness is the least-squares slope of the upper
/// platen force over the DEM's fit window (from the force at two nodes of the window: fit_window.hpp), as the
/// DEM reports it (Jarolin section 4.2: "based on the resulting force field, the reaction force").
DsmResult solve_dsm_nonlinear(const Model& model, const PlatenLoading& load, const DsmOptions& options = {});

}  // namespace bpm
