// The analyzer's findings in plain words, for the HTML report: what the pieces, the Euler
// characteristic, the boundary loops and orientability mean for this result.
#pragma once

#include "envcrust/analysis.h"

#include <string>
#include <vector>

namespace envcrust::cli::html {

/// The usual name of a connected surface from its numbers: "a disc", "an annulus (a tube open
/// at both ends)", "a Moebius band", "a torus", "a surface of genus 2 with 3 boundary loops".
/// `genus` is the number of handles when orientable, of cross-caps when not; empty when the
/// component is not a manifold (then "a set of triangles that is not a surface").
std::string surface_name(bool is_orientable, std::optional<long> genus, int boundary_loops);

/// Paragraphs for `report`, one per subject: the pieces, manifoldness, the shape with χ, the
/// boundary loops (knots, linking), orientability, self-intersections and distances, each
/// saying what it means here (a Moebius band: "χ = 0 ... one side only ...").
std::vector<std::string> topology_in_words(const analysis::AnalysisReport& report);

}  // namespace envcrust::cli::html
