// Headless rendering of meshes, point clouds, balls and boundary loops into an RGB image in
// memory (ray tracing with Intel Embree; no GPU, no display). `io` encodes the PNG.
#pragma once

#include "envcrust/image.h"
#include "envcrust/types.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace envcrust::render {

/// An RGB colour, each channel in [0, 1], as displayed (sRGB: 0.5 is mid-grey on screen).
/// Lighting is computed in linear light and encoded back to sRGB. Image is in image.h.
struct Color {
  float r = 0, g = 0, b = 0;
};

enum class Shading { Smooth, Flat };

/// A triangle mesh. Front faces (the side the triangle's winding normal points to) get
/// `front`, back faces `back`, so an open surface reads as open. Non-orientable meshes are
/// drawn per triangle.
struct MeshLayer {
  TriangleMesh mesh;
  Color front{0.80f, 0.80f, 0.85f};
  Color back{0.85f, 0.45f, 0.35f};
  Shading shading = Shading::Smooth;
  bool use_wireframe = false;  ///< darken pixels near triangle edges
  /// One colour per vertex, interpolated across each triangle, instead of `front`/`back` (a
  /// value map, e.g. the error against a reference through heat_color); back faces get it
  /// at 70% brightness, so an open surface still reads as open. Empty: front and back.
  std::vector<Color> vertex_colors{};
};

/// A colour scale for values: t = 0 blue, then cyan, green, yellow, t = 1 red (t clamped to
/// [0, 1]; NaN reads 0).
Color heat_color(double t);

/// Spheres: points of a cloud (one radius for all) or polar balls (one radius each).
struct SphereLayer {
  std::vector<Point3> centres;
  /// One radius per centre, or a single radius for all; empty: auto (0.4% of the diagonal
  /// of the whole scene's bounding box).
  std::vector<double> radii;
  Color color{0.20f, 0.45f, 0.80f};
  float opacity = 1.0f;  ///< < 1 draws the spheres translucent (polar balls over a surface)
};

/// Closed polylines drawn as round tubes (boundary loops).
struct CurveLayer {
  std::vector<Polyline> loops;
  double radius = 0;  ///< 0: auto (0.6% of the scene diagonal)
  /// One colour per loop, cycling; empty: a built-in palette of distinct colours.
  std::vector<Color> colors;
};

/// What to draw.
struct Scene {
  std::vector<MeshLayer> meshes;
  std::vector<SphereLayer> spheres;
  std::vector<CurveLayer> curves;
};

/// Camera direction: the camera sits at azimuth `azimuth_deg` about +z from +x and elevation
/// `elevation_deg` above the xy-plane, and looks at the centre of the scene's bounding box;
/// +z is up in the image (at |elevation| 90, +y is up for top, -y for bottom views).
/// Presets: iso (az 45, el 30), front (az -90, el 0: camera on -y, looking along +y, x to
/// the right), top (az -90, el 90: looking down -z, x to the right, y up).
struct View {
  double azimuth_deg = 45.0;
  double elevation_deg = 30.0;
  static View iso() { return {45.0, 30.0}; }
  static View front() { return {-90.0, 0.0}; }
  static View top() { return {-90.0, 90.0}; }
};

/// Options of render_scene.
struct RenderOptions {
  int width = 800, height = 600;  ///< pixels, each in [16, 8192]
  View view{};
  Color background{1.0f, 1.0f, 1.0f};
  /// Samples per pixel along each axis (2: 4 rays per pixel) for anti-aliasing; [1, 4].
  int supersampling = 2;
  /// Empty border as a fraction of the image, on each side; [0, 0.45]. The camera is
  /// orthographic: the 8 corners of the scene's bounding box, projected onto the image plane,
  /// span exactly (1 - 2 margin) of the width or of the height, whichever is tighter, centred.
  /// Example: a unit sphere seen from the front in a square image spans 90% of it, so it
  /// covers pi/4 * 0.9^2 = 63.6% of the pixels.
  double margin = 0.05;
};

/// Render a scene with an orthographic camera (see RenderOptions::margin), a headlight and a
/// key light from the upper left (Lambert plus a weak Blinn highlight), meshes two-sided
/// (back faces in MeshLayer::back), translucent spheres by continuing the ray (up to 16
/// layers), and supersampling. Rows are traced in parallel; each pixel depends only on the
/// scene, so the result is deterministic: the same scene and options give the same bytes.
/// @throws InvalidInput when the scene is empty or holds a non-finite coordinate or a
///         triangle index out of range; InvalidOptions for a size or sampling out of range.
Image render_scene(const Scene& scene, const RenderOptions& options = {});

/// A font for captions, as the bytes of a TrueType/OpenType file (read by io).
struct Font {
  std::vector<std::uint8_t> data;
  int pixel_height = 18;
};

/// Check that FreeType can use `font` at its size, before anything is drawn with it.
/// @throws InvalidInput ("render: cannot use the font (FreeType error N)") or InvalidOptions
///         for a pixel_height outside [4, 512].
void check_font(const Font& font);

/// One panel of a grid: an image and an optional caption drawn under it.
struct Panel {
  Image image;
  std::string caption;
};

/// Options of compose_grid.
struct GridOptions {
  int rows = 0, columns = 0;  ///< 0, 0: one row of all panels; otherwise rows*columns >= panels
  int gap_px = 8;             ///< space between panels and around the grid
  std::string title;          ///< drawn above the grid when not empty
  Color background{1.0f, 1.0f, 1.0f};
  Color text{0.1f, 0.1f, 0.1f};
};

/// Lay panels out in a grid with captions and a title. Text needs `font` (no font: captions
/// and title are left out, the layout is the same).
/// Layout: cells are as large as the largest panel; panel i goes to row i / columns, column
/// i % columns, centred in its cell. With a gap g, a caption band c (c = 1.5 * pixel_height
/// of the font, or of Font{} without one, when any caption is non-empty, else 0) and a title
/// band t (the same height, when the title is non-empty): the cell of (row, col) starts at
/// x = g + col * (cell_w + g), y = g + t + row * (cell_h + c + g); its caption is centred in
/// the band below the cell. Image size: g + columns * (cell_w + g) by
/// g + t + rows * (cell_h + c + g).
/// @throws InvalidOptions when rows * columns is smaller than the number of panels, or
///         one of rows, columns is 0 and the other not, or gap_px < 0;
///         InvalidInput when there is no panel, a panel's pixel data does not match its size,
///         or the font data cannot be parsed; InvalidOptions for a font pixel_height outside
///         [4, 512].
Image compose_grid(const std::vector<Panel>& panels, const GridOptions& options,
                   const std::optional<Font>& font);

}  // namespace envcrust::render
