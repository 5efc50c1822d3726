// envcrust_bench_powercrust: time per Power Crust stage against a bare CGAL Delaunay
// triangulation of the same points (sequential and parallel), and peak memory. Each
// measurement runs in a forked child, so every peak RSS belongs to one run. Usage:
//   envcrust_bench_powercrust [--sizes 10000,100000,1000000] [--surfaces sphere,torus]
//                             [--noise 0.001] [--min-pole-radius 3] [--parallel-from 200000] [--check]
#include "peak_memory.h"

#include "envcrust/power_crust.h"
#include "envcrust/surfaces.h"
#include "envcrust/topology.h"

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Spatial_lock_grid_3.h>
#include <CGAL/Triangulation_data_structure_3.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

using namespace envcrust;

namespace {

using SequentialDt = CGAL::Delaunay_triangulation_3<Kernel>;
using ParallelTds = CGAL::Triangulation_data_structure_3<
    CGAL::Triangulation_vertex_base_3<Kernel>,
    CGAL::Delaunay_triangulation_cell_base_3<Kernel>, CGAL::Parallel_tag>;
using ParallelDt = CGAL::Delaunay_triangulation_3<Kernel, ParallelTds>;

struct Args {
  std::vector<std::size_t> sizes = {10000, 100000, 1000000};
  std::vector<std::string> surfaces = {"sphere", "torus"};
  double noise = 0.0;
  double joggle = powercrust::PowerCrustOptions().pole_joggle;
  double min_pole_radius = 0.0;
  bool check = false;
  std::size_t parallel_from = powercrust::PowerCrustOptions().parallel_insertion_from;
};

// What a child sends back through its pipe.
struct Measurement {
  double seconds[8] = {};  // sample, delaunay, poles, power diagram, labeling, crust, shape, total
  double dt_sequential = 0, dt_parallel = 0;
  double stage_peak_mb[6] = {};  // peak RSS within each stage, in the order of seconds[1..6]
  std::size_t poles = 0, hidden = 0, faces = 0, delaunay_cells = 0;
  long euler = 0;
  int closed = -1, manifold = -1;
};

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  std::string item;
  while (std::getline(in, item, ',')) out.push_back(item);
  return out;
}

Args parse(int argc, char** argv) {
  Args a;
  for (int i = 1; i < argc; ++i) {
    const std::string key = argv[i];
    const bool has_value = i + 1 < argc;
    if (key == "--sizes" && has_value) {
      a.sizes.clear();
      for (const auto& s : split(argv[++i])) a.sizes.push_back(std::stoul(s));
    } else if (key == "--surfaces" && has_value) {
      a.surfaces = split(argv[++i]);
    } else if (key == "--noise" && has_value) {
      a.noise = std::stod(argv[++i]);
    } else if (key == "--parallel-from" && has_value) {
      a.parallel_from = std::stoul(argv[++i]);
    } else if (key == "--min-pole-radius" && has_value) {
      a.min_pole_radius = std::stod(argv[++i]);
    } else if (key == "--joggle" && has_value) {
      a.joggle = std::stod(argv[++i]);
    } else if (key == "--check") {
      a.check = true;
    } else {
      std::fprintf(stderr, "usage: %s [--sizes a,b] [--surfaces s,t] [--noise x] [--joggle x] [--min-pole-radius k] [--parallel-from n] [--check]\n", argv[0]);
      std::exit(2);
    }
  }
  return a;
}

double since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

std::vector<Point3> sample(const std::string& name, std::size_t n, double noise) {
  surfaces::SampleOptions options;
  options.count = n;
  options.noise_rel_diag = noise;
  options.seed = 11;
  return surfaces::sample_surface(*surfaces::make_builtin(name), options).points;
}

Measurement run_power_crust(const std::vector<Point3>& points, const Args& args) {
  Measurement m;
  powercrust::PowerCrustOptions options;
  options.parallel_insertion_from = args.parallel_from;
  options.pole_joggle = args.joggle;
  options.min_pole_radius_rel_spacing = args.min_pole_radius;
  Progress progress;
  const char* stage_names[] = {"delaunay", "poles", "power_diagram", "labeling", "crust", "power_shape"};
  bench::take_peak_mb();
  progress.callback = [&](std::string_view stage, double fraction) {
    if (fraction < 1.0) return;
    for (int k = 0; k < 6; ++k)
      if (stage == stage_names[k]) m.stage_peak_mb[k] = bench::take_peak_mb();
  };
  const auto t0 = std::chrono::steady_clock::now();
  const auto r = powercrust::power_crust(points, options, progress);
  m.seconds[7] = since(t0);
  const auto& s = r.stats;
  const double stages[] = {s.seconds_delaunay, s.seconds_poles, s.seconds_power_diagram,
                           s.seconds_labeling, s.seconds_crust, s.seconds_power_shape};
  for (int k = 0; k < 6; ++k) m.seconds[k + 1] = stages[k];
  m.poles = s.poles;
  m.hidden = s.hidden_poles;
  m.faces = s.crust_faces;
  m.delaunay_cells = s.delaunay_cells;
  if (args.check) {
    topology::TopologyOptions options;
    options.weld_identical_vertices = false;  // the crust's vertices are named by cell
    const auto t = topology::analyze_topology(r.crust, options);
    m.euler = t.euler_characteristic;
    m.closed = t.is_closed();
    m.manifold = t.is_manifold();
  }
  return m;
}

Measurement run_baselines(const std::vector<Point3>& points) {
  Measurement m;
  auto t0 = std::chrono::steady_clock::now();
  {
    SequentialDt dt(points.begin(), points.end());
  }
  m.dt_sequential = since(t0);
  t0 = std::chrono::steady_clock::now();
  {
    ParallelDt::Lock_data_structure lock(CGAL::bbox_3(points.begin(), points.end()), 50);
    ParallelDt dt(points.begin(), points.end(), &lock);
  }
  m.dt_parallel = since(t0);
  return m;
}

// Run `work` in a child; returns its measurement and its peak RSS in MB.
template <class Work>
std::pair<Measurement, double> in_child(Work&& work) {
  int fds[2];
  if (pipe(fds) != 0) std::exit(1);
  std::fflush(stdout);
  const pid_t pid = fork();
  if (pid == 0) {
    close(fds[0]);
    const Measurement m = work();
    if (write(fds[1], &m, sizeof m) != static_cast<ssize_t>(sizeof m)) _exit(1);
    _exit(0);
  }
  close(fds[1]);
  Measurement m;
  const bool ok = read(fds[0], &m, sizeof m) == static_cast<ssize_t>(sizeof m);
  close(fds[0]);
  int status = 0;
  rusage usage{};
  wait4(pid, &status, 0, &usage);
  if (!ok) std::fprintf(stderr, "child failed (status %d)\n", status);
  // The stage peaks reset the kernel's high-water mark (so ru_maxrss only covers what came
  // after the last stage): a Power Crust run's peak is the largest stage peak, which leaves
  // out sampling the input and the --check analysis.
  double peak = static_cast<double>(usage.ru_maxrss) / 1024.0;
  if (m.stage_peak_mb[0] > 0) peak = *std::max_element(std::begin(m.stage_peak_mb), std::end(m.stage_peak_mb));
  return {m, peak};
}

}  // namespace

int main(int argc, char** argv) {
  const Args args = parse(argc, argv);
  std::printf("%-7s %8s | %7s %7s %7s %7s %7s %7s %7s | %7s %7s | %6s %6s | %8s %9s | %7s %6s %9s\n",
              "surface", "points", "dt_s", "poles_s", "rt_s", "label_s", "crust_s", "shape_s",
              "total_s", "DTseq_s", "DTpar_s", "x_seq", "x_par", "peak_MB", "MB/Mpts", "poles",
              "hidden", "topology");
  for (const auto& name : args.surfaces) {
    for (const std::size_t n : args.sizes) {
      const auto [pc, pc_mb] = in_child([&] { return run_power_crust(sample(name, n, args.noise), args); });
      const auto [base, base_mb] = in_child([&] { return run_baselines(sample(name, n, args.noise)); });
      char topo[32] = "-";
      if (args.check)
        std::snprintf(topo, sizeof topo, "chi%ld%s%s", pc.euler, pc.closed ? ",closed" : ",OPEN",
                      pc.manifold ? "" : ",nonmf");
      std::printf("%-7s %8zu | %7.2f %7.2f %7.2f %7.2f %7.2f %7.2f %7.2f | %7.2f %7.2f | %6.2f %6.2f | %8.0f %9.0f | %7zu %6zu %9s\n",
                  name.c_str(), n, pc.seconds[1], pc.seconds[2], pc.seconds[3], pc.seconds[4],
                  pc.seconds[5], pc.seconds[6], pc.seconds[7], base.dt_sequential, base.dt_parallel,
                  pc.seconds[7] / base.dt_sequential, pc.seconds[7] / base.dt_parallel, pc_mb,
                  pc_mb / (static_cast<double>(n) / 1e6), pc.poles, pc.hidden, topo);
      std::printf("        peak MB per stage: delaunay %.0f, poles %.0f, power diagram %.0f, labeling %.0f, "
                  "crust %.0f, power shape %.0f; bare DTs %.0f; Delaunay cells %zu (%.1f per sample, "
                  "%zu bytes each in the bare DT, 64 in the Power Crust's)\n",
                  pc.stage_peak_mb[0], pc.stage_peak_mb[1], pc.stage_peak_mb[2], pc.stage_peak_mb[3],
                  pc.stage_peak_mb[4], pc.stage_peak_mb[5], base_mb, pc.delaunay_cells,
                  static_cast<double>(pc.delaunay_cells) / static_cast<double>(n), sizeof(ParallelDt::Cell));
      std::fflush(stdout);
    }
  }
  return 0;
}
