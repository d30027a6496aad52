// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Reading a mesh file through CGAL's IO, with the input checks run on what the file holds
// before any halfedge data structure is built.

#ifndef CGAL_CONFORMAL_REMESHING_IO_READ_MESH_H
#define CGAL_CONFORMAL_REMESHING_IO_READ_MESH_H

#include <CGAL/Conformal_remeshing/Error.h>
#include <CGAL/Conformal_remeshing/check_mesh.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {

/// \ingroup PkgConformalRemeshingIO
/// Reads `filename` (OFF, OBJ, PLY or STL, ASCII or binary, chosen by the extension) into
/// `mesh`, and returns the input checks of what the file holds.
///
/// The file is read as a polygon soup and checked with `check_polygon_soup()`, so that defects
/// no halfedge data structure can hold (non-manifold edges, inconsistent orientation,
/// non-orientable surfaces) are reported instead of making the read fail. `mesh` is built only
/// when the soup is a valid polygon mesh; then the report also carries the topology of each
/// connected component (`topology_available`), and `mesh` is cleared otherwise. The STL reader
/// merges the identical corners of its triangle soup into shared vertices.
///
/// \tparam PolygonMesh a model of `MutableFaceGraph` with an internal point property map
///
/// \throws Error with `Error_code::UNSUPPORTED_FORMAT` for an unknown extension, and with
///         `Error_code::FILE_NOT_READABLE` when the file cannot be opened or parsed; the message
///         names the file and the reason.
template <typename PolygonMesh>
Mesh_check_report read_and_check_mesh(const std::string& filename, PolygonMesh& mesh)
{
  typedef typename boost::property_map<PolygonMesh, CGAL::vertex_point_t>::type Vertex_point_map;
  typedef typename boost::property_traits<Vertex_point_map>::value_type Point;
  typedef typename CGAL::Kernel_traits<Point>::Kernel Kernel;

  const std::string::size_type dot = filename.find_last_of('.');
  std::string extension = (dot == std::string::npos) ? std::string() : filename.substr(dot + 1);
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if(extension != "off" && extension != "obj" && extension != "ply" && extension != "stl")
    throw Error(Error_code::UNSUPPORTED_FORMAT,
                "cannot read '" + filename + "': unsupported file extension '"
                + (dot == std::string::npos ? std::string() : "." + extension)
                + "' (expected .off, .obj, .ply or .stl)");

  {
    std::ifstream probe(filename, std::ios::binary);
    if(!probe)
      throw Error(Error_code::FILE_NOT_READABLE, "cannot read '" + filename + "': " + std::strerror(errno));
    if(probe.peek() == std::ifstream::traits_type::eof())
      throw Error(Error_code::FILE_NOT_READABLE, "cannot read '" + filename + "': the file is empty");
  }

  std::vector<Point> points;
  std::vector<std::vector<std::size_t> > polygons;
  bool parsed = false;
  try
  {
    parsed = CGAL::IO::read_polygon_soup(filename, points, polygons, CGAL::parameters::verbose(false));
  }
  catch(const std::exception& e)
  {
    throw Error(Error_code::FILE_NOT_READABLE, "cannot read '" + filename + "': " + e.what());
  }
  // CGAL's readers accept some malformed files; what no mesh format allows is refused here.
  std::string problem;
  if(!parsed)
    problem = "syntax error or truncated data";
  else if(extension == "stl" && polygons.empty())
    problem = "no complete triangle";
  for(std::size_t f = 0; problem.empty() && f < polygons.size(); ++f)
    if(polygons[f].size() < 3)
      problem = "face " + std::to_string(f) + " has fewer than 3 vertices";
  if(!problem.empty())
  {
    for(char& c : extension)
      c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    throw Error(Error_code::FILE_NOT_READABLE,
                "cannot read '" + filename + "': not a valid " + extension + " file (" + problem + ")");
  }

  Mesh_check_report report = check_polygon_soup<Kernel>(points, polygons);

  clear(mesh);
  const bool buildable = report.count(Mesh_defect::INVALID_VERTEX_INDEX) == 0
                         && report.count(Mesh_defect::NON_MANIFOLD_VERTEX) == 0
                         && Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(polygons);
  if(buildable)
  {
    Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, mesh);
    report.topology_available = !polygons.empty();
    if(report.topology_available)
      report.components = internal::component_topologies(mesh);
  }
  return report;
}

} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_IO_READ_MESH_H
