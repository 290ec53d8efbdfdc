// The contact sections of a scenario: the `contact` block of each particle material, `contacts`
// (particle-particle contacts and pair rules), `walls` and `compression` (docs/scenario.md).
#include <fmt/core.h>

#include <cmath>
#include <string>

#include "core/error.hpp"
#include "scenario/scenario_builder.hpp"

namespace bpm::scenario_detail {
namespace {

ContactLaw read_law(const YamlField& field) {
  const std::string text = field.text();
  if (text == "hertz_mindlin") return ContactLaw::hertz_mindlin;
  if (text == "linear") return ContactLaw::linear;
  field.fail("unknown contact law '" + text + "'", "use hertz_mindlin or linear");
}

BondedContacts read_bonded(const YamlField& field) {
  const std::string text = field.text();
  if (text == "superimpose") return BondedContacts::superimpose;
  if (text == "replace") return BondedContacts::replace;
  field.fail("unknown value '" + text + "'", "use superimpose (contact and bond act together) or replace (no contact while bonded)");
}

double read_restitution(const YamlField& field) {
  const double e = field.number();
  if (!(e > 0.0 && e <= 1.0)) field.fail(fmt::format("must be in (0, 1], got {}", e), "1 is elastic; 0.5 is a typical value");
  return e;
}

std::int32_t material_index(const ScenarioBuilder& b, const YamlField& field) {
  const auto index = find_name(b.scenario.particle_material_names, field.text());
  if (!index) {
    field.fail("no particle material is called '" + field.text() + "'",
               "use one of: " + list_names(b.scenario.particle_material_names));
  }
  return *index;
}

}  // namespace

ContactMaterial read_contact_material(const std::string& name, const YamlField& field) {
  const YamlMap m = field.map({"law", "youngs_modulus", "poisson_ratio", "k_n", "k_t", "restitution", "friction",
                               "rolling_friction"});
  ContactMaterial c;
  c.name = name;
  if (const auto f = m.find("law")) c.law = read_law(*f);
  if (c.law == ContactLaw::hertz_mindlin) {
    for (const char* key : {"k_n", "k_t"}) {
      if (const auto f = m.find(key)) f->fail("the Hertz-Mindlin law takes youngs_modulus and poisson_ratio", "remove it, or use law: linear");
    }
    c.youngs_modulus = m.require("youngs_modulus", "give the particle Young's modulus E in Pa").positive();
    const YamlField nu = m.require("poisson_ratio", "give the particle Poisson ratio, 0 <= nu < 0.5");
    c.poisson_ratio = nu.number();
    if (!(c.poisson_ratio >= 0.0 && c.poisson_ratio < 0.5)) nu.fail(fmt::format("must be in [0, 0.5), got {}", c.poisson_ratio));
  } else {
    for (const char* key : {"youngs_modulus", "poisson_ratio"}) {
      if (const auto f = m.find(key)) f->fail("the linear law takes k_n and k_t", "remove it, or use law: hertz_mindlin");
    }
    c.k_n = m.require("k_n", "give the normal spring stiffness in N/m").positive();
    c.k_t = m.require("k_t", "give the tangential spring stiffness in N/m").positive();
  }
  if (const auto f = m.find("restitution")) c.restitution = read_restitution(*f);
  if (const auto f = m.find("friction")) c.friction = f->non_negative();
  if (const auto f = m.find("rolling_friction")) c.rolling_friction = f->non_negative();
  return c;
}

void read_contacts(ScenarioBuilder& b, const YamlField& section) {
  ContactModel& c = b.scenario.model.contacts;
  const YamlMap m = section.map({"particle_particle", "bonded", "skin", "no_tension", "pairs"});
  if (const auto f = m.find("particle_particle")) c.particle_particle = f->boolean();
  if (const auto f = m.find("bonded")) c.bonded = read_bonded(*f);
  if (const auto f = m.find("skin")) c.skin = f->positive();
  if (const auto f = m.find("no_tension")) c.no_tension = f->boolean();
  if (const auto pairs = m.find("pairs")) {
    for (const YamlField& item : pairs->items()) {
      const YamlMap pm = item.map({"materials", "law", "restitution", "friction", "rolling_friction", "bonded"});
      const YamlField names = pm.require("materials", "name the two particle materials, e.g. [glass, steel]");
      const auto both = names.items();
      if (both.size() != 2) names.fail("must name exactly two particle materials");
      ContactPairRule rule;
      rule.a = material_index(b, both[0]);
      rule.b = material_index(b, both[1]);
      if (const auto f = pm.find("law")) rule.law = read_law(*f);
      if (const auto f = pm.find("restitution")) rule.restitution = read_restitution(*f);
      if (const auto f = pm.find("friction")) rule.friction = f->non_negative();
      if (const auto f = pm.find("rolling_friction")) rule.rolling_friction = f->non_negative();
      if (const auto f = pm.find("bonded")) rule.bonded = read_bonded(*f);
      c.pair_rules.push_back(rule);
    }
  }
}

void read_walls(ScenarioBuilder& b, const YamlField& section) {
  std::vector<Wall>& walls = b.scenario.model.walls;
  for (const YamlField& item : section.items()) {
    const YamlMap m = item.map({"name", "shape", "point", "normal", "axis", "edge", "half_width", "half_height",
                                "radius", "inside", "material", "velocity", "servo"});
    Wall w;
    w.name = m.require("name", "give the wall a name; it heads its columns in walls.csv").text();
    for (const Wall& other : walls) {
      if (other.name == w.name) m.require("name", "").fail("duplicate wall name '" + w.name + "'", "give each wall its own name");
    }
    const YamlField shape = m.require("shape", "plane, rectangle, disc or cylinder");
    const std::string kind = shape.text();
    if (kind == "plane") w.shape = WallShape::plane;
    else if (kind == "rectangle") w.shape = WallShape::rectangle;
    else if (kind == "disc") w.shape = WallShape::disc;
    else if (kind == "cylinder") w.shape = WallShape::cylinder;
    else shape.fail("unknown wall shape '" + kind + "'", "use plane, rectangle, disc or cylinder");
    const bool cylinder = w.shape == WallShape::cylinder;
    w.point = m.require("point", cylinder ? "give a point on the axis, [x, y, z]" : "give a point on the wall, [x, y, z]").vec3();
    const YamlField direction = cylinder ? m.require("axis", "give the cylinder axis, e.g. [0, 0, 1]")
                                         : m.require("normal", "give the unit normal (a plane's points towards the particles)");
    if (const auto wrong = m.find(cylinder ? "normal" : "axis")) {
      wrong->fail(cylinder ? "a cylinder takes axis, not normal" : "only a cylinder takes axis", "rename it");
    }
    const double length = norm(direction.vec3());
    if (!(length > 0.0)) direction.fail("must not be zero");
    w.normal = direction.vec3() / length;
    if (w.shape == WallShape::rectangle) {
      const YamlField edge = m.require("edge", "give the direction of the first side, normal to `normal`");
      const Vec3 e = edge.vec3() - dot(edge.vec3(), w.normal) * w.normal;
      if (!(norm(e) > 1e-9 * norm(edge.vec3()))) edge.fail("is parallel to the normal", "give a direction within the rectangle");
      w.edge = e / norm(e);
      w.half_width = m.require("half_width", "half the length along edge, m").positive();
      w.half_height = m.require("half_height", "half the length across edge, m").positive();
    }
    if (w.shape == WallShape::disc || cylinder) w.radius = m.require("radius", "give the radius in m").positive();
    if (const auto f = m.find("inside")) {
      if (!cylinder) f->fail("only a cylinder takes inside", "remove it");
      w.inside = f->boolean();
    }
    w.material = material_index(b, m.require("material", "name the particle material whose contact properties the wall has"));
    if (const auto f = m.find("velocity")) w.velocity = f->vec3();
    if (const auto servo = m.find("servo")) {
      if (cylinder) servo->fail("a cylinder cannot be servo-controlled", "use a plane, rectangle or disc");
      if (m.has("velocity")) servo->fail("give either velocity or servo, not both");
      const YamlMap sm = servo->map({"target_force", "gain", "max_speed"});
      w.servo.enabled = true;
      w.servo.target_force = sm.require("target_force", "the compressive force to hold, N").non_negative();
      w.servo.gain = sm.require("gain", "m/(N s): the wall speed per newton of force error").positive();
      if (const auto f = sm.find("max_speed")) w.servo.max_speed = f->positive();
    }
    walls.push_back(w);
  }
}

void read_compression(ScenarioBuilder& b, const YamlField& section) {
  Scenario& s = b.scenario;
  const YamlMap m = section.map({"test", "axis", "platen_material", "strain_rate", "target_strain", "fit_window",
                                 "failure_drop", "max_strain", "curve_points", "mass_scaling", "disc_axis",
                                 "grip_depth"});
  UniaxialCompression c;
  if (const auto f = m.find("test")) {
    const std::string name = f->text();
    if (name == "brazilian") {
      c.test = LabTest::brazilian;
    } else if (name == "tension") {
      c.test = LabTest::tension;
    } else if (name != "uniaxial") {
      f->fail("must be uniaxial, brazilian or tension, got '" + name + "'",
              "uniaxial: compression between platens (UCS); brazilian: a disc across its diameter (BTS); tension: "
              "pulled by grips");
    }
  }
  if (const auto f = m.find("axis")) {
    c.axis = f->vec3();
    if (!(norm(c.axis) > 0.0)) f->fail("must not be zero", "e.g. [0, 0, 1]");
  }
  c.platen_material = material_index(b, m.require("platen_material", "name the particle material of the platens"));
  c.strain_rate = m.require("strain_rate", "the platen speed as a strain rate in 1/s").positive();
  const YamlField target = m.require("target_strain", "the compressive strain to reach, e.g. 0.01");
  c.target_strain = target.positive();
  if (c.target_strain >= 1.0) target.fail("must be below 1", "e.g. 0.01 for 1 %");
  if (const auto f = m.find("fit_window")) {
    const auto w = f->items();
    if (w.size() != 2) f->fail("must be [from, to]", "fractions of target_strain, e.g. [0.2, 1.0]");
    c.fit_from = w[0].non_negative();
    c.fit_to = w[1].positive();
    if (!(c.fit_from < c.fit_to && c.fit_to <= 1.0)) f->fail("must satisfy 0 <= from < to <= 1", "e.g. [0.2, 1.0]");
  }
  if (const auto f = m.find("failure_drop")) {
    c.failure_drop = f->positive();
    if (c.failure_drop >= 1.0) f->fail("must be below 1", "e.g. 0.5: stop once the stress has fallen to half its peak");
    const YamlField max = m.require("max_strain", "with failure_drop, give the strain at which to stop anyway");
    c.max_strain = max.positive();
    if (c.max_strain <= c.target_strain) max.fail("must exceed target_strain");
  } else if (const auto max = m.find("max_strain")) {
    max->fail("max_strain applies only with failure_drop", "remove it, or add failure_drop");
  }
  if (const auto f = m.find("curve_points")) {
    c.curve_points = f->integer();
    if (c.curve_points < 10) f->fail("must be at least 10");
  }
  if (const auto f = m.find("disc_axis")) {
    if (c.test != LabTest::brazilian) f->fail("applies only to test: brazilian", "remove it, or set test: brazilian");
    c.disc_axis = f->vec3();
    if (!(norm(c.disc_axis) > 0.0)) f->fail("must not be zero", "e.g. [0, 0, 1]");
    if (std::abs(dot(c.disc_axis, c.axis)) > 1e-9 * norm(c.disc_axis) * norm(c.axis)) {
      f->fail("must be normal to the loading axis", "load the disc across its diameter: e.g. axis [1, 0, 0], disc_axis [0, 0, 1]");
    }
  } else if (c.test == LabTest::brazilian) {
    section.fail("test: brazilian needs disc_axis", "give the disc's axis, e.g. disc_axis: [0, 0, 1] with axis: [1, 0, 0]");
  }
  if (const auto f = m.find("grip_depth")) {
    if (c.test != LabTest::tension) f->fail("applies only to test: tension", "remove it, or set test: tension");
    c.grip_depth = f->positive();
  }
  if (const auto f = m.find("mass_scaling")) {
    c.mass_scaling = f->positive();
    if (!(c.mass_scaling >= 1.0)) f->fail("must be at least 1", "1 runs the real masses; 25 makes the test about 5 times shorter");
  }
  s.compression = c;
}

}  // namespace bpm::scenario_detail
