#pragma once
/// The input of `bpmkit generate`: a YAML file that says what structure to build (container,
/// radius distribution, porosity or count, relaxation tolerance, bonding rule and bond materials)
/// and what to write. The schema is in docs/generate.md. Every problem is an InputError that names
/// the file, the line, the key path and the fix (io/yaml_field.hpp), as for scenario files.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "structure/bonding.hpp"
#include "structure/container.hpp"
#include "structure/packing.hpp"
#include "structure/radius_distribution.hpp"

namespace bpm {

struct BondMaterialShare {
  std::string name;  ///< the bond material's name in the scenario (letters, digits, _ - .)
  double fraction = 1.0;  ///< probability of a bond getting this material
};

struct GenerateSpec {
  std::string path;         ///< the spec file
  std::string description;  ///< free text, copied into summary.json
  std::uint64_t seed = 1;   ///< std::mt19937_64 seed for radii, positions and bond materials
  std::shared_ptr<const Container> container;
  RadiusDistribution radii;
  PackingTarget target;
  RelaxationSettings relaxation;
  bool fail_if_not_relaxed = true;  ///< packing.on_failure: error (true) or warn (false)
  std::string relaxation_where;     ///< "FILE:LINE: packing", for the not-relaxed message
  bool bonds = false;               ///< the spec has a `bonds` section
  BondCriterion bond_criterion;
  std::optional<double> bond_radius_multiplier;  ///< write r_b = multiplier * min(R_i, R_j)
  std::vector<BondMaterialShare> bond_materials;  ///< at least one when bonds is true
  bool write_vtk = true;
  bool write_scenario = true;
  bool write_binary = true;  ///< particles.bpk and bonds.bpk beside the CSV files
};

/// Reads and validates a spec file (relative paths inside it start at its folder).
GenerateSpec load_generate_spec(const std::string& path);

/// Size limits of generate, checked on the particle count (given, or expected from the porosity)
/// before anything is allocated: at most 1e8 particles, and no more than the memory available now
/// holds at the peak measured per particle (packing, relaxation, bonds and the files' text: 0.94 kB
/// for 4e5 densely packed particles). Beyond either, generate used to end in std::bad_alloc.
inline constexpr double kMaxGenerateParticles = 1e8;
inline constexpr double kGenerateBytesPerParticle = 1000.0;

/// MemAvailable of /proc/meminfo, or the address-space limit (ulimit -v) if lower; infinity if
/// neither is known.
double available_memory_bytes();

/// Why `count` particles are too many (naming the limit), or "" if they are not.
std::string particle_count_problem(double count, double available_bytes);

}  // namespace bpm
