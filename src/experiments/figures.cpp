// Rendering a figure: each panel's scene, then the grid with captions.
#include "envcrust/errors.h"
#include "envcrust/experiments.h"

namespace envcrust::experiments {

render::Image render_figure(const Figure& figure, const FigureRenderOptions& options,
                            const std::optional<render::Font>& font) {
  std::vector<render::Panel> panels;
  for (const auto& spec : figure.panels) {
    render::Panel panel;
    panel.caption = spec.caption;
    render::RenderOptions ro;
    ro.width = options.panel_width;
    ro.height = options.panel_height;
    ro.supersampling = options.supersampling;
    ro.view = spec.view;
    if (spec.scene.meshes.empty() && spec.scene.spheres.empty() && spec.scene.curves.empty()) {
      // An empty result (a failed reconstruction) is a blank panel, not an error.
      panel.image.width = ro.width;
      panel.image.height = ro.height;
      panel.image.rgb.assign(static_cast<std::size_t>(ro.width) * ro.height * 3, 255);
    } else {
      panel.image = render::render_scene(spec.scene, ro);
    }
    panels.push_back(std::move(panel));
  }
  render::GridOptions grid;
  grid.title = figure.title;
  if (figure.columns > 0) {
    grid.columns = figure.columns;
    grid.rows = static_cast<int>((panels.size() + figure.columns - 1) / figure.columns);
  }
  return render::compose_grid(panels, grid, font);
}

}  // namespace envcrust::experiments
