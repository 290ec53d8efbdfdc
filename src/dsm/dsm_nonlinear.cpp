#include "dsm/dsm_nonlinear.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "dsm/fit_window.hpp"
#include "dsm/platen_constraints.hpp"
#include "dsm/platen_springs.hpp"
#include "statics/static_contact.hpp"
#include "statics/static_problem.hpp"

namespace bpm {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// The nonlinear DSM with the particle pairs listed within `band` of each other.
DsmResult solve_along_path(const Model& model, const PlatenLoading& load, const DsmOptions& options,
                           double band) {
  const auto start = std::chrono::steady_clock::now();
  DsmResult r;
  r.loading = load;
  r.pair_band = band;
  const int dofs = options.dofs;
  const DofConstraints c = platen_constraints(model, load, dofs, /*kinematic_platens=*/false);
  r.detached_particles = c.detached_particles;
  std::vector<StaticContact> contacts = list_static_contacts(model, band);
  const std::size_t pairs = contacts.size();
  r.potential_contacts = pairs;
  const std::vector<StaticContact> walls =
      platen_contacts(model, load, c, platen_listing_band(model, load));
  r.potential_wall_contacts = walls.size();
  contacts.insert(contacts.end(), walls.begin(), walls.end());
  StaticProblem problem(model, c, std::move(contacts),
                        {dofs, options.solver, options.slip, options.bond_axes},
                        dsm_coarse_space(model, c));
  r.unknowns = problem.unknowns();
  r.nonzeros = problem.nonzeros();

  // The path: equal steps of the travel and the nodes of the window's rule, in order.
  const WindowRule rule = force_rule(3, load.fit_from, load.fit_to);
  std::vector<double> steps;
  const int count = std::max(1, options.load_steps);
  for (int k = 1; k <= count; ++k) steps.push_back(static_cast<double>(k) / count);
  steps.insert(steps.end(), rule.travel.begin(), rule.travel.end());
  std::sort(steps.begin(), steps.end());
  steps.erase(std::unique(steps.begin(), steps.end(),
                          [](double a, double b) { return std::abs(a - b) < 1e-12; }),
              steps.end());

  // The first step starts from the uniform axial strain; each later one from the secant through
  // the last two states.
  Eigen::VectorXd& x = problem.field();
  const double first = steps.front() * load.displacement;
  for (std::size_t p = 0; p < model.particles.size(); ++p) {
    const double height =
        (dot(model.particles.position[p], load.axis) - load.sample.bottom) / load.sample.length;
    const auto dof = static_cast<Eigen::Index>(dofs * p + static_cast<std::size_t>(c.axial_dof));
    if (!c.fixed[static_cast<std::size_t>(dof)])
      x[dof] = -load.axis[c.axial_dof] * first * (0.75 - 0.5 * height);
  }
  Eigen::VectorXd before = x, last = x;
  double w_before = 0.0, w_last = 0.0;
  r.stiffness = 0.0;
  // The body's strains by the same rule (strain_gauge.hpp): their slopes over the window.
  const StrainGauge gauge(model.particles.position, load.axis, load.sample);
  GaugeStrain per_travel;
  for (const double fraction : steps) {
    const double w = fraction * load.displacement;
    if (w_last > 0.0) x = last + ((w - w_last) / (w_last - w_before)) * (last - before);
    problem.solve(w, options.nonlinear_tolerance, "dsm-nonlinear");
    problem.commit();
    before = last;
    last = x;
    w_before = w_last;
    w_last = w;
    for (std::size_t k = 0; k < rule.travel.size(); ++k) {
      if (std::abs(rule.travel[k] - fraction) < 1e-12) {
        r.stiffness += rule.weight[k] * problem.wall_force(w, /*moving=*/true) / load.displacement;
        if (!gauge.valid()) continue;
        const GaugeStrain g = gauge.measure_field(x, dofs);
        per_travel.axial += rule.weight[k] * g.axial / load.displacement;
        per_travel.lateral += rule.weight[k] * g.lateral / load.displacement;
      }
    }
  }
  r.force_top = problem.wall_force(w_last, /*moving=*/true);
  r.force_bottom = problem.wall_force(w_last, /*moving=*/false);
  r.secant_stiffness = r.force_top / w_last;
  r.youngs_modulus = r.stiffness * load.sample.length / load.sample.area;
  r.gauge_particles = gauge.size();
  if (gauge.valid())
    r.body = body_moduli(r.stiffness, load.sample.area, per_travel.axial, per_travel.lateral);
  r.residual = problem.relative_residual();
  const StaticWork& work = problem.work();
  r.newton_iterations = work.newton_iterations;
  r.krylov_iterations = work.krylov_iterations;
  r.solve = work.setup;
  r.solve.seconds = work.solve_seconds;
  r.assembly_seconds = work.assembly_seconds;
  // The last state, scaled to the full travel.
  Eigen::VectorXd u = x * (load.displacement / w_last);
  for (Eigen::Index i = 0; i < u.size(); ++i) {
    if (c.fixed[static_cast<std::size_t>(i)]) u[i] = c.value[static_cast<std::size_t>(i)];
  }
  for (std::size_t k = 0; k < pairs; ++k)
    r.max_pair_approach = std::max(r.max_pair_approach, problem.approach(k, u));
  set_fields(model, c, u, r);
  r.seconds = seconds_since(start);
  return r;
}

}  // namespace

DsmResult solve_dsm_nonlinear(const Model& model, const PlatenLoading& load,
                              const DsmOptions& options) {
  return solve_with_listed_pairs(model, load, options, solve_along_path);
}

}  // namespace bpm
