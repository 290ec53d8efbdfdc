// `bpmkit generate SPEC.yaml --out DIR`: builds a bonded-particle structure (random packing in a
// container, force-biased relaxation, bonding; Jarolin 2020 §2) from a spec file
// (docs/generate.md) and writes particles.csv and bonds.csv (and their binary twins, .bpk) for
// `bpmkit run`, a VTK file, a summary and a scenario stub.
#include <fmt/core.h>

#include <chrono>
#include <memory>
#include <string>

#include "cli/commands.hpp"
#include "io/log.hpp"
#include "io/output_folder.hpp"
#include "structure/generate.hpp"
#include "structure/generate_spec.hpp"
#include "structure/structure_writer.hpp"

namespace bpm::cli {
namespace {

struct GenerateOptions {
  std::string spec;
  std::string out_dir = "out/generate";
  bool overwrite = false;
};

/// The settings behind the numbers (--verbose): packing target, relaxation, bonding rule.
void log_settings(const GenerateSpec& spec) {
  const std::string target = spec.target.count > 0 ? fmt::format("{} particles", spec.target.count)
                                                   : fmt::format("porosity {}", spec.target.porosity);
  log::detail("settings: {}; relaxation to a largest overlap of {} R in at most {} iterations (on failure: {})\n",
              target, spec.relaxation.overlap_tolerance, spec.relaxation.max_iterations,
              spec.fail_if_not_relaxed ? "error" : "warn");
  if (!spec.bonds) return log::detail("settings: no bonds\n");
  const BondCriterion& c = spec.bond_criterion;
  std::string materials;
  for (const BondMaterialShare& m : spec.bond_materials) {
    materials += fmt::format("{}{} {:.3g} %", materials.empty() ? "" : ", ", m.name, 100.0 * m.fraction);
  }
  log::detail("settings: bonds {}{}{}; materials {}\n",
              c.contact_radius_multiplier ? fmt::format("where the centre distance <= eta_r (R_i + R_j), eta_r = {}", *c.contact_radius_multiplier)
                                          : "",
              c.max_gap ? fmt::format("{}within a gap of {} m", c.contact_radius_multiplier ? ", " : "", *c.max_gap) : "",
              spec.bond_radius_multiplier ? fmt::format(", r_b = {} min(R_i, R_j)", *spec.bond_radius_multiplier) : "",
              materials);
}

/// Generates and writes the structure; returns the summary.
nlohmann::json generate_into(const GenerateSpec& spec, const OutputFolder& folder) {
  const GeneratedStructure g = generate_structure(spec);
  const PackingStats& s = g.stats;
  if (!g.relaxation.converged) {
    log::warn("warning: the relaxation stopped after {} iterations with a largest overlap of {:.4g} of the "
              "smaller radius, above the tolerance {} (on_failure: warn)\n",
              g.relaxation.iterations, g.relaxation.max_overlap, spec.relaxation.overlap_tolerance);
  }
  fmt::print("{} particles, porosity {:.4f}, largest overlap {:.3g} R after {} relaxation iterations\n", s.particles,
             s.porosity, s.max_overlap, g.relaxation.iterations);
  if (spec.bonds) {
    fmt::print("{} bonds ({:.2f} per particle), coordination number {:.2f} at eta_r = {}\n", g.bonds.size(),
               s.particles > 0 ? static_cast<double>(g.bonds.size()) / static_cast<double>(s.particles) : 0.0,
               s.coordination_number, s.contact_radius_multiplier);
  }
  const auto t0 = std::chrono::steady_clock::now();
  const auto [files, summary] = write_structure(spec, g, folder);
  const double write_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  log::info("wall time: insert {:.2f} s, relax {:.2f} s, bond {:.2f} s, write {:.2f} s ({} threads)\n",
            g.insert_seconds, g.relax_seconds, g.bond_seconds, write_seconds, g.threads);
  log::info("wrote {} files to {}\n", files.size(), folder.dir());
  return summary;
}

void generate(const GenerateOptions& options) {
  const GenerateSpec spec = load_generate_spec(options.spec);
  OutputFolder folder(options.out_dir, "generate", structure_outputs(spec), options.overwrite);
  log::info("{}: {}, {}, seed {}\n", options.spec, spec.container->describe(), spec.radii.describe(), spec.seed);
  log_settings(spec);
  folder.run([&] { return generate_into(spec, folder); });
}

}  // namespace

void add_generate_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("generate", "generate a bonded packing from a spec file (YAML; see docs/generate.md)");
  auto options = std::make_shared<GenerateOptions>();
  cmd->add_option("spec", options->spec, "spec file (YAML)")->required();
  add_output_options(cmd, options->out_dir, options->overwrite);
  cmd->callback([options] { generate(*options); });
}

}  // namespace bpm::cli
