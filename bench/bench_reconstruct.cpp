// envcrust_bench_reconstruct: time of the envelope reconstruction of built-in surfaces, as a
// ratio to a bare CGAL Delaunay triangulation of the same envelope samples (same run).
//   envcrust_bench_reconstruct [--sizes 10000,100000,1000000] [--surfaces trefoil-ribbon,moebius]
//                              [--point-clouds]
// Peak MB: the largest resident size during the reconstruction (VmHWM, reset before it).
// --point-clouds: the samples lose their exact normals and boundary; as `reconstruct` does for
// a point file, stray samples are removed, normal lines estimated by PCA and the boundary
// detected (each timed apart), and the settings are pipeline::options_for_input's.
#include "peak_memory.h"

#include "envcrust/boundary.h"
#include "envcrust/extract.h"
#include "envcrust/heap.h"
#include "envcrust/normals.h"
#include "envcrust/outliers.h"
#include "envcrust/pipeline.h"
#include "envcrust/surfaces.h"

#include <CGAL/Delaunay_triangulation_3.h>

#include <chrono>
#include <memory>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

using namespace envcrust;

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

std::vector<std::string> split(const char* text) {
  std::vector<std::string> out;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) out.push_back(item);
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  io::reuse_freed_memory();  // as the CLI's reconstruct does
  std::vector<std::string> sizes = {"10000", "100000", "1000000"};
  std::vector<std::string> names = {"trefoil-ribbon", "moebius", "cylinder"};
  bool point_clouds = false;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--point-clouds") == 0) point_clouds = true;
    if (i + 1 == argc) break;
    if (std::strcmp(argv[i], "--sizes") == 0) sizes = split(argv[i + 1]);
    if (std::strcmp(argv[i], "--surfaces") == 0) names = split(argv[i + 1]);
  }
  pipeline::InputKind input;  // as `reconstruct` runs builtin:NAME, or a point file without normals
  input.is_builtin = !point_clouds;
  input.are_normals_estimated = point_clouds;
  const auto options = pipeline::options_for_input(input);
  std::printf("| surface | input points | outliers s | normals s | boundary s | envelope samples | envelope s | sheet s | "
              "total s | bare DT s | ratio | peak MB |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const auto& name : names) {
    const auto surface = surfaces::make_builtin(name);
    for (const auto& size : sizes) {
      surfaces::SampleOptions o;
      o.count = std::stoul(size);
      o.with_normals = true;
      const PointSet ps = surfaces::sample_surface(*surface, o);
      envelope::SurfaceSamples samples{ps.points, ps.normals,
                                       surfaces::boundary_curves(*surface, 0.005 * surfaces::bbox_diagonal(*surface)), {}};
      double outliers_s = 0.0, normals_s = 0.0, boundary_s = 0.0;
      bench::take_peak_mb();  // the peak below is the reconstruction's, sampling excluded
      auto t0 = std::chrono::steady_clock::now();
      if (point_clouds) {
        // As `reconstruct` does for a point file: one neighbour search for the three passes
        // (its time counted with the stray samples'), freed before the reconstruction.
        auto table = std::make_unique<NeighbourTable>(samples.points, 32);
        const auto strays = outliers::find_outliers(samples.points, *table);
        std::vector<char> keep(samples.points.size());
        std::vector<Point3> kept;
        for (std::size_t i = 0; i < samples.points.size(); ++i) {
          keep[i] = strays.is_outlier[i] ? 0 : 1;
          if (keep[i]) kept.push_back(samples.points[i]);
        }
        if (kept.size() < samples.points.size())
          table = std::make_unique<NeighbourTable>(table->subset(samples.points, keep));
        samples.points = std::move(kept);
        outliers_s = seconds_since(t0);
        t0 = std::chrono::steady_clock::now();
        samples.normals = normals::estimate_normal_lines(samples.points, *table);
        normals_s = seconds_since(t0);
        t0 = std::chrono::steady_clock::now();
        samples.boundary = boundary::detect_boundary(samples.points, samples.normals, *table).curves;
        boundary_s = seconds_since(t0);
        table.reset();
        t0 = std::chrono::steady_clock::now();
      }
      const auto result = pipeline::reconstruct(samples, options);
      const double total = seconds_since(t0) + outliers_s + normals_s + boundary_s;
      const double peak = bench::take_peak_mb();
      const auto points = result.envelope.points();
      t0 = std::chrono::steady_clock::now();
      CGAL::Delaunay_triangulation_3<Kernel> dt(points.begin(), points.end());
      const double bare = seconds_since(t0);
      std::printf("| %s | %s | %.2f | %.2f | %.2f | %zu | %.2f | %.2f | %.2f | %.2f | %.1f× | %.0f |\n", name.c_str(),
                  size.c_str(), outliers_s, normals_s, boundary_s, points.size(), result.seconds.envelope,
                  result.seconds.extraction, total, bare, total / bare, peak);
      std::fflush(stdout);
    }
  }
  return 0;
}
