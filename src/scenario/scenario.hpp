#pragma once
/// A scenario file (YAML) turned into a ready-to-run model: materials, particles, bonds, damping,
/// boundary conditions, loads, time step, stop criteria and outputs. The schema is documented in
/// docs/scenario.md. Every problem in the file becomes a bpm::InputError naming the file, the key
/// path (e.g. `bond_materials.beam.poisson_ratio`) or CSV line, and how to fix it.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "bonds/bond_material.hpp"
#include "compress/uniaxial_compression.hpp"
#include "model/model.hpp"
#include "dem/simulation.hpp"

namespace bpm {

struct OutputSettings {
  /// Steps between two outputs (VTK frame and probe row). Resolved from `every_steps` or
  /// `every_time`; 0 writes only the initial and the final state.
  std::int64_t every_steps = 0;
  double every_time = 0.0;  ///< s, as given (0 if not given); already converted into every_steps
  bool vtk = true;          ///< write VTK frames (.vtp) and their collection (.pvd)
  bool bond_csv = false;    ///< write bonds/bonds_NNNNNN.csv (io/result_tables.hpp) at each output
  /// Steps between two checkpoints (scenario/checkpoint.hpp), from `checkpoint_every: {steps: N}` or
  /// `{time: T}` (rounded to whole steps); 0: none (Ctrl-C, SIGTERM and divergence still write one).
  std::int64_t checkpoint_every_steps = 0;
};

/// A named set of particles whose mean displacement and velocity and summed force are recorded.
struct Probe {
  std::string name;
  std::vector<std::int32_t> particles;  ///< indices into the particle store
};

struct Scenario {
  std::string path;         ///< the YAML file it was read from
  std::string description;  ///< free text from the file, may be empty
  Model model;              ///< finalised, ready for Simulation
  double time_step = 0.0;        ///< s, the step the run uses
  double time_step_limit = 0.0;  ///< s, critical_time_step(model).critical (infinity if undefined)
  double safety_factor = 0.8;    ///< time_step / limit when time_step is `auto`
  bool time_step_given = false;  ///< integrator.time_step is the user's number, not `auto`
  std::uint64_t seed = 1;        ///< of the bond strengths' random draws (`seed`, default 1)
  StopCriteria stop;
  OutputSettings output;
  std::vector<Probe> probes;
  /// Material names and data; particle and bond `material` fields index these vectors.
  std::vector<std::string> particle_material_names, bond_material_names;
  std::vector<double> particle_densities;  ///< kg/m^3
  std::vector<BondMaterial> bond_materials;
  /// The uniaxial compression test, when the file has a `compression` section: `bpmkit run` then
  /// places the platens and runs the test instead of running to `stop`.
  std::optional<UniaxialCompression> compression;
};

struct ScenarioLoadOptions {
  /// Derive the stability limit (and check integrator.time_step against it). A command that does
  /// not integrate in time (the STE, the DSMs) skips it: on an 8.1e6-bond model it was ~9 s of a
  /// ~14 s load. Skipped, time_step is the user's value or 0 (auto: a compression derives its own)
  /// and time_step_limit is infinity.
  bool time_step = true;
};

/// Reads, validates and builds a scenario. Throws InputError for anything wrong in the file or in
/// the CSV files it references (whose paths are relative to the YAML file's folder).
Scenario load_scenario(const std::string& path, const ScenarioLoadOptions& options = {});
/// The same from YAML (or JSON) text, as if it were the file `path`: messages name it, and the CSV
/// files it references are found relative to its folder (the Python module loads a dict this way).
Scenario load_scenario_text(const std::string& text, const std::string& path, const ScenarioLoadOptions& options = {});

}  // namespace bpm
