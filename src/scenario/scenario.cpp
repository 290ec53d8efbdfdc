// Reading a scenario: one function per top-level section, in the order the model needs them
// (materials, structure, damping, constraints and loads, then the time step, which needs the
// finalised model). The structure sections live in scenario_structure.cpp.
#include "scenario/scenario.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <limits>
#include <set>

#include "bonds/bond_model.hpp"
#include "compress/mass_scaling.hpp"
#include "core/error.hpp"
#include "dem/contact_time_step.hpp"
#include "io/parse_number.hpp"
#include "scenario/scenario_builder.hpp"
#include "io/yaml_field.hpp"

namespace bpm {
namespace {

using scenario_detail::ScenarioBuilder;

// ---------------------------------------------------------------------------------------------
// Materials

void read_particle_materials(ScenarioBuilder& b, const YamlField& section) {
  Scenario& s = b.scenario;
  const auto entries = section.entries();
  if (entries.empty()) section.fail("defines no material", "add one, e.g. 'steel: {density: 7850}'");
  for (const auto& [name, value] : entries) {
    const YamlMap m = value.map({"density", "contact"});
    s.particle_material_names.push_back(name);
    s.particle_densities.push_back(m.require("density", "give the particle density in kg/m^3").positive());
    const auto contact = m.find("contact");
    b.contact_materials.push_back(contact ? std::optional(scenario_detail::read_contact_material(name, *contact)) : std::nullopt);
  }
}

/// Once contacts, walls or a compression test are used, every particle material needs its contact
/// properties; they become the model's contact materials (same indices).
void resolve_contact_materials(ScenarioBuilder& b, const YamlField& section) {
  Scenario& s = b.scenario;
  if (!s.model.contacts.particle_particle && s.model.walls.empty() && !s.compression) return;
  s.model.contacts.materials.clear();
  for (std::size_t i = 0; i < b.contact_materials.size(); ++i) {
    if (!b.contact_materials[i]) {
      section.fail("material '" + s.particle_material_names[i] + "' has no contact properties, which contacts, walls and compression need",
                   "add e.g. 'contact: {youngs_modulus: 1e9, poisson_ratio: 0.3, restitution: 0.5, friction: 0.3}'");
    }
    s.model.contacts.materials.push_back(*b.contact_materials[i]);
  }
  try {
    ContactTable check(s.model.contacts);
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}:{}", s.path, section.line()), e.what());
  }
}

/// `shear_stiffness`: a number in N/m, or the name of a beam-theory rule (Chen case 5 uses
/// euler_bernoulli, Eq. 26, for the PBM).
void read_shear_override(BondMaterial& mat, const YamlField& field) {
  const std::string text = field.text();
  if (text == "euler_bernoulli") {
    mat.shear_override = ShearOverride::euler_bernoulli;
  } else if (text == "timoshenko") {
    mat.shear_override = ShearOverride::timoshenko;
  } else if (parse_double(text)) {
    mat.shear_override = ShearOverride::value;
    mat.shear_stiffness = field.positive();
  } else {
    field.fail("expected a stiffness in N/m, euler_bernoulli or timoshenko, got '" + text + "'",
               "write e.g. 1e9, euler_bernoulli (Chen Eq. 26) or timoshenko (Chen Eq. 18)");
  }
}

/// A strength in Pa: a number, or {distribution: normal, mean, std_dev} or
/// {distribution: weibull, scale, shape}.
StrengthDistribution read_strength(const YamlField& field) {
  using Kind = StrengthDistribution::Kind;
  if (field.is_scalar()) return {Kind::constant, field.positive(), 0.0};
  const YamlMap m = field.map({"distribution", "mean", "std_dev", "scale", "shape"});
  const YamlField kind = m.require("distribution", "normal (mean, std_dev) or weibull (scale, shape)");
  if (kind.text() == "normal") {
    if (m.has("scale") || m.has("shape")) kind.fail("a normal distribution takes mean and std_dev", "remove scale/shape");
    return {Kind::normal, m.require("mean", "give the mean strength in Pa").positive(),
            m.require("std_dev", "give the standard deviation in Pa").non_negative()};
  }
  if (kind.text() == "weibull") {
    if (m.has("mean") || m.has("std_dev")) kind.fail("a Weibull distribution takes scale and shape", "remove mean/std_dev");
    return {Kind::weibull, m.require("scale", "give the Weibull scale (characteristic strength) in Pa").positive(),
            m.require("shape", "give the Weibull modulus m, e.g. 5").positive()};
  }
  kind.fail("unknown distribution '" + kind.text() + "'", "use normal or weibull, or give a number for a constant strength");
}

BondMaterial read_bond_material(const std::string& name, const YamlField& field) {
  const YamlMap m = field.map({"model", "youngs_modulus", "poisson_ratio", "kappa", "shear_coefficient",
                               "shear_stiffness", "radius", "radius_multiplier", "tensile_strength",
                               "shear_strength"});
  BondMaterial mat;
  mat.name = name;
  const YamlField model = m.require("model", "one of pbm, brendel, ebbm, tbbm, obermayr");
  mat.model = model.text();
  find_bond_model(mat.model, model.where());  // throws, listing the valid keys
  mat.youngs_modulus = m.require("youngs_modulus", "give the bond Young's modulus E_b in Pa").positive();
  const YamlField nu = m.require("poisson_ratio", "give the bond Poisson ratio nu_b, 0 <= nu_b < 0.5");
  mat.poisson_ratio = nu.number();
  if (!(mat.poisson_ratio >= 0.0 && mat.poisson_ratio < 0.5)) {
    nu.fail(fmt::format("must be in [0, 0.5), got {}", mat.poisson_ratio),
            "use 0 <= nu_b < 0.5: at 0.5 the solid is incompressible; steel is about 0.3");
  }
  if (const auto kappa = m.find("kappa")) {
    // Only the PBM reads kappa; elsewhere it would be silently ignored, so refuse it.
    if (mat.model != "pbm") kappa->fail("kappa applies only to model pbm", "remove it, or use model: pbm");
    mat.kappa = kappa->positive();
  }
  if (const auto alpha = m.find("shear_coefficient")) {
    if (mat.model != "obermayr") alpha->fail("shear_coefficient applies only to model obermayr", "remove it");
    mat.shear_coefficient = alpha->positive();
  }
  if (const auto ks = m.find("shear_stiffness")) read_shear_override(mat, *ks);
  const auto radius = m.find("radius");
  const auto multiplier = m.find("radius_multiplier");
  if (radius && multiplier) multiplier->fail("give either radius or radius_multiplier, not both");
  if (radius) mat.radius = radius->positive();
  if (multiplier) mat.radius_multiplier = multiplier->positive();
  if (const auto f = m.find("tensile_strength")) mat.tensile_strength = read_strength(*f);
  if (const auto f = m.find("shear_strength")) mat.shear_strength = read_strength(*f);
  return mat;
}

void read_bond_materials(Scenario& s, const YamlField& section) {
  for (const auto& [name, value] : section.entries()) {
    s.bond_material_names.push_back(name);
    s.bond_materials.push_back(read_bond_material(name, value));
  }
}

// ---------------------------------------------------------------------------------------------
// Particle sets: `particles: [ids] | all` or `region: {box: {min, max}}`

std::vector<std::int32_t> read_particle_set(const ScenarioBuilder& b, const YamlMap& m) {
  const ParticleStore& p = b.scenario.model.particles;
  const auto [kind, field] = m.one_of({"particles", "region"});
  std::vector<std::int32_t> set;
  if (kind == "particles") {
    if (field.is_scalar() && field.text() == "all") {
      for (std::size_t i = 0; i < p.size(); ++i) set.push_back(static_cast<std::int32_t>(i));
      return set;
    }
    std::set<std::int32_t> seen;
    for (const YamlField& item : field.items()) {
      const std::int64_t id = item.integer();
      const auto it = b.index_of_id.find(id);
      if (it == b.index_of_id.end()) item.fail(fmt::format("no particle has id {}", id), "use ids defined in the particles section");
      if (!seen.insert(it->second).second) item.fail(fmt::format("particle id {} is listed twice", id), "list each id once");
      set.push_back(it->second);
    }
    if (set.empty()) field.fail("the list is empty", "name at least one particle id, or write 'all'");
    return set;
  }
  const YamlMap region = field.map({"box"});
  const YamlMap box = region.require("box", "write box: {min: [x, y, z], max: [x, y, z]}").map({"min", "max"});
  const Vec3 lo = box.require("min", "give the lower corner [x, y, z]").vec3();
  const YamlField max_field = box.require("max", "give the upper corner [x, y, z]");
  const Vec3 hi = max_field.vec3();
  for (int d = 0; d < 3; ++d) {
    if (lo[d] > hi[d]) max_field.fail("every max coordinate must be >= the min coordinate", "swap the corners");
  }
  for (std::size_t i = 0; i < p.size(); ++i) {  // inclusive bounds, on the initial positions
    const Vec3& x = p.reference_position[i];
    if (x.x >= lo.x && x.x <= hi.x && x.y >= lo.y && x.y <= hi.y && x.z >= lo.z && x.z <= hi.z) {
      set.push_back(static_cast<std::int32_t>(i));
    }
  }
  if (set.empty()) field.fail("the box contains no particle centre", "widen the box or check the particle positions");
  return set;
}

// ---------------------------------------------------------------------------------------------
// Damping, constraints, loads, gravity

void read_damping(Scenario& s, const YamlField& section) {
  const YamlMap m = section.map({"particle", "bond"});
  if (const auto gamma = m.find("particle")) {
    s.model.damping.particle = gamma->number();
    if (!(s.model.damping.particle >= 0.0 && s.model.damping.particle < 1.0)) {
      gamma->fail(fmt::format("must be in [0, 1), got {}", s.model.damping.particle),
                  "gamma_b (Chen Eq. 11-12) is a fraction of the unbalanced load; 0 switches it off");
    }
  }
  if (const auto eta = m.find("bond")) s.model.damping.bond = eta->non_negative();  // eta_b, Chen Eq. 9-10
}

/// `fix: all` or a list of DOF names; returns the (translation, rotation) masks, 1 = fixed.
std::pair<Vec3, Vec3> read_fixed_dofs(const YamlField& field) {
  if (field.is_scalar() && field.text() == "all") return {{1, 1, 1}, {1, 1, 1}};
  if (!field.is_sequence()) field.fail("expected 'all' or a list of degrees of freedom", "write e.g. fix: all or fix: [x, y, rz]");
  static constexpr std::array<std::string_view, 6> kNames{"x", "y", "z", "rx", "ry", "rz"};
  Vec3 translation, rotation;
  for (const YamlField& item : field.items()) {
    const std::string name = item.text();
    const auto it = std::find(kNames.begin(), kNames.end(), name);
    if (it == kNames.end()) item.fail("unknown degree of freedom '" + name + "'", "use x, y, z, rx, ry, rz, or write fix: all");
    const auto d = static_cast<int>(it - kNames.begin());
    (d < 3 ? translation[d] : rotation[d - 3]) = 1.0;
  }
  return {translation, rotation};
}

/// `velocity: [vx, vy, vz]`: a number prescribes that component, `~` (null) leaves it free.
std::array<std::optional<double>, 3> read_prescribed(const YamlField& field) {
  const auto items = field.items();
  if (items.size() != 3) field.fail(fmt::format("expected 3 entries, got {}", items.size()), "write [vx, vy, vz]; ~ leaves a component free");
  std::array<std::optional<double>, 3> out;
  for (std::size_t d = 0; d < 3; ++d) {
    if (!items[d].is_null()) out[d] = items[d].number();
  }
  if (!out[0] && !out[1] && !out[2]) field.fail("prescribes no component", "give at least one number");
  return out;
}

void read_boundary_conditions(ScenarioBuilder& b, const YamlField& section) {
  Model& model = b.scenario.model;
  for (const YamlField& item : section.items()) {
    const YamlMap m = item.map({"particles", "region", "fix", "velocity", "angular_velocity"});
    const auto set = read_particle_set(b, m);
    const auto fix = m.find("fix");
    const auto velocity = m.find("velocity");
    const auto spin = m.find("angular_velocity");
    if (!fix && !velocity && !spin) item.fail("constrains nothing", "add fix, velocity or angular_velocity");
    const auto [t_fixed, r_fixed] = fix ? read_fixed_dofs(*fix) : std::pair<Vec3, Vec3>{};
    std::array<std::optional<double>, 3> v, w;
    if (velocity) v = read_prescribed(*velocity);
    if (spin) w = read_prescribed(*spin);
    for (int d = 0; d < 3; ++d) {
      const auto k = static_cast<std::size_t>(d);
      if (v[k] && t_fixed[d] != 0.0) velocity->fail("a component is both fixed and prescribed", "fix means velocity 0; keep one of the two");
      if (w[k] && r_fixed[d] != 0.0) spin->fail("a component is both fixed and prescribed", "fix means angular velocity 0; keep one of the two");
    }
    // A prescribed velocity is a fixed DOF (mask 0) that keeps a non-zero velocity: the integrator
    // never changes it, so the particle moves at exactly that rate.
    for (const std::int32_t p : set) {
      model.fix(p, t_fixed, r_fixed);
      for (int d = 0; d < 3; ++d) {
        const auto k = static_cast<std::size_t>(d);
        if (v[k]) {
          model.particles.translation_free[p][d] = 0.0;
          model.particles.velocity[p][d] = *v[k];
        }
        if (w[k]) {
          model.particles.rotation_free[p][d] = 0.0;
          model.particles.angular_velocity[p][d] = *w[k];
        }
      }
    }
  }
}

void read_loads(ScenarioBuilder& b, const YamlField& section) {
  for (const YamlField& item : section.items()) {
    const YamlMap m = item.map({"particles", "region", "force", "moment", "ramp_time"});
    Load load;
    load.particles = read_particle_set(b, m);
    if (!m.has("force") && !m.has("moment")) item.fail("applies nothing", "add force: [fx, fy, fz] and/or moment: [mx, my, mz]");
    if (const auto f = m.find("force")) load.force = f->vec3();
    if (const auto mo = m.find("moment")) load.moment = mo->vec3();
    if (const auto ramp = m.find("ramp_time")) load.ramp_time = ramp->non_negative();
    b.scenario.model.loads.push_back(std::move(load));
  }
}

// ---------------------------------------------------------------------------------------------
// Time step, stop criteria, output

void read_integrator(Scenario& s, const std::optional<YamlField>& section, bool derive_limit) {
  std::optional<YamlField> dt_field;
  if (section) {
    const YamlMap m = section->map({"time_step", "safety_factor"});
    if (const auto f = m.find("safety_factor")) {
      s.safety_factor = f->number();
      if (!(s.safety_factor > 0.0 && s.safety_factor <= 1.0)) {
        f->fail(fmt::format("must be in (0, 1], got {}", s.safety_factor), "0.8 is a good default");
      }
    }
    if (const auto f = m.find("time_step"); f && !(f->is_scalar() && f->text() == "auto")) dt_field = f;
  }
  s.time_step_given = dt_field.has_value();
  if (!derive_limit) {
    s.time_step_limit = std::numeric_limits<double>::infinity();
    s.time_step = dt_field ? dt_field->positive() : 0.0;
    return;
  }
  try {
    s.time_step_limit = stability_limit(s.model);
  } catch (const InputError& e) {
    // Nothing bounds the step (no bond acts on a free particle, no contacts): fine if the user gave
    // one. e.what() already names integrator.time_step; add file and line.
    if (!dt_field) throw InputError(section ? fmt::format("{}:{}", s.path, section->line()) : s.path, e.what());
    s.time_step_limit = std::numeric_limits<double>::infinity();
  }
  if (!dt_field) {
    s.time_step = s.safety_factor * s.time_step_limit;
    return;
  }
  s.time_step = dt_field->positive();
  if (s.time_step > s.time_step_limit) {
    dt_field->fail(fmt::format("{:.6g} s is above this model's stability limit of {:.6g} s", s.time_step, s.time_step_limit),
                   fmt::format("use a step of at most {:.6g} s, or time_step: auto", s.time_step_limit));
  }
}

/// A step below this fraction of the run length is refused: 1e15 steps take years at any speed,
/// and near 1e-16 `time += dt` stops advancing, so the run would never end.
constexpr double kMinStepFraction = 1e-15;

/// The steps end_time needs at the time step the run will use, checked before the run: a 0-step
/// run, an endless one (a step that extreme values make 0 or 1e-149 s) and one that max_steps
/// would cut short are refused with the estimate.
void check_step_count(const Scenario& s, const YamlField& end_field, const std::optional<YamlField>& max_field) {
  const double end = s.stop.end_time, dt = s.time_step;
  const double steps = end / dt;  // Simulation::run takes round(end / dt) steps (half a step of slack)
  const std::string step_text =
      fmt::format("the time step is {:.6g} s ({})", dt,
                  s.time_step == s.safety_factor * s.time_step_limit
                      ? fmt::format("auto: {} x the stability limit {:.6g} s", s.safety_factor, s.time_step_limit)
                      : std::string("integrator.time_step"));
  if (end < 0.5 * dt) {
    end_field.fail(fmt::format("{:.6g} s is below half a time step, so the run would take 0 steps; {}", end, step_text),
                   fmt::format("give an end_time of at least one step, {:.6g} s", dt));
  }
  if (!(dt >= kMinStepFraction * end)) {
    end_field.fail(fmt::format("would take {:.3g} steps: {}, below {:.0e} of end_time", steps, step_text, kMinStepFraction),
                   "a step that small comes from extreme material values: check the densities, radii and Young's "
                   "moduli, or shorten end_time");
  }
  // With rest_speed, end_time and max_steps are both guards for a run meant to end at rest.
  if (max_field && s.stop.rest_speed == 0.0 && std::round(steps) > static_cast<double>(s.stop.max_steps)) {
    max_field->fail(fmt::format("{} steps do not reach end_time {:.6g} s, which needs about {:.0f} steps: {}",
                                s.stop.max_steps, end, std::round(steps), step_text),
                    fmt::format("raise max_steps to at least {:.0f}, shorten end_time, or give only one of the two",
                                std::round(steps)));
  }
}

void read_stop(Scenario& s, const YamlField& section) {
  const YamlMap m = section.map({"end_time", "max_steps", "rest_speed", "rest_after"});
  if (!m.has("end_time") && !m.has("max_steps")) {
    section.fail("needs end_time or max_steps, so that every run ends", "add e.g. end_time: 100");
  }
  if (const auto f = m.find("end_time")) s.stop.end_time = f->positive();
  if (const auto f = m.find("max_steps")) {
    s.stop.max_steps = f->integer();
    if (s.stop.max_steps < 1) f->fail(fmt::format("must be at least 1, got {}", s.stop.max_steps));
  }
  if (const auto f = m.find("rest_speed")) s.stop.rest_speed = f->non_negative();
  // Rest is meaningless while loads still ramp up: by default check it only once all have.
  s.stop.rest_after = 0.0;
  for (const Load& load : s.model.loads) s.stop.rest_after = std::max(s.stop.rest_after, load.ramp_time);
  if (const auto f = m.find("rest_after")) s.stop.rest_after = f->non_negative();
  if (const auto f = m.find("end_time")) check_step_count(s, *f, m.find("max_steps"));
}

bool valid_probe_name(const std::string& name) {
  return !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
  });
}

/// output.checkpoint_every: {steps: N} or {time: T} (s, rounded to whole steps).
void read_checkpoint_every(Scenario& s, const YamlField& field) {
  const YamlMap m = field.map({"steps", "time"});
  const auto steps = m.find("steps");
  const auto time = m.find("time");
  if (steps.has_value() == time.has_value()) field.fail("give one of steps or time", "e.g. 'checkpoint_every: {steps: 10000}'");
  if (steps) {
    s.output.checkpoint_every_steps = steps->integer();
    if (s.output.checkpoint_every_steps < 1) steps->fail(fmt::format("must be at least 1, got {}", s.output.checkpoint_every_steps));
  } else {
    const double ratio = std::min(time->positive() / s.time_step, 1e15);
    s.output.checkpoint_every_steps = std::max<std::int64_t>(1, std::llround(ratio));
  }
}

void read_output(ScenarioBuilder& b, const YamlField& section) {
  Scenario& s = b.scenario;
  const YamlMap m = section.map({"every_steps", "every_time", "vtk", "bond_csv", "probes", "checkpoint_every"});
  const auto steps = m.find("every_steps");
  const auto time = m.find("every_time");
  if (steps && time) time->fail("give either every_steps or every_time, not both");
  if (steps) {
    s.output.every_steps = steps->integer();
    if (s.output.every_steps < 1) steps->fail(fmt::format("must be at least 1, got {}", s.output.every_steps));
  }
  if (time) {
    // Outputs happen between steps, so the interval is rounded to a whole number of steps.
    s.output.every_time = time->positive();
    const double ratio = std::min(s.output.every_time / s.time_step, 1e15);
    s.output.every_steps = std::max<std::int64_t>(1, std::llround(ratio));
  }
  if (const auto vtk = m.find("vtk")) s.output.vtk = vtk->boolean();
  if (const auto bond_csv = m.find("bond_csv")) s.output.bond_csv = bond_csv->boolean();
  if (const auto every = m.find("checkpoint_every")) read_checkpoint_every(s, *every);
  if (const auto probes = m.find("probes")) {
    std::set<std::string> names;
    for (const YamlField& item : probes->items()) {
      const YamlMap pm = item.map({"name", "particles", "region"});
      const YamlField name_field = pm.require("name", "give the probe a name; it heads its CSV columns");
      Probe probe;
      probe.name = name_field.text();
      if (!valid_probe_name(probe.name)) name_field.fail("'" + probe.name + "' is not a valid probe name", "use letters, digits, '_', '-' and '.'");
      if (!names.insert(probe.name).second) name_field.fail("duplicate probe name '" + probe.name + "'", "give each probe its own name");
      probe.particles = read_particle_set(b, pm);
      s.probes.push_back(std::move(probe));
    }
  }
}

/// The scenario of a parsed file (or text) that stands for `path`.
Scenario build_scenario(const YamlField& root, const std::string& path, const ScenarioLoadOptions& options) {
  if (root.is_null()) root.fail("the scenario file is empty", "see docs/scenario.md for the keys");
  const YamlMap m = root.map({"description", "particle_materials", "bond_materials", "particles", "bonds", "damping",
                              "boundary_conditions", "loads", "gravity", "integrator", "stop", "output", "seed",
                              "contacts", "walls", "compression"});
  Scenario s;
  s.path = path;
  ScenarioBuilder b{s, std::filesystem::path(path).parent_path(), {}, {}};
  if (const auto f = m.find("description")) s.description = f->text();

  const YamlField materials = m.require("particle_materials", "define at least one, e.g. 'steel: {density: 7850}'");
  read_particle_materials(b, materials);
  read_bond_materials(s, m.require("bond_materials", "define e.g. 'beam: {model: tbbm, youngs_modulus: 200e9, poisson_ratio: 0.3}'"));
  scenario_detail::read_particles(b, m.require("particles", "give the particles with file:, list: or row:"));
  scenario_detail::read_bonds(b, m.require("bonds", "give the bonds with file:, list: or auto: (list: [] for none)"));
  if (const auto f = m.find("damping")) read_damping(s, *f);
  if (const auto f = m.find("boundary_conditions")) read_boundary_conditions(b, *f);
  if (const auto f = m.find("loads")) read_loads(b, *f);
  if (const auto f = m.find("gravity")) s.model.gravity = f->vec3();
  if (const auto f = m.find("contacts")) scenario_detail::read_contacts(b, *f);
  if (const auto f = m.find("walls")) scenario_detail::read_walls(b, *f);
  if (const auto f = m.find("compression")) scenario_detail::read_compression(b, *f);
  resolve_contact_materials(b, materials);

  // Strengths are drawn in bond order from one generator: the same seed, the same strengths.
  const auto seed = m.find("seed");
  const std::int64_t seed_value = seed ? seed->integer() : 1;
  if (seed && seed_value < 0) seed->fail("must be a non-negative integer");
  s.seed = static_cast<std::uint64_t>(seed_value);
  s.model.bonds.draw_strengths(s.bond_materials, s.seed);
  // The bond axes and damping coefficients are needed for the stability limit.
  s.model.finalize();
  {
    // A compression test with mass scaling runs at the step of the scaled masses.
    const ScaledMasses scaled(s.model, s.compression ? s.compression->mass_scaling : 1.0);
    read_integrator(s, m.find("integrator"), options.time_step);
  }
  if (s.compression) {
    // The compression test ends itself (target strain or failure).
    if (const auto f = m.find("stop")) f->fail("a compression test stops at its target strain", "remove stop, or the compression section");
    s.compression->time_step = s.time_step;
  } else {
    read_stop(s, m.require("stop", "add e.g. 'stop: {end_time: 10}' (end_time or max_steps is required)"));
  }
  if (const auto f = m.find("output")) read_output(b, *f);
  return s;
}

}  // namespace

Scenario load_scenario(const std::string& path, const ScenarioLoadOptions& options) {
  return build_scenario(YamlField::load_file(path), path, options);
}

Scenario load_scenario_text(const std::string& text, const std::string& path, const ScenarioLoadOptions& options) {
  return build_scenario(YamlField::load_text(text, path), path, options);
}

}  // namespace bpm
