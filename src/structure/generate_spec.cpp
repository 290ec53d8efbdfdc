// Reading `bpmkit generate` spec files (docs/generate.md). Each section is read by one function;
// all checks happen here, so the generator itself can assume valid input.
#include "structure/generate_spec.hpp"

#include <fmt/core.h>
#include <sys/resource.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>

#include "core/error.hpp"
#include "io/yaml_field.hpp"
#include "structure/mesh_container.hpp"
#include "structure/stl_mesh.hpp"

namespace bpm {
namespace {

/// The value of `key` in /proc/meminfo (written in kB) in bytes; infinity if absent.
double meminfo_bytes(const std::string& key) {
  std::ifstream in("/proc/meminfo");
  for (std::string line; std::getline(in, line);) {
    if (line.starts_with(key)) return 1024.0 * std::strtod(line.c_str() + key.size(), nullptr);
  }
  return std::numeric_limits<double>::infinity();
}

std::shared_ptr<const Container> read_container(const YamlField& field, const std::filesystem::path& folder) {
  const YamlMap m = field.map({"box", "cylinder", "sphere", "stl"});
  const auto [kind, f] = m.one_of({"box", "cylinder", "sphere", "stl"});
  if (kind == "box") {
    const YamlMap b = f.map({"min", "max"});
    const Vec3 lo = b.require("min", "give the lower corner as [x, y, z] in metres").vec3();
    const YamlField hi_field = b.require("max", "give the upper corner as [x, y, z] in metres");
    const Vec3 hi = hi_field.vec3();
    if (!(hi.x > lo.x && hi.y > lo.y && hi.z > lo.z)) {
      hi_field.fail("every component of max must be greater than that of min", "swap or fix the corners");
    }
    return std::make_shared<BoxContainer>(lo, hi);
  }
  if (kind == "cylinder") {
    const YamlMap c = f.map({"radius", "height", "base"});
    const double r = c.require("radius", "give the cylinder radius in metres").positive();
    const double h = c.require("height", "give the cylinder height (along z) in metres").positive();
    const Vec3 base = c.has("base") ? c.find("base")->vec3() : Vec3{};
    return std::make_shared<CylinderContainer>(base, r, h);
  }
  if (kind == "sphere") {
    const YamlMap s = f.map({"radius", "centre"});
    const double r = s.require("radius", "give the sphere radius in metres").positive();
    const Vec3 centre = s.has("centre") ? s.find("centre")->vec3() : Vec3{};
    return std::make_shared<SphereContainer>(centre, r);
  }
  const YamlMap s = f.map({"file", "scale"});
  const YamlField file_field = s.require("file", "give the STL file, relative to this spec's folder");
  const std::filesystem::path given = file_field.text();
  const std::string path = (given.is_absolute() ? given : folder / given).lexically_normal().string();
  const double scale = s.has("scale") ? s.find("scale")->positive() : 1.0;
  return std::make_shared<MeshContainer>(read_stl(path, scale, file_field.where()), path);
}

/// Probability that a normal(mu, sigma) variable falls in [a, b].
double normal_mass(double mu, double sigma, double a, double b) {
  auto cdf = [&](double x) { return 0.5 * std::erfc(-(x - mu) / (sigma * std::numbers::sqrt2)); };
  return cdf(b) - cdf(a);
}

RadiusDistribution read_radii(const YamlField& field) {
  const YamlMap m = field.map({"monodisperse", "uniform", "normal", "lognormal", "table"});
  const auto [kind, f] = m.one_of({"monodisperse", "uniform", "normal", "lognormal", "table"});
  if (kind == "monodisperse") {
    const YamlMap d = f.map({"radius"});
    return RadiusDistribution::monodisperse(d.require("radius", "give the particle radius in metres").positive());
  }
  if (kind == "uniform") {
    const YamlMap d = f.map({"min", "max"});
    const double lo = d.require("min", "give the smallest radius in metres").positive();
    const YamlField hi_field = d.require("max", "give the largest radius in metres");
    const double hi = hi_field.positive();
    if (!(hi > lo)) hi_field.fail(fmt::format("must be greater than min ({}), got {}", lo, hi), "use min < max");
    return RadiusDistribution::uniform(lo, hi);
  }
  if (kind == "normal" || kind == "lognormal") {
    const YamlMap d = f.map({"mean", "std", "min", "max"});
    const double mean = d.require("mean", "give the mean radius in metres").positive();
    const double std = d.require("std", "give the standard deviation of the radius in metres").positive();
    const double lo = d.has("min") ? d.find("min")->positive() : 0.0;
    const double hi = d.has("max") ? d.find("max")->positive() : 0.0;
    RadiusDistribution dist = kind == "normal" ? RadiusDistribution::normal(mean, std, lo, hi)
                                               : RadiusDistribution::lognormal(mean, std, lo, hi);
    if (!(dist.max > dist.min)) {
      f.fail(fmt::format("the truncation window [{}, {}] m is empty", dist.min, dist.max), "use min < max");
    }
    double mass = 0.0;
    if (kind == "normal") {
      mass = normal_mass(mean, std, dist.min, dist.max);
    } else {
      const double sigma = std::sqrt(std::log1p(std * std / (mean * mean)));
      mass = normal_mass(std::log(mean) - 0.5 * sigma * sigma, sigma, std::log(dist.min), std::log(dist.max));
    }
    if (!(mass > 1e-4)) {
      f.fail(fmt::format("only a fraction {:.3g} of the distribution lies in [{}, {}] m", mass, dist.min, dist.max),
             "widen min/max around the mean");
    }
    return dist;
  }
  const YamlMap d = f.map({"fractions", "rows"});
  const YamlField basis_field = d.require("fractions", "write 'fractions: number' or 'fractions: volume'");
  const std::string basis = basis_field.text();
  if (basis != "number" && basis != "volume") basis_field.fail("expected 'number' or 'volume', got '" + basis + "'");
  const YamlField rows_field = d.require("rows", "give rows [radius, fraction]");
  std::vector<double> radius, fraction;
  for (const YamlField& row : rows_field.items()) {
    const auto cells = row.items();
    if (cells.size() != 2) row.fail(fmt::format("expected [radius, fraction], got {} items", cells.size()), "write [radius in m, fraction]");
    radius.push_back(cells[0].positive());
    fraction.push_back(cells[1].non_negative());
  }
  if (radius.empty()) rows_field.fail("the table has no rows", "add rows [radius, fraction]");
  double total = 0.0;
  for (const double x : fraction) total += x;
  if (!(total > 0.0)) rows_field.fail("all fractions are 0", "give at least one positive fraction");
  return RadiusDistribution::table(std::move(radius), std::move(fraction), basis == "volume");
}

/// E[R^3] of a distribution, estimated from draws with a fixed seed (exact for monodisperse).
double mean_cube(const RadiusDistribution& d) {
  RadiusSampler draw(d);
  std::mt19937_64 rng(12345);
  double s = 0.0;
  constexpr int kDraws = 20000;
  for (int i = 0; i < kDraws; ++i) {
    const double r = draw(rng);
    s += r * r * r;
  }
  return s / kDraws;
}

/// Refuses `count` particles (expected or given) at `f` when over the limit.
void check_particle_count(const YamlField& f, double count) {
  const std::string problem = particle_count_problem(count, available_memory_bytes());
  if (!problem.empty()) f.fail(problem, "use fewer particles: larger radii, a smaller container or a lower count");
}

void read_packing(GenerateSpec& spec, const YamlField& field) {
  const YamlMap m = field.map({"porosity", "count", "overlap_tolerance", "max_iterations", "on_failure"});
  spec.relaxation_where = field.where();
  const auto [kind, f] = m.one_of({"porosity", "count"});
  if (kind == "porosity") {
    const double phi = f.number();
    if (!(phi > 0.0 && phi < 1.0)) f.fail(fmt::format("must be in (0, 1), got {}", phi), "give the pore volume fraction, e.g. 0.4");
    spec.target.porosity = phi;
    const double expected = (1.0 - phi) * spec.container->volume() / (4.0 / 3.0 * std::numbers::pi * mean_cube(spec.radii));
    check_particle_count(f, expected);
    if (expected < 0.5) f.fail("the container holds less than one particle at this porosity", "use smaller radii or a larger container");
  } else {
    // A whole number in any notation (3e9 too), checked before anything is allocated.
    const double n = f.number();
    if (!(n >= 1.0 && n == std::floor(n))) {
      f.fail(fmt::format("must be a whole number between 1 and {:.0e}, got {}", kMaxGenerateParticles, f.text()),
             "give the number of particles");
    }
    check_particle_count(f, n);
    spec.target.count = static_cast<std::int64_t>(n);
  }
  if (const auto t = m.find("overlap_tolerance")) {
    spec.relaxation.overlap_tolerance = t->positive();
    if (spec.relaxation.overlap_tolerance >= 1.0) t->fail("must be below 1 (it is overlap / smaller radius)", "use e.g. 0.01");
  }
  if (const auto it = m.find("max_iterations")) {
    spec.relaxation.max_iterations = it->integer();
    if (spec.relaxation.max_iterations < 0) it->fail("must not be negative", "use e.g. 20000");
  }
  if (const auto of = m.find("on_failure")) {
    const std::string v = of->text();
    if (v != "error" && v != "warn") of->fail("expected 'error' or 'warn', got '" + v + "'");
    spec.fail_if_not_relaxed = v == "error";
  }
}

bool valid_name(const std::string& name) {
  return !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '-' || c == '.';
  });
}

void read_bonds(GenerateSpec& spec, const YamlField& field) {
  const YamlMap m = field.map({"contact_radius_multiplier", "max_gap", "radius_multiplier", "materials"});
  spec.bonds = true;
  if (const auto e = m.find("contact_radius_multiplier")) {
    const double eta = e->number();
    if (!(eta >= 1.0)) e->fail(fmt::format("must be at least 1, got {}", eta), "eta_r = 1 bonds touching particles; 1.1-1.2 is typical");
    spec.bond_criterion.contact_radius_multiplier = eta;
  }
  if (const auto g = m.find("max_gap")) spec.bond_criterion.max_gap = g->non_negative();
  if (!spec.bond_criterion.contact_radius_multiplier && !spec.bond_criterion.max_gap) {
    field.fail("needs contact_radius_multiplier and/or max_gap", "add e.g. 'contact_radius_multiplier: 1.15'");
  }
  if (const auto r = m.find("radius_multiplier")) spec.bond_radius_multiplier = r->positive();
  if (const auto mats = m.find("materials")) {
    double total = 0.0;
    for (const auto& [name, value] : mats->entries()) {
      if (!valid_name(name)) value.fail("a material name may hold only letters, digits, '_', '-' and '.'", "rename it");
      const double f = value.number();
      if (!(f >= 0.0 && f <= 1.0)) value.fail(fmt::format("a fraction must be in [0, 1], got {}", f));
      spec.bond_materials.push_back({name, f});
      total += f;
    }
    if (spec.bond_materials.empty()) mats->fail("no materials given", "write 'name: fraction' lines, e.g. 'soft: 0.4'");
    if (std::abs(total - 1.0) > 1e-6) mats->fail(fmt::format("the fractions must sum to 1, they sum to {}", total), "fix the fractions");
  } else {
    spec.bond_materials.push_back({"bond", 1.0});
  }
}

void read_output(GenerateSpec& spec, const YamlField& field) {
  const YamlMap m = field.map({"vtk", "scenario", "binary"});
  if (const auto v = m.find("vtk")) spec.write_vtk = v->boolean();
  if (const auto b = m.find("binary")) spec.write_binary = b->boolean();
  if (const auto s = m.find("scenario")) spec.write_scenario = s->boolean();
}

}  // namespace

double available_memory_bytes() {
  double bytes = meminfo_bytes("MemAvailable:");
  // A ulimit -v (or a batch system's) caps the address space below what the machine has free.
  rlimit limit{};
  if (::getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY) {
    bytes = std::min(bytes, static_cast<double>(limit.rlim_cur));
  }
  return bytes;
}

std::string particle_count_problem(double count, double available_bytes) {
  if (count > kMaxGenerateParticles) {
    return fmt::format("this needs about {:.3g} particles, more than the limit of {:.0e} particles for generate",
                       count, kMaxGenerateParticles);
  }
  if (count * kGenerateBytesPerParticle > available_bytes) {
    return fmt::format("this needs about {:.3g} particles, more than the {:.3g} that fit in the memory available "
                       "now ({:.3g} GB at about {:.0f} bytes per particle)",
                       count, available_bytes / kGenerateBytesPerParticle, available_bytes / 1e9,
                       kGenerateBytesPerParticle);
  }
  return {};
}

GenerateSpec load_generate_spec(const std::string& path) {
  if (!std::filesystem::is_regular_file(path)) {
    throw InputError(path, "spec file not found", "check the path; a relative path starts at the current directory");
  }
  const YamlField root = YamlField::load_file(path);
  if (!root.is_map()) root.fail("a spec file is a map of sections", "see docs/generate.md for an example");
  const YamlMap m = root.map({"description", "seed", "container", "radii", "packing", "bonds", "output"});
  GenerateSpec spec;
  spec.path = path;
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  if (const auto d = m.find("description")) spec.description = d->text();
  if (const auto s = m.find("seed")) {
    const std::int64_t seed = s->integer();
    if (seed < 0) s->fail("must not be negative", "use an integer >= 0");
    spec.seed = static_cast<std::uint64_t>(seed);
  }
  spec.container = read_container(m.require("container", "add 'container:' with one of box, cylinder, sphere, stl"), folder);
  const YamlField radii_field = m.require("radii", "add 'radii:' with one of monodisperse, uniform, normal, lognormal, table");
  spec.radii = read_radii(radii_field);
  const Vec3 size = spec.container->bounds().size();
  const double smallest_side = std::min({size.x, size.y, size.z});
  if (2.0 * spec.radii.largest() > smallest_side) {
    radii_field.fail(fmt::format("the largest radius {} m does not fit in the container (narrowest extent {} m)",
                                 spec.radii.largest(), smallest_side),
                     "use smaller radii or a larger container");
  }
  read_packing(spec, m.require("packing", "add 'packing:' with porosity or count"));
  if (const auto b = m.find("bonds")) read_bonds(spec, *b);
  if (const auto o = m.find("output")) read_output(spec, *o);
  return spec;
}

}  // namespace bpm
