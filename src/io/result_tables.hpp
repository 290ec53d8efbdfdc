#pragma once
/// The result tables of a run besides the final state and the probes: broken bonds, wall forces
/// and displacements, and the compression test's curve and summary (formats in docs/scenario.md).
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "compress/uniaxial_compression.hpp"
#include "model/model.hpp"

namespace bpm {

/// bond_breaks.csv: one row per broken bond, in the order they broke: the pair (user ids), time
/// (update number times dt), mode and contact point. Its header, and the rows of breaks
/// [from, breaks.size()) (the run streams them).
std::string bond_breaks_header();
std::string bond_breaks_rows(const Model& model, double dt, std::size_t from);

/// bonds/bonds_NNNNNN.csv (`output.bond_csv`): every bond at one output time, in the order of the
/// input (bond: its input row), with the pair (user ids), intact (1 or 0), the axial force
/// (force . axis, > 0 in tension, N) and the elastic force and moment on alpha at the contact point
/// (global frame, BondStore::force and ::moment; N, N m). Numbers in the shortest exact form.
std::string bond_state_csv(const Model& model);

/// One row of walls.csv: time, then per wall its displacement since t = 0 and the force the
/// particles exert on it; the header first when `header`.
std::string walls_row(const std::vector<Wall>& walls, double t, bool header);

/// force_displacement.csv of a compression test: its header, and one row for a point of the curve
/// (stress = force / area, area in m^2).
std::string force_displacement_header();
std::string force_displacement_row(const CompressionPoint& p, double area);

/// The `compression` block of summary.json.
nlohmann::json compression_json(const CompressionResult& r);
/// The body's E and nu (compress/strain_gauge.hpp): null where the gauge measured none.
nlohmann::json body_json(const BodyModuli& body, std::size_t gauge_particles);

}  // namespace bpm
