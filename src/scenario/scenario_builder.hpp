#pragma once
/// Internal to the scenario reader (not a public header): the state the section readers share
/// while one file is read, and the readers of the two structure sections, `particles` and `bonds`
/// (scenario_structure.cpp). The other sections are read in scenario.cpp.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "scenario/scenario.hpp"
#include "io/yaml_field.hpp"

namespace bpm::scenario_detail {

struct ScenarioBuilder {
  Scenario& scenario;
  std::filesystem::path folder;  ///< the YAML file's folder; CSV paths are relative to it
  std::unordered_map<std::int64_t, std::int32_t> index_of_id;  ///< user id -> particle index
  /// The `contact` block of each particle material, where given (needed once contacts are used).
  std::vector<std::optional<ContactMaterial>> contact_materials;
};

/// Index of `name` in `names`, or nullopt.
std::optional<std::int32_t> find_name(const std::vector<std::string>& names, const std::string& name);
/// "a, b, c" for error messages.
std::string list_names(const std::vector<std::string>& names);

/// The `particles` section: exactly one of file, list, row; plus the default `material`.
void read_particles(ScenarioBuilder& builder, const YamlField& section);
/// The `bonds` section: exactly one of file, list, auto; plus the default `material`.
void read_bonds(ScenarioBuilder& builder, const YamlField& section);

// Contact sections (scenario_contacts.cpp).
/// A particle material's `contact` block.
ContactMaterial read_contact_material(const std::string& name, const YamlField& field);
/// `contacts`: particle-particle contacts, what bonds do to them, pair rules.
void read_contacts(ScenarioBuilder& builder, const YamlField& section);
/// `walls`: a list of planes, rectangles, discs and cylinders, moving or servo-controlled.
void read_walls(ScenarioBuilder& builder, const YamlField& section);
/// `compression`: the uniaxial compression test.
void read_compression(ScenarioBuilder& builder, const YamlField& section);

}  // namespace bpm::scenario_detail
