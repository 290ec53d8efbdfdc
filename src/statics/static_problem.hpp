#pragma once
/// The one static problem of bpmkit's fast methods (Jarolin Eq. 10): the bonds' linear stiffness
/// plus the contact forces of particle pairs and walls,
///   R(x) = K_b x - f - h(x) = 0,
/// with one residual, one tangent and one Newton driver, which the DSM with walls (its tangent at
/// an operating point) and the nonlinear DSM (the loading path in steps) share.
///
/// The contacts (static_contact.hpp) are listed once with a constant normal and the DEM's contact
/// point. Their forces are the DEM's contact law (contacts/contact_law.hpp) without the dashpots:
/// - normal: F_n(delta) with delta = delta_0 - n.Delta; pairs that overlap at the start are taken
///   as prestressed in equilibrium (the bonds were made at these positions): only F_n(delta) -
///   F_n(delta_0) acts; a wall starts apart or touching (delta_0 = -gap <= 0);
/// - tangential: the spring s, F_t = k_t(delta) s, as the DEM's: s grows by the tangential
///   displacement of the contact point since the last accepted state (commit), starts at zero when
///   the contact closes and is dropped when it opens; with `slip` it is capped at the Coulomb force
///   mu F_n and keeps the capped length (the DEM's sliding), so the history of a loading path in
///   steps is the DEM's. Without slip (Jarolin 3.1.2: "we assume no-slip condition") nothing caps
///   it.
/// With `bond_axes`, a bond's normal force is the DEM's (bonds/bond_law.hpp: the stretch is the
/// change of the current length, the load turns with the axis): k_n (L - L_0) n along the current
/// axis n = (L_0 n_0 + u_beta - u_alpha) / L, in place of K_b's k_n n_0 . (u_beta - u_alpha) n_0;
/// no moment, as the contact point stays on the axis. This term of second order makes a
/// compressed bond soften sideways (the P-delta effect): on the study's case 1 cylinders at 2 %
/// strain it lowers the nonlinear DSM's K by 0.4-1.6 %, what separated it from the quasi-static
/// DEM (docs/validation.md). Shear forces and moments keep the initial frame; the contacts keep
/// their initial normal (their turning moved K by 0.02 % on case 1, and on the case 2 agglomerates
/// it leaves Newton without a solution: the prestressed contacts' rolling modes lose their
/// stiffness).
///
/// Newton's matrix is K_b plus every contact's tangent at the current state (a sliding contact's
/// tangential secant k_t |F_t| / |k_t s|); the bonds' turning stays out of it (a modified
/// Newton: with its compressed part the operator is indefinite on the case 2 agglomerates, and
/// its tension part saved no step). It is solved by conjugate gradients with a preconditioner
/// built once (solvers/sparse_solver.hpp: ShiftedSystem): K_0 (bonds and the pairs at their
/// initial tangents) is assembled once; the walls' translation stiffness is the diagonal shift and
/// every other change an added product (contact_change.hpp).
///
/// The loading tangent (tangent_stiffness, the DSM with walls) gives a sliding contact no
/// tangential stiffness: along the slip a Coulomb contact adds no force as it slides on. (Across
/// the slip its force turns with the secant, and along it grows with mu dF_n; the first is left
/// out to keep the tangent isotropic per contact, the second is not symmetric.) With the secant
/// instead, the linear DSM was +0.1 to +1.5 % off the quasi-static DEM on five of the study's
/// samples; without it, -0.1 to -0.4 % there and within 0.88 % on all eight (docs/validation.md).
#include <cstdint>
#include <memory>
#include <vector>

#include "model/model.hpp"
#include "solvers/sparse_solver.hpp"
#include "statics/contact_change.hpp"
#include "statics/dof_constraints.hpp"
#include "statics/static_contact.hpp"

namespace bpm {

struct StaticProblemOptions {
  int dofs = 6;  ///< per particle: 6 (translation, rotation) or 3 (translation only)
  SparseSolverOptions solver;
  /// Coulomb slip at the contacts, with the tangential springs' history; false: no slip.
  bool slip = true;
  /// The bonds' normal forces along their current axes with their current length, as in the DEM
  /// (above); false: K_b alone, Jarolin's small displacements.
  bool bond_axes = true;
};

/// Counters of the work done, for the reports.
struct StaticWork {
  int newton_iterations = 0;
  int krylov_iterations = 0;
  double solve_seconds = 0.0;
  double assembly_seconds = 0.0;
  SparseSolveReport setup;  ///< the first solve's: the preconditioner's set-up and AMG's levels
};

class StaticProblem {
 public:
  /// K_0 of the bonds and the pair contacts (walls: j < 0, moving with the travel by their
  /// wall_motion) with the constraints eliminated; under mpirun each rank assembles its rows
  /// (solvers/distributed_solver.hpp). With AMG, the columns of `coarse` are deflated (the
  /// sample's rigid-body modes). The field starts at zero with the held values.
  StaticProblem(const Model& model, const DofConstraints& constraints,
                std::vector<StaticContact> contacts, const StaticProblemOptions& options,
                const Eigen::MatrixXd& coarse = {});
  ~StaticProblem();
  StaticProblem(const StaticProblem&) = delete;
  StaticProblem& operator=(const StaticProblem&) = delete;

  /// The displacement field (dofs per particle), the Newton iterate; callers may set a predictor.
  Eigen::VectorXd& field() { return x_; }
  const std::vector<StaticContact>& contacts() const { return contacts_; }

  /// Newton's method at platen travel w from the current field until ||R|| <= tolerance ||h||
  /// (h: the contact loads), each step solved to a forcing tolerance and damped by a line search.
  /// Throws InputError (naming `method`) if it does not converge in 40 steps.
  void solve(double w, double tolerance, const char* method);
  /// Accepts the current field as a state of the loading path: the tangential springs keep what
  /// they hold now (the history of the next step).
  void commit();

  /// At the current operating point (after solve at w): dF/dw of the moving walls' normal force,
  /// from v = dx/dw solving the loading tangent system (K_t v = dh/dw: Newton's matrix with no
  /// tangential stiffness at sliding contacts, without the bonds' turning) to `tolerance`; `guess`
  /// (may be empty) starts the iteration. Second-order accurate in v's error (2 b^T v - v^T A v).
  double tangent_stiffness(double w, double tolerance, Eigen::VectorXd& v,
                           const Eigen::VectorXd& guess);

  /// Normal force of the moving (true) or the held walls on the sample at the current field, N.
  double wall_force(double w, bool moving) const;
  /// How far pair k has closed under field u: -n.(u_j - u_i), m.
  double approach(std::size_t k, const Eigen::VectorXd& u) const;

  std::size_t unknowns() const { return static_cast<std::size_t>(x_.size()); }
  std::size_t nonzeros() const { return nonzeros_; }
  const StaticWork& work() const { return work_; }
  double relative_residual() const { return relative_residual_; }

 private:
  /// R(x) into residual_ (zero on held DOFs), the trial springs and the tangents; returns ||R||.
  double evaluate(const Eigen::VectorXd& x, double w);
  /// y = (K_0 + diag(shift_) + change) u, zero on held DOFs.
  void tangent_product(const Eigen::VectorXd& u, const AddedProduct* added,
                       Eigen::VectorXd& y) const;
  /// The tangents of the last evaluate as the solver's shift and added product.
  ContactStiffnessChange tangent_change() const;

  const Model& model_;
  const DofConstraints& c_;
  StaticProblemOptions options_;
  int dofs_;
  std::vector<StaticContact> contacts_;  ///< k_n, k_t: the tangent of the last evaluate
  std::vector<StaticContact> start_;     ///< the pairs as K_0 holds them; walls with zero stiffness
  std::vector<double> force0_;           ///< F_n(delta_0) of each contact (the prestress)
  std::vector<Vec3> spring_, trial_;     ///< tangential springs: committed, of the last evaluate
  std::vector<Vec3> slide_from_;         ///< Delta_t at the commit
  std::vector<Vec3> slide_trial_;        ///< Delta_t of the last evaluate
  struct BondAxis {
    std::int32_t alpha, beta;
    Vec3 n;  ///< n_0
    double length, k_n;
  };
  std::vector<BondAxis> bond_axes_;  ///< the intact bonds (empty without bond_axes)
  struct ContactForce {
    Vec3 g;        ///< C_0 Delta - f_i: the contact's residual on i (the opposite on j)
    double on_i2;  ///< |f_i|^2, for the load's norm (walls)
  };
  std::vector<Vec3> bond_force_;             ///< evaluate's per-bond change of the force on alpha
  std::vector<ContactForce> contact_force_;  ///< evaluate's per-contact residual
  std::unique_ptr<ShiftedSystem> system_;
  Eigen::VectorXd rhs_, x_, residual_, shift_, load_;
  std::size_t nonzeros_ = 0;
  double floor_ = 0.0;  ///< least wall stiffness in Newton's matrix (an opened wall spring)
  bool loading_tangent_ = false;  ///< evaluate for tangent_stiffness: sliding contacts k_t = 0
  double relative_residual_ = 0.0;
  StaticWork work_;
};

}  // namespace bpm
