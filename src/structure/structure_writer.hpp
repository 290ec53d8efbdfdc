#pragma once
/// Writes a generated structure into a folder, each file atomically (io/atomic_file.hpp):
///
/// | file            | content                                                                   |
/// | --------------- | ------------------------------------------------------------------------- |
/// | particles.csv   | `id,x,y,z,radius`, ids 0..N-1, m (the format `bpmkit run` reads)          |
/// | bonds.csv       | `i,j[,radius],material` (particle ids; radius only if a multiplier is set) |
/// | structure.vtp   | (if vtk) VTK PolyData (binary, zlib: io/vtk_polydata.hpp): particles as
/// points (id, radius), bonds as lines (material; field data bond_material_names) | | summary.json
/// | counts, porosity, coordination number, largest overlap, timings, seed      | | scenario.yaml
/// | (if scenario) a `bpmkit run` stub referencing the CSVs, placeholder constants |
///
/// Numbers are written with the shortest text that reads back to the same double. The files are
/// written as one set: into the subfolder generate.tmp/ first, then renamed into place together
/// (io/output_folder.hpp, StagedFiles).
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/output_folder.hpp"
#include "io/structure_table.hpp"
#include "structure/generate.hpp"
#include "structure/generate_spec.hpp"

namespace bpm {

/// The staging subfolder of the output folder (declared in structure_outputs).
inline constexpr const char* kStructureStaging = "generate.tmp";

/// The generated particles and bonds as tables, written as particles.csv and bonds.csv and as their
/// binary twins (io/structure_table.hpp): the same rows, bit for bit.
ParticleTable particle_table(const Packing& packing);
BondTable bond_table(const GenerateSpec& spec, const GeneratedStructure& g);
std::string structure_vtp(const GenerateSpec& spec, const GeneratedStructure& g);
nlohmann::json structure_summary(const GenerateSpec& spec, const GeneratedStructure& g);
std::string scenario_stub(const GenerateSpec& spec, const GeneratedStructure& g);

/// Writes the files above into `out_dir` (claimed first: io/output_folder.hpp); returns their
/// paths.
std::vector<std::string> write_structure(const GenerateSpec& spec, const GeneratedStructure& g,
                                         const std::string& out_dir);

/// The names of the files above that `spec` writes, for OutputFolder.
std::vector<std::string> structure_outputs(const GenerateSpec& spec);

/// Writes the files above into a folder claimed for structure_outputs(spec); returns their paths
/// and the summary (the caller ends the run with it: OutputFolder::run).
std::pair<std::vector<std::string>, nlohmann::json> write_structure(const GenerateSpec& spec,
                                                                    const GeneratedStructure& g,
                                                                    const OutputFolder& folder);

}  // namespace bpm
