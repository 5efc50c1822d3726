// `envcrust render`: pictures of meshes, point clouds, balls and boundary loops (headless).
#include "cli_common.h"
#include "commands.h"
#include "inputs.h"

#include "envcrust/distance.h"
#include "envcrust/errors.h"
#include "envcrust/io.h"
#include "envcrust/render.h"
#include "envcrust/topology.h"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>

namespace envcrust::cli {
namespace {

enum class PointStyle { Spheres, None };
enum class BallLabels { In, Out, All };

struct RenderCommand {
  std::vector<std::string> inputs;
  std::string output;
  std::string size = "800x600";
  std::string view = "iso";
  bool is_flat = false;
  bool use_wireframe = false;
  std::string front_color, back_color, boundary_color;  ///< "#rrggbb"; empty: library default
  PointStyle points_as = PointStyle::Spheres;
  std::optional<double> point_radius;  ///< model units; unset: 0.4% of the diagonal
  bool use_boundary = false;           ///< mesh files: draw their boundary loops
  std::optional<double> tube_radius;   ///< model units; unset: 0.6% of the diagonal
  std::vector<int> grid;               ///< rows, columns
  std::string title;
  std::vector<std::string> captions;
  std::vector<std::string> balls;
  BallLabels ball_labels = BallLabels::In;
  float ball_opacity = 0.3f;
  std::string font = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
  int font_px = render::Font{}.pixel_height;
  std::string error_reference;       ///< colour meshes by the distance of their vertices to it
  std::optional<double> error_max;   ///< the distance drawn red; unset: the largest of all panels
  render::RenderOptions options;
  CommonFlags common;
};

render::Color parse_color(const std::string& flag, const std::string& text) {
  const std::string hex = !text.empty() && text[0] == '#' ? text.substr(1) : text;
  if (hex.size() != 6 || hex.find_first_not_of("0123456789abcdefABCDEF") != std::string::npos)
    throw UsageError(flag + ": expected a colour as #rrggbb, got '" + text + "'");
  auto channel = [&](int i) { return static_cast<float>(std::stoi(hex.substr(2 * i, 2), nullptr, 16)) / 255.0f; };
  return {channel(0), channel(1), channel(2)};
}

void parse_size(const std::string& text, render::RenderOptions& options) {
  char x = 0, extra = 0;
  std::istringstream in(text);
  if (!(in >> options.width >> x >> options.height) || (x != 'x' && x != 'X') || in >> extra)
    throw UsageError("--size: expected WIDTHxHEIGHT in pixels, e.g. 800x600, got '" + text + "'");
  if (options.width < 16 || options.width > 8192 || options.height < 16 || options.height > 8192)
    throw UsageError("--size: width and height must be in [16, 8192] pixels, got '" + text + "'");
}

render::View parse_view(const std::string& text) {
  if (text == "iso") return render::View::iso();
  if (text == "front") return render::View::front();
  if (text == "top") return render::View::top();
  render::View view;
  char comma = 0, extra = 0;
  std::istringstream in(text);
  if (!(in >> view.azimuth_deg >> comma >> view.elevation_deg) || comma != ',' || in >> extra)
    throw UsageError("--view: expected iso, front, top or AZIMUTH,ELEVATION in degrees, got '" + text + "'");
  if (!(std::abs(view.elevation_deg) <= 90))
    throw UsageError("--view: the elevation must be in [-90, 90] degrees, got '" + text + "'");
  // Taken modulo a turn: the camera's trigonometry loses all precision on huge angles.
  view.azimuth_deg = std::fmod(view.azimuth_deg, 360.0);
  return view;
}

std::string default_caption(const std::string& spec) {
  if (is_builtin_spec(spec)) return spec.substr(spec.find(':') + 1);  // a NURBS file: its file name
  return std::filesystem::path(spec).filename().string();
}

/// What one panel shows, and counts for the report.
struct PanelScene {
  render::Scene scene;
  nlohmann::json summary;
};

void add_balls(const RenderCommand& cmd, const std::string& path, PanelScene& panel) {
  const io::BallSet balls = io::read_balls(path);
  render::SphereLayer layer;
  layer.color = {0.25f, 0.5f, 0.9f};
  layer.opacity = cmd.ball_opacity;
  for (std::size_t i = 0; i < balls.centres.size(); ++i) {
    const std::string& label = balls.labels[i];
    const bool keep = label.empty() || cmd.ball_labels == BallLabels::All ||
                      (cmd.ball_labels == BallLabels::In && label == "in") ||
                      (cmd.ball_labels == BallLabels::Out && label == "out");
    if (!keep) continue;
    layer.centres.push_back(balls.centres[i]);
    layer.radii.push_back(balls.radii[i]);
  }
  panel.summary["balls"] = layer.centres.size();
  panel.summary["balls_file"] = path;
  if (!layer.centres.empty()) panel.scene.spheres.push_back(std::move(layer));
}

PanelScene panel_scene(const RenderCommand& cmd, const std::string& spec) {
  PanelScene panel;
  analysis::Reference reference = load_reference(spec);
  render::CurveLayer loops;
  if (cmd.tube_radius) loops.radius = *cmd.tube_radius;
  if (!cmd.boundary_color.empty()) loops.colors = {parse_color("--boundary-color", cmd.boundary_color)};
  loops.loops = reference.boundary;  // builtins and NURBS patches: their exact boundary curves
  panel.summary = {{"input", spec}, {"triangles", 0}, {"points", 0}};
  if (reference.mesh) {
    if (cmd.use_boundary && loops.loops.empty()) {
      const auto topology = topology::analyze_topology(*reference.mesh);
      for (const auto& loop : topology.boundary_loops) loops.loops.push_back(loop.polyline(topology.points));
    }
    render::MeshLayer mesh;
    mesh.mesh = std::move(*reference.mesh);
    mesh.shading = cmd.is_flat ? render::Shading::Flat : render::Shading::Smooth;
    mesh.use_wireframe = cmd.use_wireframe;
    if (!cmd.front_color.empty()) mesh.front = parse_color("--front-color", cmd.front_color);
    if (!cmd.back_color.empty()) mesh.back = parse_color("--back-color", cmd.back_color);
    panel.summary["triangles"] = mesh.mesh.triangles.size();
    panel.scene.meshes.push_back(std::move(mesh));
  } else if (cmd.points_as == PointStyle::Spheres) {
    render::SphereLayer points;
    points.centres = std::move(reference.points);
    if (cmd.point_radius) points.radii = {*cmd.point_radius};
    panel.summary["points"] = points.centres.size();
    panel.scene.spheres.push_back(std::move(points));
  }
  panel.summary["boundary_loops"] = loops.loops.size();
  if (!loops.loops.empty()) panel.scene.curves.push_back(std::move(loops));
  return panel;
}

// The distance of every vertex of each panel's meshes to the reference (a mesh, builtin:NAME's
// exact tessellation, or a point file), as colours from blue (0) to red (the scale's top:
// --error-max, or the largest distance over all panels); each panel's report gets its largest
// and mean distance. Returns the top of the scale.
double colour_by_error(const RenderCommand& cmd, std::vector<PanelScene>& panels) {
  const analysis::Reference reference = load_reference(cmd.error_reference);
  std::vector<std::vector<std::vector<double>>> distances(panels.size());
  double largest = 0.0;
  for (std::size_t p = 0; p < panels.size(); ++p) {
    double max = 0.0, sum = 0.0;
    std::size_t count = 0;
    for (const auto& layer : panels[p].scene.meshes) {
      const auto& vertices = layer.mesh.vertices;
      distances[p].push_back(reference.mesh ? distance::distances_to_mesh(vertices, *reference.mesh)
                                            : distance::distances_to_points(vertices, reference.points));
      for (const double d : distances[p].back()) max = std::max(max, d), sum += d, ++count;
    }
    if (count > 0)
      panels[p].summary["error"] = {{"max", max}, {"mean", sum / static_cast<double>(count)}, {"vertices", count}};
    largest = std::max(largest, max);
  }
  const double top = cmd.error_max.value_or(largest);
  for (std::size_t p = 0; p < panels.size(); ++p)
    for (std::size_t m = 0; m < panels[p].scene.meshes.size(); ++m) {
      auto& layer = panels[p].scene.meshes[m];
      const auto& d = distances[p][m];
      if (d.size() != layer.mesh.vertices.size()) continue;  // no triangle to measure against: plain colours
      layer.vertex_colors.resize(d.size());
      for (std::size_t v = 0; v < d.size(); ++v) layer.vertex_colors[v] = render::heat_color(top > 0 ? d[v] / top : 0.0);
    }
  return top;
}

std::string short_number(double value) {
  std::ostringstream out;
  out.precision(3);
  out << value;
  return out.str();
}

std::optional<render::Font> load_font(const RenderCommand& cmd, std::vector<std::string>& warnings) {
  if (!std::filesystem::exists(cmd.font)) {
    warnings.push_back("font " + cmd.font + " not found: captions and title left out");
    return std::nullopt;
  }
  return read_checked_font(cmd.font, cmd.font_px);
}

void run_render(RenderCommand& cmd) {
  io::check_output_path(cmd.output, io::OutputKind::Image);
  std::vector<std::pair<std::string, std::string>> inputs = {{"--error-to", cmd.error_reference}, {"--font", cmd.font}};
  for (const auto& f : cmd.inputs) inputs.emplace_back("input", f);
  for (const auto& f : cmd.balls) inputs.emplace_back("--balls", f);
  check_outputs_are_not_inputs(inputs, {{"-o", cmd.output}});
  const auto thread_limit = limit_threads(cmd.common.threads);
  const auto start = std::chrono::steady_clock::now();
  parse_size(cmd.size, cmd.options);
  cmd.options.view = parse_view(cmd.view);
  if (!cmd.captions.empty() && cmd.captions.size() != cmd.inputs.size())
    throw UsageError("--caption: give one per input (" + std::to_string(cmd.inputs.size()) + "), got " +
                     std::to_string(cmd.captions.size()));
  if (cmd.balls.size() > cmd.inputs.size())
    throw UsageError("--balls: at most one per input (" + std::to_string(cmd.inputs.size()) + "), got " +
                     std::to_string(cmd.balls.size()));
  if (!cmd.grid.empty() && cmd.grid.size() != 2) throw UsageError("--grid: expected ROWS COLUMNS");
  if (cmd.error_max && cmd.error_reference.empty()) throw UsageError("--error-max needs --error-to");
  if (!cmd.grid.empty() && (cmd.grid[0] < 1 || cmd.grid[1] < 1 ||
                            static_cast<std::size_t>(cmd.grid[0]) * static_cast<std::size_t>(cmd.grid[1]) < cmd.inputs.size()))
    throw UsageError("--grid " + std::to_string(cmd.grid[0]) + " " + std::to_string(cmd.grid[1]) + ": room for " +
                     std::to_string(std::max(0, cmd.grid[0]) * std::max(0, cmd.grid[1])) + " panels, not the " +
                     std::to_string(cmd.inputs.size()) + " inputs");
  if (!cmd.grid.empty() && (static_cast<std::size_t>(cmd.grid[0] - 1) * static_cast<std::size_t>(cmd.grid[1]) >= cmd.inputs.size() ||
                            static_cast<std::size_t>(cmd.grid[1]) > cmd.inputs.size()))
    throw UsageError("--grid " + std::to_string(cmd.grid[0]) + " " + std::to_string(cmd.grid[1]) +
                     ": leaves a row or column empty for " + std::to_string(cmd.inputs.size()) +
                     (cmd.inputs.size() == 1 ? " input" : " inputs"));

  std::vector<std::string> warnings;
  std::vector<PanelScene> scenes;
  for (std::size_t i = 0; i < cmd.inputs.size(); ++i) {
    scenes.push_back(panel_scene(cmd, cmd.inputs[i]));
    if (i < cmd.balls.size()) add_balls(cmd, cmd.balls[i], scenes.back());
  }
  std::optional<double> error_top;
  if (!cmd.error_reference.empty()) {
    error_top = colour_by_error(cmd, scenes);
    if (cmd.title.empty())
      cmd.title = "distance to " + default_caption(cmd.error_reference) + ": blue 0, red " + short_number(*error_top) +
                  " or more";
  }
  // The font is read and checked before the panels are drawn.
  const bool is_grid = !(cmd.inputs.size() == 1 && cmd.title.empty() && cmd.captions.empty());
  const std::optional<render::Font> font = is_grid ? load_font(cmd, warnings) : std::nullopt;
  std::vector<render::Panel> panels;
  nlohmann::json panel_reports = nlohmann::json::array();
  for (std::size_t i = 0; i < cmd.inputs.size(); ++i) {
    const auto panel_start = std::chrono::steady_clock::now();
    PanelScene& panel = scenes[i];
    render::Image image;
    try {
      image = render::render_scene(panel.scene, cmd.options);
    } catch (const InvalidInput& e) {
      throw InvalidInput(cmd.inputs[i] + ": " + e.what());  // say which input it was
    }
    const std::string caption = cmd.captions.empty() ? default_caption(cmd.inputs[i]) : cmd.captions[i];
    panel.summary["caption"] = caption;
    panel.summary["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - panel_start).count();
    panel_reports.push_back(panel.summary);
    panels.push_back({std::move(image), caption});
  }

  // A single input without title or explicit caption is the picture itself, at --size.
  render::Image picture;
  if (!is_grid) {
    picture = std::move(panels[0].image);
  } else {
    render::GridOptions grid;
    if (!cmd.grid.empty()) grid.rows = cmd.grid[0], grid.columns = cmd.grid[1];
    grid.title = cmd.title;
    grid.background = cmd.options.background;
    picture = render::compose_grid(panels, grid, font);
  }
  io::write_png(cmd.output, picture);

  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (cmd.common.json) {
    nlohmann::json report = {{"output", cmd.output}, {"width", picture.width}, {"height", picture.height},
                              {"panels", panel_reports}, {"seconds", seconds}, {"warnings", warnings}};
    if (error_top) report["error_scale"] = {{"reference", cmd.error_reference}, {"red_at", *error_top}};
    print_json(report);
    return;
  }
  for (const auto& w : warnings) std::cerr << "envcrust: warning: " << w << "\n";
  if (cmd.common.quiet) return;
  std::cout << "rendered " << panels.size() << (panels.size() == 1 ? " panel" : " panels") << " to " << cmd.output
            << " (" << picture.width << " x " << picture.height << " pixels) in " << seconds << " s\n";
  if (!error_top) return;
  std::cout << "  distance to " << cmd.error_reference << " (red at " << *error_top << "):\n";
  for (const auto& panel : panel_reports)
    if (panel.contains("error"))
      std::cout << "    " << panel["input"].get<std::string>() << ": largest " << panel["error"]["max"].get<double>()
                << ", mean " << panel["error"]["mean"].get<double>() << "\n";
}

}  // namespace

void register_render(CLI::App& app) {
  auto cmd = std::make_shared<RenderCommand>();
  CLI::App* sub = app.add_subcommand("render", "Render meshes, point clouds, balls and boundary loops to a PNG");
  sub->add_option("inputs", cmd->inputs,
                  "Meshes (.ply/.off/.obj/.stl), point files (.xyz/.pts/.txt/.csv/.ply) builtin:NAME or NURBS patches (.igs/.iges/.json); "
                  "several inputs become panels side by side")
      ->required();
  sub->add_option("-o,--output", cmd->output, "PNG file to write")->required();
  sub->add_option("--size", cmd->size, "Pixels of each panel, WIDTHxHEIGHT")->capture_default_str();
  sub->add_option("--view", cmd->view, "iso, front, top, or AZIMUTH,ELEVATION in degrees")->capture_default_str();
  sub->add_option("--supersampling", cmd->options.supersampling, "Rays per pixel along each axis (1-4)")
      ->capture_default_str()
      ->check(whole_number_in(1, 4));
  sub->add_flag("--flat", cmd->is_flat, "Flat shading (one normal per triangle) instead of smooth");
  sub->add_flag("--wireframe", cmd->use_wireframe, "Darken triangle edges");
  sub->add_option("--front-color", cmd->front_color, "Colour of front faces, #rrggbb (default grey-blue)");
  sub->add_option("--back-color", cmd->back_color, "Colour of back faces, #rrggbb (default terracotta)");
  const std::map<std::string, PointStyle> point_styles = {{"spheres", PointStyle::Spheres}, {"none", PointStyle::None}};
  sub->add_option("--points-as", cmd->points_as, "How point files are drawn: spheres or none")
      ->transform(CLI::CheckedTransformer(point_styles, CLI::ignore_case))
      ->default_str("spheres");
  sub->add_option("--point-radius", cmd->point_radius, "Radius of point spheres in model units (default 0.4% of the diagonal)")
      ->check(number_above(0));
  sub->add_flag("--boundary", cmd->use_boundary,
                "Draw the boundary loops of mesh inputs as tubes (builtin:NAME and NURBS inputs always show theirs)");
  sub->add_option("--tube-radius", cmd->tube_radius, "Radius of boundary tubes in model units (default 0.6% of the diagonal)")
      ->check(number_above(0));
  sub->add_option("--boundary-color", cmd->boundary_color, "One colour for all boundary tubes, #rrggbb (default: a palette)");
  sub->add_option("--balls", cmd->balls,
                  "Balls (powercrust --poles: .ply with radius and label, or text 'x y z radius [label]') drawn translucent over the i-th input");
  const std::map<std::string, BallLabels> labels = {{"in", BallLabels::In}, {"out", BallLabels::Out}, {"all", BallLabels::All}};
  sub->add_option("--ball-labels", cmd->ball_labels, "Which labelled balls to draw: in, out or all (unlabelled: always)")
      ->transform(CLI::CheckedTransformer(labels, CLI::ignore_case))
      ->default_str("in");
  sub->add_option("--ball-opacity", cmd->ball_opacity, "Opacity of the balls, (0, 1]")
      ->capture_default_str()
      ->check(number_in(0, 1, false, true));
  sub->add_option("--grid", cmd->grid, "Panels in ROWS COLUMNS (default: one row)")->expected(2);
  sub->add_option("--title", cmd->title, "Title above the panels");
  sub->add_option("--caption", cmd->captions, "Caption of each panel, one per input (default: the file name)");
  sub->add_option("--font", cmd->font, "TrueType font for captions (missing: captions left out, with a warning)")
      ->capture_default_str();
  sub->add_option("--font-size", cmd->font_px, "Caption height in pixels")
      ->capture_default_str()
      ->check(whole_number_in(4, 512));
  sub->add_option("--error-to", cmd->error_reference,
                  "Colour the meshes by the distance of each vertex to this reference (a mesh, the exact "
                  "surface of builtin:NAME or a NURBS patch, or a point file): blue 0 to red at --error-max; the title gives the scale");
  sub->add_option("--error-max", cmd->error_max,
                  "With --error-to: the distance drawn red (default: the largest over all panels)")
      ->check(number_above(0));
  add_common_flags(*sub, cmd->common);
  add_threads_option(*sub, cmd->common.threads);
  sub->callback([cmd] { run_render(*cmd); });
}

}  // namespace envcrust::cli
