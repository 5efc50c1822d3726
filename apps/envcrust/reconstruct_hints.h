// The hints of `envcrust reconstruct` for scans: what to try when the result of a point file
// or a mesh has handles or cross-caps the cuts left, loops that may be unsampled stripes, or
// more pieces than its samples.
#pragma once

#include "surface_input.h"

#include "envcrust/analysis.h"
#include "envcrust/pipeline.h"

#include <cstddef>
#include <string>
#include <vector>

namespace envcrust::cli {

/// What to try when a scan (a point file or a mesh, not a built-in surface) comes out with
/// cross-caps or handles the cuts did not remove (the usual cause is a part thinner than 2 rho
/// or sampled too sparsely, which the cuts repair when the scanned surface is known to be
/// orientable and locally a disc; a mesh that is itself non-orientable gets no such hint), or
/// with detected loops narrow enough to be unsampled stripes. `unresolved_curves`: the input
/// curves below the reconstruction's resolution (analysis::BoundaryCheck), left out of the
/// latter. A point file whose result has more pieces than its samples form within 2 rho
/// (`envelope`: the run's) gets the advice of the direct Power Crust for a closed surface.
/// None for other methods or extractions than the envelope's medial sheet.
std::vector<std::string> scan_hints(const LoadedSurface& loaded, const pipeline::ReconstructOptions& options,
                                    const analysis::AnalysisReport& report,
                                    const std::vector<std::size_t>& unresolved_curves,
                                    const envelope::EnvelopeSamples& envelope);

}  // namespace envcrust::cli
