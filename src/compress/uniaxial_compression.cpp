#include "compress/uniaxial_compression.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <string>
#include <tuple>
#include <utility>

#include "compress/mass_scaling.hpp"
#include "core/error.hpp"
#include "dem/contact_time_step.hpp"
#include "dem/step_monitor.hpp"

namespace bpm {

LinearFit fit_line(const std::vector<double>& x, const std::vector<double>& y, double x_min,
                   double x_max) {
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0, syy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (x[i] < x_min || x[i] > x_max) continue;
    n += 1;
    sx += x[i];
    sy += y[i];
    sxx += x[i] * x[i];
    sxy += x[i] * y[i];
    syy += y[i] * y[i];
  }
  LinearFit f;
  f.points = static_cast<std::size_t>(n);
  const double vxx = sxx - sx * sx / n, vxy = sxy - sx * sy / n, vyy = syy - sy * sy / n;
  if (n < 2 || vxx <= 0.0) return f;
  f.slope = vxy / vxx;
  f.intercept = (sy - f.slope * sx) / n;
  f.r2 = vyy > 0.0 ? vxy * vxy / (vxx * vyy) : 1.0;
  return f;
}

namespace {

void validate(const Model& model, const UniaxialCompression& s) {
  auto require = [](bool ok, const std::string& key, const std::string& what,
                    const std::string& fix) {
    if (!ok) throw InputError("compression." + key, what, fix);
  };
  require(s.strain_rate > 0.0, "strain_rate", "must be > 0",
          "give the platen speed as a strain rate in 1/s, e.g. 0.1");
  require(s.target_strain > 0.0 && s.target_strain < 1.0, "target_strain", "must be in (0, 1)",
          "e.g. 0.01 for 1 %");
  require(s.fit_from >= 0.0 && s.fit_from < s.fit_to && s.fit_to <= 1.0, "fit_window",
          "must satisfy 0 <= from < to <= 1 (fractions of target_strain)", "e.g. [0.2, 1.0]");
  require(s.failure_drop >= 0.0 && s.failure_drop < 1.0, "failure_drop", "must be in [0, 1)",
          "e.g. 0.5");
  require(s.failure_drop == 0.0 || s.max_strain > s.target_strain, "max_strain",
          "must exceed target_strain when continuing to failure", "e.g. 5 times target_strain");
  require(s.platen_material >= 0 &&
              static_cast<std::size_t>(s.platen_material) < model.contacts.materials.size(),
          "platen_material", "is not a contact material",
          "name one of the particle materials with contact properties");
  require(s.curve_points >= 10, "curve_points", "must be at least 10", "e.g. 200");
  require(norm(s.axis) > 0.0, "axis", "must not be zero", "e.g. [0, 0, 1]");
  require(s.mass_scaling >= 1.0 && std::isfinite(s.mass_scaling), "mass_scaling",
          "must be a finite number >= 1",
          "1 runs the real masses; 25 makes the test about 5 times shorter");
  if (s.test == LabTest::brazilian) {
    const double n = norm(s.disc_axis);
    require(n > 0.0, "disc_axis", "is needed for the Brazilian test",
            "give the disc's axis, e.g. [0, 0, 1] for a disc in the x-y plane");
    require(std::abs(dot(s.disc_axis, s.axis)) <= 1e-9 * n * norm(s.axis), "disc_axis",
            "must be normal to the loading axis",
            "load the disc across its diameter: e.g. axis [1, 0, 0], disc_axis [0, 0, 1]");
  }
  require(s.grip_depth >= 0.0 && std::isfinite(s.grip_depth), "grip_depth",
          "must be a finite number >= 0", "0 takes 2 R_max");
}

/// The particles whose centre lies within `depth` of each end of the sample along `a`.
std::pair<std::vector<std::int32_t>, std::vector<std::int32_t>> grips(const ParticleStore& p,
                                                                      const Vec3& a,
                                                                      const SampleGeometry& sample,
                                                                      double depth) {
  std::vector<std::int32_t> bottom, top;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double centre = dot(p.position[i], a);
    if (centre - sample.bottom <= depth) bottom.push_back(static_cast<std::int32_t>(i));
    if (sample.top - centre <= depth) top.push_back(static_cast<std::int32_t>(i));
  }
  return {bottom, top};
}

Wall platen(const std::string& name, const Vec3& point, const Vec3& normal, std::int32_t material) {
  Wall w;
  w.name = name;
  w.shape = WallShape::plane;
  w.point = point;
  w.normal = normal;
  w.material = material;
  return w;
}

/// A fitted K <= 0 is no stiffness (E = -4873 Pa was once reported for a sample without bonds):
/// refused, with the cause the curve in the fit window [from, to] (m of travel) points at.
[[noreturn]] void refuse_stiffness(const CompressionResult& r, std::size_t bonds, double from,
                                   double to) {
  double top = 0.0, bottom = 0.0;
  std::size_t broken_before = 0, broken_after = 0;
  bool first = true;
  for (const CompressionPoint& pt : r.curve) {
    if (pt.displacement < from || pt.displacement > to) continue;
    top = std::max(top, pt.force_top);
    bottom = std::max(bottom, pt.force_bottom);
    if (first) broken_before = pt.bonds_broken;
    broken_after = pt.bonds_broken;
    first = false;
  }
  char cause[512];
  if (top <= 0.0 && bottom <= 0.0) {
    std::snprintf(cause, sizeof cause,
                  "the platens carried no compressive force in the fit window: the sample never "
                  "pressed on them");
  } else if (bonds == 0) {
    std::snprintf(cause, sizeof cause,
                  "the sample has no bonds: loose particles are pushed along, not compressed");
  } else if (bottom <= 0.1 * top) {
    std::snprintf(cause, sizeof cause,
                  "the load does not go through the sample: the upper platen pushed with up to "
                  "%.4g N, the lower one "
                  "carried at most %.4g N (a sample without bonds, or one in pieces, is pushed "
                  "along, not compressed)",
                  top, bottom);
  } else if (broken_after > broken_before) {
    std::snprintf(cause, sizeof cause,
                  "%zu bonds broke in the fit window: the sample fails before target_strain",
                  broken_after - broken_before);
  } else if (r.max_kinetic_ratio > 0.1) {
    std::snprintf(cause, sizeof cause,
                  "the test is not quasi-static: the kinetic energy reached %.3g times the elastic "
                  "energy in the fit "
                  "window",
                  r.max_kinetic_ratio);
  } else {
    std::snprintf(cause, sizeof cause, "the force falls as the platen advances in the fit window");
  }
  char what[1024];
  std::snprintf(
      what, sizeof what,
      "the fitted stiffness K = %.6g N/m (E = %.6g Pa, fit r^2 = %.3g) is not positive: %s",
      r.stiffness, r.youngs_modulus, r.fit_r2, cause);
  throw InputError(
      "compression", what,
      "check that the sample has its bonds (bonds: {list: []} means none) and is one piece along "
      "the "
      "axis, and lower compression.strain_rate or target_strain if it breaks or rattles");
}

}  // namespace

double failure_fraction(const UniaxialCompression& s) {
  if (s.failure_drop == 0.0) return 0.0;
  // The disc's halves, crushed between flat platens after the split, can carry more than the
  // intact disc did (a 2,578-grain disc: split at 1.09 N and strain 0.016, its force down to 0.55
  // of that, then 1.42 N at 0.039): the BTS is the load at the split.
  constexpr double kSplit = 0.8;
  return s.test == LabTest::brazilian ? std::max(s.failure_drop, kSplit) : s.failure_drop;
}

namespace {

/// Whether the test ends at curve point `pt` (r's peak already includes it); sets r.stop if so.
bool test_ends(const UniaxialCompression& s, const CompressionPoint& pt, double area,
               CompressionResult& r) {
  if (s.failure_drop == 0.0) return pt.strain >= s.target_strain * (1.0 - 1e-12);
  if (pt.strain > r.peak_strain && pt.force < failure_fraction(s) * r.peak_stress * area) {
    r.stop = "failure";
    return true;
  }
  if (pt.strain >= s.max_strain * (1.0 - 1e-12)) {
    r.stop = "max_strain";
    return true;
  }
  return false;
}

}  // namespace

std::string_view to_string(LabTest test) {
  switch (test) {
    case LabTest::brazilian:
      return "brazilian";
    case LabTest::tension:
      return "tension";
    case LabTest::uniaxial:
      break;
  }
  return "uniaxial";
}

std::string_view strength_definition(LabTest test) {
  switch (test) {
    case LabTest::brazilian:
      return "BTS = 2 F / (pi D t)";
    case LabTest::tension:
      return "tensile strength = F / A";
    case LabTest::uniaxial:
      break;
  }
  return "UCS = F / A";
}

double disc_thickness(const ParticleStore& p, const UniaxialCompression& s) {
  const Vec3 n = s.disc_axis / norm(s.disc_axis);
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double c = dot(p.position[i], n);
    low = std::min(low, c - p.radius[i]);
    high = std::max(high, c + p.radius[i]);
  }
  return high - low;
}

double test_stress(LabTest test, double force, double length, double area, double thickness) {
  return test == LabTest::brazilian ? 2.0 * force / (std::numbers::pi * length * thickness)
                                    : force / area;
}

double scenario_time_step(Model& model, double mass_scaling, double safety_factor) {
  const ScaledMasses scaled(model, mass_scaling);
  return safety_factor * stability_limit(model);
}

SampleGeometry compression_sample(const Model& model, const UniaxialCompression& s) {
  return measure_sample(model.particles, s.axis / norm(s.axis));
}

CompressionResult run_uniaxial_compression(
    Model& model, const UniaxialCompression& s,
    const std::function<void(const Simulation&, const CompressionPoint&)>& observer,
    const CompressionHooks& hooks) {
  validate(model, s);
  const Vec3 a = s.axis / norm(s.axis);
  CompressionResult r;
  r.test = s.test;
  r.failure_drop = failure_fraction(s);
  r.sample = compression_sample(model, s);
  const double l = r.sample.length;
  const bool tension = s.test == LabTest::tension;
  const double speed = s.strain_rate * l;
  // Platens touch the sample's extremes: the lower one pushes along +a, the upper one along -a.
  // In tension grips instead: every DOF of their particles prescribed, the upper grip at +speed.
  const std::size_t bottom = model.walls.size(), top = bottom + 1;
  std::vector<std::int32_t> grip_bottom, grip_top;
  if (tension) {
    double r_max = 0.0;
    for (const double radius : model.particles.radius) r_max = std::max(r_max, radius);
    std::tie(grip_bottom, grip_top) =
        grips(model.particles, a, r.sample, s.grip_depth > 0.0 ? s.grip_depth : 2.0 * r_max);
    if (grip_bottom.empty() || grip_top.empty() ||
        grip_bottom.size() + grip_top.size() >= model.particles.size()) {
      throw InputError("compression.grip_depth",
                       "leaves a grip empty or no particle between the grips",
                       "give grip_depth between R_max and a third of the sample's length");
    }
    const Vec3 all{1.0, 1.0, 1.0};  // Model::fix: the DOFs to fix
    for (const std::int32_t i : grip_bottom) model.fix(i, all, all);
    for (const std::int32_t i : grip_top) {
      model.fix(i, all, all);
      model.particles.velocity[static_cast<std::size_t>(i)] = speed * a;
    }
    r.grip_particles = grip_bottom.size() + grip_top.size();
  } else {
    model.walls.push_back(platen("platen_bottom", r.sample.bottom * a, a, s.platen_material));
    model.walls.push_back(platen("platen_top", r.sample.top * a, -1.0 * a, s.platen_material));
    model.walls[top].velocity = -speed * a;
  }
  if (s.test == LabTest::brazilian) r.thickness = disc_thickness(model.particles, s);
  // Before the time step: its bound sees the scaled masses.
  const ScaledMasses scaled(model, s.mass_scaling);
  r.mass_scaling = s.mass_scaling;

  if (s.time_step > 0.0) {
    r.time_step = s.time_step;
  } else {
    r.time_step = s.safety_factor * stability_limit(model);
  }
  if (!std::isfinite(r.time_step) || r.time_step <= 0.0) {
    throw InputError("compression.time_step", "cannot derive a stable time step",
                     "set compression.time_step");
  }

  const double final_strain = s.failure_drop > 0.0 ? s.max_strain : s.target_strain;
  const double duration = final_strain * l / speed;
  // As for a run's end_time (scenario/scenario.cpp): beyond 1e15 steps the test would never end.
  if (!(r.time_step >= 1e-15 * duration)) {
    char what[256];
    std::snprintf(what, sizeof what,
                  "the test would take %.3g steps: the time step is %.6g s, below 1e-15 of its "
                  "duration %.6g s "
                  "(strain %g at strain_rate %g 1/s)",
                  duration / r.time_step, r.time_step, duration, final_strain, s.strain_rate);
    throw InputError("compression.time_step", what,
                     "a step that small comes from extreme material values: check the densities, "
                     "radii and Young's "
                     "moduli, or raise strain_rate");
  }
  Simulation sim(model, r.time_step);
  const auto total_steps = static_cast<std::int64_t>(std::ceil(duration / r.time_step));
  // curve_points up to target_strain, where K, E and nu are fitted; a test run past it to failure
  // goes on at the same spacing, so its fit window and its peak are as finely resolved.
  const auto target_steps =
      static_cast<std::int64_t>(std::ceil(s.target_strain * l / speed / r.time_step));
  const std::int64_t every = std::max<std::int64_t>(1, target_steps / s.curve_points);
  const double area = r.sample.area;
  const StrainGauge gauge(model.particles.reference_position, a, r.sample);
  r.gauge_particles = gauge.size();

  // The break log only grows: each point counts the breaks since the last one (a resumed test
  // counts the restored log at its first point).
  std::size_t breaks_counted = 0, broken_in_tension = 0;
  auto record = [&] {
    CompressionPoint pt;
    pt.time = sim.time();
    const ParticleStore& p = model.particles;
    if (tension) {
      // The sample pulls the upper grip back along -a and the lower one along +a. A prescribed
      // particle's force is what its bonds and contacts exert (local damping acts on free DOFs).
      const auto i = static_cast<std::size_t>(grip_top.front());
      pt.displacement = dot(p.position[i] - p.reference_position[i], a);
      for (const std::int32_t k : grip_top)
        pt.force_top -= dot(p.force[static_cast<std::size_t>(k)], a);
      for (const std::int32_t k : grip_bottom)
        pt.force_bottom += dot(p.force[static_cast<std::size_t>(k)], a);
    } else {
      pt.displacement = -dot(model.walls[top].displacement, a);
      pt.force_top = dot(model.walls[top].force, a);  // particles push the upper platen along +a
      pt.force_bottom = -dot(model.walls[bottom].force, a);  // ... and the lower one along -a
    }
    pt.strain = pt.displacement / l;
    pt.force = 0.5 * (pt.force_top + pt.force_bottom);
    const Energies e = sim.energies();
    pt.kinetic = e.kinetic;
    pt.elastic = e.elastic + e.contact;
    pt.bonds_broken = model.bonds.breaks.size();
    for (; breaks_counted < pt.bonds_broken; ++breaks_counted) {
      broken_in_tension += model.bonds.breaks[breaks_counted].mode == BreakMode::tension ? 1 : 0;
    }
    pt.bonds_broken_tension = broken_in_tension;
    if (gauge.valid()) {
      pt.gauge = gauge.measure([&](std::int32_t q) {
        return p.position[static_cast<std::size_t>(q)] -
               p.reference_position[static_cast<std::size_t>(q)];
      });
    }
    r.curve.push_back(pt);
    if (observer) observer(sim, pt);
    if (pt.force / area > r.peak_stress) {
      r.peak_stress = pt.force / area;
      r.peak_strain = pt.strain;
    }
    return pt;
  };

  if (hooks.resume) {
    CompressionProgress restored;
    hooks.resume(sim, restored);  // the first point and those up to the checkpoint are in it
    r.curve = std::move(restored.curve);
    r.peak_stress = restored.peak_stress;
    r.peak_strain = restored.peak_strain;
  } else {
    record();
  }
  r.stop = "target_strain";
  const auto start = std::chrono::steady_clock::now();
  auto checkpoint = [&] {
    hooks.checkpoint(sim, CompressionProgress{r.curve, r.peak_stress, r.peak_strain});
  };
  while (true) {
    sim.step();
    const bool curve_step = sim.steps() % every == 0 || sim.steps() >= total_steps;
    if (curve_step && test_ends(s, record(), area, r)) break;
    // After the point and the end check: a test resumed from here goes on with the next step.
    const bool checkpointed =
        hooks.checkpoint && hooks.checkpoint_every > 0 && sim.steps() % hooks.checkpoint_every == 0;
    if (checkpointed) checkpoint();
    if (hooks.interrupted && hooks.interrupted(sim)) {
      r.stop = "interrupted";
      if (hooks.checkpoint && !checkpointed) checkpoint();
      break;
    }
  }
  notify_run_ended(sim);
  r.final_energies = sim.energies();
  r.run.steps = sim.steps();
  r.run.time = sim.time();
  r.run.max_speed = sim.max_speed();
  r.run.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.run.bond_updates_per_second =
      r.run.wall_seconds > 0.0 ? static_cast<double>(sim.steps()) *
                                     static_cast<double>(model.bonds.size()) / r.run.wall_seconds
                               : 0.0;

  if (r.stop == "interrupted") return r;  // too few points for a fit

  std::vector<double> x, y;
  for (const CompressionPoint& pt : r.curve) {
    x.push_back(pt.displacement);
    y.push_back(pt.force);
  }
  const double from = s.fit_from * s.target_strain * l, to = s.fit_to * s.target_strain * l;
  const double window_end =
      to * (1.0 + 1e-9);  // the window's end, with the curve's last point in it
  const LinearFit fit = fit_line(x, y, from, window_end);
  if (fit.points < 2) {
    throw InputError("compression.fit_window", "holds fewer than two points of the curve",
                     "widen the window or raise curve_points");
  }
  r.stiffness = fit.slope;
  r.fit_r2 = fit.r2;
  r.fit_points = fit.points;
  r.fit_from_m = from;
  r.fit_to_m = to;
  r.youngs_modulus = r.stiffness * l / area;
  if (gauge.valid()) {
    std::vector<double> axial, lateral;
    for (const CompressionPoint& pt : r.curve) {
      axial.push_back(pt.gauge.axial);
      lateral.push_back(pt.gauge.lateral);
    }
    // Compression shortens the gauge (d eps_a / dw < 0), tension lengthens it: the same E and nu.
    const double sign = tension ? -1.0 : 1.0;
    r.body = body_moduli(r.stiffness, area, sign * fit_line(x, axial, from, window_end).slope,
                         sign * fit_line(x, lateral, from, window_end).slope);
    // A disc loaded across its diameter has no uniform middle third: no E or nu from it.
    if (s.test == LabTest::brazilian) r.body = {};
  }
  const auto peak = std::max_element(
      r.curve.begin(), r.curve.end(),
      [](const CompressionPoint& p, const CompressionPoint& q) { return p.force < q.force; });
  r.peak_force = peak->force;
  if (peak->elastic > 0.0) r.peak_kinetic_ratio = peak->kinetic / peak->elastic;
  if (peak->force > 0.0)
    r.peak_force_imbalance = std::abs(peak->force_top - peak->force_bottom) / peak->force;
  r.strength = test_stress(s.test, r.peak_force, l, area, r.thickness);
  for (const CompressionPoint& pt : r.curve) {
    if (pt.displacement < from || pt.displacement > window_end || pt.elastic <= 0.0) continue;
    r.max_kinetic_ratio = std::max(r.max_kinetic_ratio, pt.kinetic / pt.elastic);
    if (pt.force > 0.0) {
      r.max_force_imbalance =
          std::max(r.max_force_imbalance, std::abs(pt.force_top - pt.force_bottom) / pt.force);
    }
  }
  if (!(r.stiffness > 0.0)) refuse_stiffness(r, model.bonds.size(), from, window_end);
  return r;
}

}  // namespace bpm
