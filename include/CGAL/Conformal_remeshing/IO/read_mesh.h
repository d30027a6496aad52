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
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <map>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace internal {

// Reads `filename` if it is a binary STL file (its size matches the triangle count of its
// header) and returns false otherwise. CGAL's STL reader merges corners through a std::map,
// which merges a NaN corner with an arbitrary vertex and so hides it; here only finite
// corners are merged, so non-finite coordinates reach the input checks.
template <typename Point>
bool read_binary_STL(const std::string& filename, std::vector<Point>& points,
                     std::vector<std::vector<std::size_t> >& polygons)
{
  std::ifstream in(filename, std::ios::binary | std::ios::ate);
  if(!in)
    return false;
  const std::streamoff size = in.tellg();
  if(size < 84)
    return false;
  in.seekg(80);
  unsigned char count_bytes[4];
  in.read(reinterpret_cast<char*>(count_bytes), 4);
  const std::uint64_t count = std::uint64_t(count_bytes[0]) | (std::uint64_t(count_bytes[1]) << 8)
                              | (std::uint64_t(count_bytes[2]) << 16) | (std::uint64_t(count_bytes[3]) << 24);
  if(!in || std::uint64_t(size) != 84 + 50 * count)
    return false;

  auto lexicographic = [](const std::array<float, 3>& a, const std::array<float, 3>& b) { return a < b; };
  std::map<std::array<float, 3>, std::size_t, decltype(lexicographic)> index_of(lexicographic);
  points.clear();
  polygons.assign(count, std::vector<std::size_t>(3));
  for(std::uint64_t t = 0; t < count; ++t)
  {
    unsigned char record[50];
    in.read(reinterpret_cast<char*>(record), 50);
    if(!in)
      return false;
    for(int corner = 0; corner < 3; ++corner)
    {
      std::array<float, 3> xyz;
      for(int k = 0; k < 3; ++k)
      {
        const unsigned char* b = record + 12 * (corner + 1) + 4 * k; // after the facet normal
        const std::uint32_t bits = std::uint32_t(b[0]) | (std::uint32_t(b[1]) << 8)
                                   | (std::uint32_t(b[2]) << 16) | (std::uint32_t(b[3]) << 24);
        std::memcpy(&xyz[k], &bits, sizeof(float));
      }
      const bool finite = std::isfinite(xyz[0]) && std::isfinite(xyz[1]) && std::isfinite(xyz[2]);
      std::size_t index = points.size();
      if(finite)
      {
        const auto inserted = index_of.emplace(xyz, index);
        index = inserted.first->second;
      }
      if(index == points.size())
        points.push_back(Point(xyz[0], xyz[1], xyz[2]));
      polygons[t][corner] = index;
    }
  }
  return true;
}

} // namespace internal

/// \ingroup PkgConformalRemeshingIO
/// Reads `filename` (OFF, OBJ, PLY or STL, ASCII or binary, chosen by the extension) into
/// `mesh`, and returns the input checks of what the file holds.
///
/// The file is read as a polygon soup and checked with `check_polygon_soup()`, so that defects
/// no halfedge data structure can hold (non-manifold edges, inconsistent orientation,
/// non-orientable surfaces) are reported instead of making the read fail. `mesh` is built only
/// when the soup is a valid polygon mesh; then the report also carries the topology of each
/// connected component (`topology_available`), and `mesh` is cleared otherwise. The STL readers
/// merge the identical corners of the file's triangle soup into shared vertices (corners with
/// non-finite coordinates are never merged, so that the checks see them).
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
    parsed = (extension == "stl" && internal::read_binary_STL(filename, points, polygons))
             || CGAL::IO::read_polygon_soup(filename, points, polygons, CGAL::parameters::verbose(false));
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
