// `bpmkit generate SPEC.yaml --out DIR`: builds a bonded-particle structure (random packing in a
// container, force-biased relaxation, bonding; Jarolin 2020 §2) from a spec file
// (docs/generate.md) and writes particles.csv and bonds.csv for `bpmkit run`, a VTK file, a
// summary and a scenario stub.
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
