#pragma once
/// Large-deflection correction for the cantilever references.
///
/// The DEM bond law is geometrically exact (bonds rotate with the particles), while Chen Eq. 29 and
/// the linearised discrete solution assume small deflections. For a tip load F of fixed direction
/// the Euler-Bernoulli elastica gives the exact tip deflection; its ratio to the linear value
/// F L^3 / (3 E I) depends only on alpha = F L^2 / (E I) and is 1 - 0.114 alpha^2 + ... (Chen case 4,
/// r_b = 0.1 m: alpha = 0.102, ratio 0.99882; cases 1-3 and 5: ratio 0.999996).
namespace bpm::verify {

/// Tip deflection of the elastica divided by the linear tip deflection, for alpha = F L^2/(E I).
/// Solved by shooting on theta'' = -alpha cos(theta), theta(0) = 0, theta'(1) = 0 (RK4 with 2000
/// steps, bisection on theta'(0)), accurate to ~1e-12 for alpha <= 1.
double elastica_tip_ratio(double alpha);

}  // namespace bpm::verify
