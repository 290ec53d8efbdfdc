// `bpmkit convert INPUT --to FORMAT --out DIR`: a bonded structure from one code's format into
// another's (io/structure_exchange.hpp): bpmkit (particles.csv + bonds.csv), lammps (a data file),
// yade (spheres.txt + bonds.txt), musen (musen.txt: MUSEN's text import/export format). It prints,
// and records in summary.json, what the target format cannot hold. `bpmkit export lammps SCENARIO
// --out DIR`: a scenario with its bond stiffnesses as a data file and input deck for LAMMPS's
// bond_style bpm/rotational (scenario/lammps_export.hpp).
#include <fmt/core.h>

#include <filesystem>
#include <memory>
#include <string>

#include "cli/commands.hpp"
#include "core/error.hpp"
#include "io/lammps_data.hpp"
#include "io/log.hpp"
#include "io/musen_text.hpp"
#include "io/output_folder.hpp"
#include "scenario/lammps_export.hpp"
#include "scenario/scenario.hpp"

namespace bpm::cli {
namespace {

namespace fs = std::filesystem;

struct ConvertOptions {
  std::string input;
  std::string from;  ///< "" = guessed from the input
  std::string to;
  std::string out_dir = "out/convert";
  bool overwrite = false;
  double density = 0.0;
  std::string lammps_style = "bpm/sphere";
};

/// The input's format: a file is a MUSEN text file if its first line starts like a MUSEN object
/// ("0 ID 1 TYPE"), else a LAMMPS data file (its first line is a free title, so it is checked
/// second); a folder holds particles.csv (bpmkit) or spheres.txt (yade).
std::string guess_format(const std::string& input) {
  if (fs::is_regular_file(input)) return is_musen_text(input) ? "musen" : "lammps";
  if (fs::exists(fs::path(input) / "particles.csv") ||
      fs::exists(fs::path(input) / "particles.bpk"))
    return "bpmkit";
  if (fs::exists(fs::path(input) / "spheres.txt")) return "yade";
  throw InputError(
      input,
      "not a file (LAMMPS data, MUSEN text), nor a folder with particles.csv (bpmkit) or "
      "spheres.txt (yade)",
      "give --from bpmkit|lammps|yade|musen and the right path");
}

ExchangeStructure read_structure(const std::string& format, const std::string& input,
                                 std::vector<std::string>& dropped) {
  if (format == "bpmkit") return read_bpmkit_structure(input);
  if (format == "yade") return read_yade_structure(input);
  if (format == "musen") return read_musen_structure(input, &dropped);
  return read_lammps_data(input, &dropped);
}

ExchangeFiles structure_files(const ConvertOptions& o, const ExchangeStructure& s) {
  if (o.to == "bpmkit") return bpmkit_structure_files(s);
  if (o.to == "yade") return yade_structure_files(s);
  if (o.to == "musen") return musen_structure_files(s);
  LammpsDataOptions options;
  options.style = o.lammps_style == "bpm/sphere" ? LammpsAtomStyle::bpm_sphere
                                                 : LammpsAtomStyle::hybrid_sphere_bond;
  options.density = o.density;
  ExchangeFiles out;
  out.files.emplace_back("structure.data", lammps_data_text(s, options));
  return out;
}

std::vector<std::string> output_names(const std::string& to) {
  if (to == "bpmkit") return {"particles.csv", "bonds.csv"};
  if (to == "yade") return {"spheres.txt", "bonds.txt"};
  if (to == "musen") return {"musen.txt"};
  return {"structure.data"};
}

void convert(const ConvertOptions& o) {
  const std::string from = o.from.empty() ? guess_format(o.input) : o.from;
  OutputFolder folder(o.out_dir, "convert", output_names(o.to), o.overwrite);
  folder.run([&] {
    std::vector<std::string> dropped;
    const ExchangeStructure s = read_structure(from, o.input, dropped);
    ExchangeFiles out = structure_files(o, s);
    dropped.insert(dropped.end(), out.dropped.begin(), out.dropped.end());
    nlohmann::json files = nlohmann::json::array();
    for (const auto& [name, content] : out.files) files.push_back(folder.write(name, content));
    fmt::print("{} particles, {} bonds: {} ({}) -> {} in {}\n", s.particles.id.size(),
               s.bonds.i.size(), o.input, from, o.to, folder.dir());
    for (const std::string& d : dropped) log::warn("not carried over: {}\n", d);
    return nlohmann::json{{"from", from},
                          {"to", o.to},
                          {"input", o.input},
                          {"particles", s.particles.id.size()},
                          {"bonds", s.bonds.i.size()},
                          {"dropped", dropped},
                          {"files", files}};
  });
}

struct ExportOptions {
  std::string scenario;
  std::string out_dir = "out/export";
  bool overwrite = false;
};

void export_to_lammps(const ExportOptions& o) {
  Scenario scenario = load_scenario(o.scenario);
  OutputFolder folder(o.out_dir, "export", {"structure.data", "in.bpmkit"}, o.overwrite);
  folder.run([&] {
    const LammpsExport e = export_lammps(scenario);
    const std::string data = folder.write("structure.data", e.data);
    const std::string deck = folder.write("in.bpmkit", e.deck);
    fmt::print("{} particles, {} bonds in {} bond types (bond_style bpm/rotational): {}, {}\n",
               scenario.model.particles.size(), scenario.model.bonds.size(), e.bond_types, data,
               deck);
    for (const std::string& note : e.notes) log::warn("note: {}\n", note);
    return nlohmann::json{{"scenario", o.scenario},
                          {"particles", scenario.model.particles.size()},
                          {"bonds", scenario.model.bonds.size()},
                          {"bond_types", e.bond_types},
                          {"notes", e.notes},
                          {"files", {data, deck}}};
  });
}

}  // namespace

void add_convert_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "convert",
      "a bonded structure between formats: bpmkit (particles.csv, bonds.csv), lammps (data file), "
      "yade (spheres.txt, bonds.txt), musen (MUSEN's text import/export file); says what the "
      "target cannot hold (docs/formats.md)");
  auto o = std::make_shared<ConvertOptions>();
  cmd->add_option("input", o->input,
                  "a LAMMPS data file or MUSEN text file, or a folder with particles.csv or "
                  "spheres.txt")
      ->required();
  cmd->add_option("--from", o->from, "input format (default: guessed from INPUT)")
      ->check(CLI::IsMember({"bpmkit", "lammps", "yade", "musen"}));
  cmd->add_option("--to", o->to, "output format")
      ->required()
      ->check(CLI::IsMember({"bpmkit", "lammps", "yade", "musen"}));
  cmd->add_option("--density", o->density,
                  "kg/m^3 of every particle, for LAMMPS when the input has no densities");
  cmd->add_option("--lammps-style", o->lammps_style, "atom style of the LAMMPS data file written")
      ->check(CLI::IsMember({"bpm/sphere", "hybrid sphere bond"}))
      ->capture_default_str();
  add_output_options(cmd, o->out_dir, o->overwrite);
  cmd->callback([o] { convert(*o); });
}

void add_export_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("export", "a scenario as another code's input (docs/formats.md)");
  cmd->require_subcommand(1);
  auto* lammps = cmd->add_subcommand("lammps",
                                     "data file and input deck for LAMMPS's bond_style "
                                     "bpm/rotational (K_r = k_n, K_s = k_s, K_t = k_tor, "
                                     "K_b = k_ben per bond)");
  auto o = std::make_shared<ExportOptions>();
  lammps->add_option("scenario", o->scenario, "scenario YAML file")->required();
  add_output_options(lammps, o->out_dir, o->overwrite);
  lammps->callback([o] { export_to_lammps(*o); });
}

}  // namespace bpm::cli
