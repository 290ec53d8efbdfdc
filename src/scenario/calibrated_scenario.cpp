#include "scenario/calibrated_scenario.hpp"

#include <yaml-cpp/yaml.h>

#include <filesystem>

#include "core/error.hpp"

namespace bpm {
namespace {

namespace fs = std::filesystem;

/// A path of the scenario (relative to its folder) as seen from `folder`.
std::string moved_path(const std::string& given, const fs::path& scenario_folder,
                       const fs::path& folder) {
  const fs::path p = given;
  const fs::path target =
      fs::absolute(p.is_absolute() ? p : scenario_folder / p).lexically_normal();
  const fs::path relative = target.lexically_relative(fs::absolute(folder).lexically_normal());
  return relative.empty() ? target.string() : relative.string();
}

/// A strength as the scenario writes it (scenario.cpp): a number, or its distribution's map.
YAML::Node strength_node(const StrengthDistribution& d) {
  YAML::Node node;
  switch (d.kind) {
    case StrengthDistribution::Kind::constant:
      node = d.value;
      break;
    case StrengthDistribution::Kind::normal:
      node["distribution"] = "normal";
      node["mean"] = d.value;
      node["std_dev"] = d.spread;
      break;
    case StrengthDistribution::Kind::weibull:
      node["distribution"] = "weibull";
      node["scale"] = d.value;
      node["shape"] = d.spread;
      break;
  }
  return node;
}

}  // namespace

std::string calibrated_scenario_yaml(const std::string& scenario_path,
                                     const std::vector<BondMaterial>& materials,
                                     bool with_shear_ratio, bool with_strengths,
                                     const std::string& folder,
                                     const std::vector<std::string>& header) {
  YAML::Node root;
  try {
    root = YAML::LoadFile(scenario_path);
  } catch (const YAML::Exception& e) {
    throw InputError(
        scenario_path,
        std::string("could not be read again to write the calibrated scenario: ") + e.what(),
        "keep the scenario file in place until the calibration ends");
  }
  YAML::Node bond_materials = root["bond_materials"];
  for (const BondMaterial& m : materials) {
    YAML::Node node = bond_materials[m.name];
    node["youngs_modulus"] = m.youngs_modulus;
    if (with_strengths) {
      node["tensile_strength"] = strength_node(m.tensile_strength);
      node["shear_strength"] = strength_node(m.shear_strength);
    }
    if (!with_shear_ratio) continue;
    if (m.model == "pbm" && m.kappa) node["kappa"] = *m.kappa;
    if (m.model == "obermayr" && m.shear_coefficient)
      node["shear_coefficient"] = *m.shear_coefficient;
  }
  const fs::path scenario_folder = fs::path(scenario_path).parent_path();
  for (const char* section : {"particles", "bonds"}) {
    YAML::Node node = root[section];
    if (node.IsMap() && node["file"])
      node["file"] = moved_path(node["file"].as<std::string>(), scenario_folder, folder);
  }
  YAML::Emitter out;
  for (const std::string& line : header) out << YAML::Comment(line) << YAML::Newline;
  out << root;
  return std::string(out.c_str()) + "\n";
}

}  // namespace bpm
