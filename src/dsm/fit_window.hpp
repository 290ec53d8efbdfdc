#pragma once
/// The DEM reports K as the least-squares slope of the platen force F(w) over its fit window
/// [a, b] of the platen travel w. The static methods reproduce that slope by quadrature:
///   slope = 12 / (b - a)^3 * integral of (w - m) F(w) dw          (m = (a + b) / 2)
///         = integral of F'(w) 6 (w - a)(b - w) / (b - a)^3 dw      (by parts).
/// The nonlinear DSM evaluates F (the first form, Gauss-Legendre), the linear DSM with walls its
/// tangent F' (the second, Gauss-Jacobi with the weight (1 - t^2)). Two nodes are exact for a
/// smooth F (F' up to cubic); a sample that touches a platen at few particles has a kinked F
/// (each new particle adds a Hertz spring that starts at zero stiffness), which more nodes follow.
#include <vector>

namespace bpm {

struct WindowRule {
  std::vector<double> travel;  ///< the nodes, as fractions of the full platen travel
  std::vector<double> weight;  ///< slope = sum of weight[i] F'(node i), or of weight[i] F(node i)
};

/// Nodes and weights for the mean tangent: slope = sum w_i F'(w_i), the w_i summing to 1; points
/// >= 1 (1 is the midpoint rule). fit_from < fit_to are fractions of the travel.
WindowRule tangent_rule(int points, double fit_from, double fit_to);

/// Nodes and weights for the slope from forces: slope = sum c_i F(w_i) / travel, the c_i summing
/// to 0; points >= 2. The middle node of an odd Gauss-Legendre rule has no weight and is left out
/// (the classical 3-point rule needs F at 2 nodes).
WindowRule force_rule(int points, double fit_from, double fit_to);

}  // namespace bpm
