// envcrust.read_points(), read_mesh() and write_mesh(), on the library's readers and writers.
#include "io_binding.h"

#include "arrays.h"

#include "envcrust/io.h"

#include <pybind11/stl/filesystem.h>

#include <filesystem>

namespace envcrust::python {
namespace py = pybind11;
namespace {

// {"points", "normals" (or None), "colors" (or None), and each scalar column by name}.
py::dict points_dict(const AttributedPoints& read) {
  py::dict out;
  out["points"] = points_array(read.points.points);
  out["normals"] = read.points.has_normals() ? py::object(vectors_array(read.points.normals)) : py::none();
  out["colors"] = read.attributes.has_colours() ? py::object(colours_array(read.attributes.colours)) : py::none();
  py::dict scalars;
  for (std::size_t c = 0; c < read.attributes.names.size(); ++c)
    scalars[py::str(read.attributes.names[c])] = py::array_t<float>(
        static_cast<py::ssize_t>(read.attributes.scalars[c].size()), read.attributes.scalars[c].data());
  out["scalars"] = scalars;
  return out;
}

py::dict read_points(const std::filesystem::path& path) {
  AttributedPoints read;
  {
    py::gil_scoped_release released;
    read = io::read_attributed_points(path);
  }
  return points_dict(read);
}

py::tuple read_mesh(const std::filesystem::path& path) {
  TriangleMesh mesh;
  {
    py::gil_scoped_release released;
    mesh = io::read_triangle_mesh(path);
  }
  return py::make_tuple(points_array(mesh.vertices), triangles_array(mesh.triangles));
}

void write_mesh(const std::filesystem::path& path, const py::handle& vertices, const py::handle& faces,
                const py::handle& colors, const py::handle& normals) {
  TriangleMesh mesh;
  mesh.vertices = to_points(vertices, "vertices");
  mesh.triangles = to_triangles(faces, mesh.vertices.size());
  io::MeshVertexData data;
  if (!normals.is_none()) {
    data.normals = to_vectors(normals, "normals");
    if (data.normals.size() != mesh.vertices.size())
      throw py::value_error("normals must have " + std::to_string(mesh.vertices.size()) +
                            " rows (one per vertex), got " + std::to_string(data.normals.size()));
  }
  if (!colors.is_none()) data.attributes.colours = to_colours(colors, mesh.vertices.size());
  py::gil_scoped_release released;
  io::write_mesh(path, mesh, data);
}

}  // namespace

void register_io(py::module_& module) {
  module.def("read_points", &read_points, py::arg("path"),
             "Read a point file (.xyz .pts .txt .csv .ply .las, or a mesh file's vertices) as `envcrust reconstruct` "
             "reads it.\nReturns a dict: points (n x 3 float64), normals (n x 3 or None), colors (n x 3 uint8 or "
             "None), scalars (name -> n float32, e.g. intensity).\nRaises envcrust.IoError naming the file and the "
             "problem (\"scan.xyz:12: expected at least 3 numbers ..., got 2\").");
  module.def("read_mesh", &read_mesh, py::arg("path"),
             "Read a mesh (.off .obj .ply .stl); polygons are split into triangles.\nReturns (vertices n x 3 "
             "float64, faces m x 3 int64). Raises envcrust.IoError naming the file.");
  module.def("write_mesh", &write_mesh, py::arg("path"), py::arg("vertices"), py::arg("faces"),
             py::arg("colors") = py::none(), py::arg("normals") = py::none(),
             "Write a triangle mesh (.ply binary with float positions, colours and normals; .obj; .off; .stl), "
             "through a temporary file renamed when complete.\ncolors: n x 3, 0..255 integers or 0..1 floats. "
             "Raises ValueError for arrays of the wrong shape or indices out of range, envcrust.IoError naming the "
             "file (\"x.abc: unknown extension '.abc' ...\").");
}

}  // namespace envcrust::python
