// power_crust: the stages in order, with timings, progress and the DT freed before the RT.
#include "stages.h"

#include "envcrust/errors.h"
#include "envcrust/mesh.h"

#include <algorithm>
#include <limits>

#include <tbb/task_arena.h>


namespace envcrust::powercrust {
namespace {

class StageClock {
 public:
  explicit StageClock(const Progress& progress) : progress_(progress) {}

  // Ends the running stage: returns its seconds, reports it done and checks cancellation.
  double lap(std::string_view stage) {
    const double seconds = watch_.lap();
    progress_.report(stage, 1.0);
    if (progress_.is_cancelled()) throw Error("power crust cancelled");
    return seconds;
  }
  void begin(std::string_view stage) { progress_.report(stage, 0.0); }

 private:
  const Progress& progress_;
  Stopwatch watch_;
};

void count_labels(const std::vector<Pole>& poles, PowerCrustStats& stats) {
  for (const Pole& p : poles) {
    stats.inner_poles += p.label == PoleLabel::In;
    stats.outer_poles += p.label == PoleLabel::Out;
    stats.hidden_poles += p.is_hidden;
  }
}

// Poles below `ratio` local spacings of the samples that chose them (the smallest such
// spacing): left out of the power diagram (PowerCrustOptions::min_pole_radius_rel_spacing).
std::vector<bool> small_poles(const PowerCrustResult& result, const std::vector<double>& spacing, double ratio) {
  if (ratio <= 0) return {};
  std::vector<double> scale(result.poles.size(), std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < result.samples.size(); ++i)
    for (Index p : {result.sample_poles[i].outer, result.sample_poles[i].inner})
      scale[p] = std::min(scale[p], spacing[i]);
  std::vector<bool> skip(result.poles.size());
  for (std::size_t p = 0; p < result.poles.size(); ++p) skip[p] = result.poles[p].radius < ratio * scale[p];
  return skip;
}

// Poles that only bad choices made (PowerCrustOptions::sampling_estimate; the samples left
// unpaired): a bad second pole, and with drop_both the first pole of its sample, unless
// another sample keeps the pole.
std::vector<bool> bad_poles(const PowerCrustResult& result, bool drop_both) {
  std::vector<bool> kept(result.poles.size(), false);
  for (const SamplePoles& sp : result.sample_poles) {
    if (sp.is_paired || !drop_both) kept[sp.outer] = true;
    if (sp.is_paired) kept[sp.inner] = true;
  }
  kept.flip();
  return kept;
}

}  // namespace

PowerCrustResult power_crust(const std::vector<Point3>& points, const PowerCrustOptions& options,
                             const Progress& progress) {
  const Thresholds thresholds = check_options(options);
  mesh::MergedPoints merged = mesh::merge_duplicate_points(points);
  check_dimension(merged.points);

  PowerCrustResult result;
  PowerCrustStats& stats = result.stats;
  stats.input_points = points.size();
  stats.duplicate_points = merged.duplicates;
  result.samples = std::move(merged.points);
  result.input_to_sample = std::move(merged.input_to_merged);
  result.bounding_points = bounding_points(result.samples, options.bounding_box_scale);
  if (merged.duplicates > 0)
    result.warnings.push_back(std::to_string(merged.duplicates) + " duplicate points merged");

  // Lock-grid insertion only pays with spare cores: on 2 shared cores it measured 2-4x slower
  // than sequential insertion (the same holds for a bare CGAL DT there).
  const bool spare_cores = tbb::this_task_arena::max_concurrency() >= 4;
  auto parallel = [&](std::size_t n) {
    return options.parallel_insertion_from == 0 || (spare_cores && n >= options.parallel_insertion_from);
  };
  StageClock clock(progress);
  std::vector<double> local_spacing;
  {
    clock.begin("delaunay");
    std::unique_ptr<Delaunay> dt = build_delaunay(result.samples, result.bounding_points,
                                                  parallel(result.samples.size()));
    stats.seconds_delaunay = clock.lap("delaunay");
    clock.begin("poles");
    // compute_poles frees the DT, the largest object besides the RT: the two are never held
    // together (docs/method.md §7.10).
    PoleStage poles = compute_poles(std::move(dt), result.samples, options.keep_delaunay_cells,
                                     options.min_pole_radius_rel_spacing > 0, thresholds.sampling_estimate);
    result.poles = std::move(poles.poles);
    result.sample_poles = std::move(poles.sample_poles);
    result.delaunay_cells = std::move(poles.cells);
    local_spacing = std::move(poles.local_spacing);
    stats.delaunay_cells = poles.finite_cells;
    stats.welded_poles = poles.welded_poles;
    stats.poles = result.poles.size();
    stats.seconds_poles = clock.lap("poles");
  }

  clock.begin("power_diagram");
  const CGAL::Bbox_3 sample_box = CGAL::bbox_3(result.samples.begin(), result.samples.end());
  std::vector<bool> skip = small_poles(result, local_spacing, options.min_pole_radius_rel_spacing);
  stats.filtered_poles = static_cast<std::size_t>(std::count(skip.begin(), skip.end(), true));
  std::vector<bool> deferred;
  if (thresholds.sampling_estimate < 1.0) {
    const std::vector<bool> bad = bad_poles(result, options.drop_both_bad_poles);
    stats.bad_second_poles = static_cast<std::size_t>(std::count_if(
        result.sample_poles.begin(), result.sample_poles.end(), [](const SamplePoles& sp) { return !sp.is_paired; }));
    skip.resize(result.poles.size(), false);
    for (std::size_t p = 0; p < bad.size(); ++p) {
      stats.bad_poles_left_out += bad[p] && !skip[p];
      skip[p] = skip[p] || bad[p];
    }
    if (options.defer_bad_first_poles && !options.drop_both_bad_poles) {
      deferred.assign(result.poles.size(), false);
      for (const SamplePoles& sp : result.sample_poles)
        if (!sp.is_paired) deferred[sp.outer] = true;
      stats.deferred_poles = static_cast<std::size_t>(std::count(deferred.begin(), deferred.end(), true));
    }
  }
  const PowerDiagram diagram =
      build_power_diagram(result.poles, sample_box, parallel(result.poles.size()),
                          options.pole_joggle, skip);
  // Poles left out (the minimum radius, bad poles) may leave too few to span a volume.
  if (diagram.rt->dimension() < 3) {
    const std::size_t left_out = static_cast<std::size_t>(std::count(skip.begin(), skip.end(), true));
    throw DegenerateInput("only " + std::to_string(result.poles.size() - left_out) + " of " +
                          std::to_string(result.poles.size()) + " poles are left for the power diagram" +
                          (stats.filtered_poles > 0 ? " (the minimum pole radius left out " +
                                                          std::to_string(stats.filtered_poles) + ")"
                                                    : std::string()) +
                          ": they span no volume");
  }
  stats.power_diagram_cells = diagram.rt->number_of_finite_cells();
  stats.seconds_power_diagram = clock.lap("power_diagram");

  clock.begin("labeling");
  {
    const PoleGraph graph = build_pole_graph(diagram, result.poles);
    const LabelingReport report =
        label_poles(result.poles, result.sample_poles, graph, thresholds, sample_box,
                    options.resolve_unknown, deferred);
    stats.unknown_poles = report.unknown_after_second_pass;
    stats.resolved_unknown_poles = report.resolved;
    if (report.unknown_after_second_pass > 0)
      result.warnings.push_back(std::to_string(report.unknown_after_second_pass) +
                                " poles left unlabeled by the second pass" +
                                (options.resolve_unknown ? ", " + std::to_string(report.resolved) +
                                                               " of them labeled like their deepest neighbour"
                                                         : std::string()));
  }
  count_labels(result.poles, stats);
  stats.seconds_labeling = clock.lap("labeling");
  if (stats.inner_poles == 0)
    result.warnings.push_back("no pole is labeled in: the " + std::to_string(result.samples.size()) +
                              " samples enclose no volume the labeling can find (too few or too sparse for a "
                              "closed surface), so the crust is empty");

  if (options.build_crust) {
    clock.begin("crust");
    CrustStage crust = extract_crust(diagram, result.poles);
    result.crust = std::move(crust.mesh);
    result.crust_face_poles = std::move(crust.face_poles);
    stats.crust_polygons = crust.polygons;
    stats.unbounded_crust_faces = crust.unbounded_faces;
    stats.crust_faces = result.crust.triangles.size();
    result.warnings.insert(result.warnings.end(), crust.warnings.begin(), crust.warnings.end());
    if (stats.crust_faces == 0 && stats.inner_poles > 0)
      result.warnings.push_back("the crust is empty: no face of the power diagram separates an inner pole from an "
                                "outer one (" + std::to_string(stats.inner_poles) + " inner poles" +
                                (stats.filtered_poles > 0 ? ", " + std::to_string(stats.filtered_poles) +
                                                                " poles left out by the minimum pole radius"
                                                          : std::string()) + ")");
    stats.seconds_crust = clock.lap("crust");
  }
  if (options.build_power_shape) {
    clock.begin("power_shape");
    result.power_shape = extract_power_shape(diagram, result.poles);
    stats.seconds_power_shape = clock.lap("power_shape");
  }
  return result;
}

}  // namespace envcrust::powercrust
