// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// libFuzzer target: the input checks on polygon soups decoded from the bytes (no file format in
// the way), the mesh built from a soup that is one, and the verifier of a mesh against itself.
//
// Layout of an input: the number of points (1 byte), each coordinate (1 byte: a small lattice
// value, so that collinear faces and duplicated points are common; or a marker and 8 raw bytes:
// NaN, infinities, denormals, 1e300), then the number of faces (1 byte) and each face (its size,
// then its indices, 1 byte each, which may point past the last point).

#include "fuzz_support.h"

#include <CGAL/Conformal_remeshing/check_mesh.h>
#include <CGAL/Conformal_remeshing/mesh_quality.h>
#include <CGAL/Conformal_remeshing/verify_remesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace CR = CGAL::Conformal_remeshing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;

namespace {

void fail(const char* what) { fuzz::fail("fuzz_check_soup", what); }

// A coordinate: a small lattice value, so that collinear faces and duplicated points are common,
// or after a marker byte any double.
double next_coordinate(fuzz::Bytes& bytes)
{
  const std::uint8_t b = bytes.next();
  return b < 0xf0 ? (int(b % 16) - 8) * 0.5 : bytes.raw_double();
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  fuzz::Bytes bytes(data, size);
  std::vector<Point> points(bytes.next() % 24);
  for(Point& p : points)
  {
    const double x = next_coordinate(bytes), y = next_coordinate(bytes), z = next_coordinate(bytes);
    p = Point(x, y, z);
  }
  std::vector<std::vector<std::size_t> > polygons(bytes.next() % 48);
  for(std::vector<std::size_t>& polygon : polygons)
  {
    polygon.resize(bytes.next() % 6);
    for(std::size_t& v : polygon)
      v = bytes.next() % (points.size() + 2);
  }

  const CR::Mesh_check_report report = CR::check_polygon_soup<K>(points, polygons);
  if(report.summary().empty() || report.number_of_faces != polygons.size())
    fail("inconsistent soup report");

  // Build a mesh where read_and_check_mesh() would: then check_mesh() must find the same defects.
  const bool buildable = !polygons.empty() && report.count(CR::Mesh_defect::INVALID_VERTEX_INDEX) == 0
                         && report.count(CR::Mesh_defect::NON_MANIFOLD_VERTEX) == 0
                         && CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(polygons);
  if(report.is_valid() && !buildable)
    fail("a valid soup is not a polygon mesh");
  if(!buildable)
    return 0;
  Mesh mesh;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  const CR::Mesh_check_report again = CR::check_mesh(mesh);
  if(again.defects.size() != report.defects.size())
    fail("check_mesh() and check_polygon_soup() disagree on the defects");
  for(std::size_t i = 0; i < report.defects.size(); ++i)
    if(again.defects[i].defect != report.defects[i].defect || again.defects[i].count != report.defects[i].count)
      fail("check_mesh() and check_polygon_soup() disagree on a defect count");
  if(!again.topology_available)
    fail("no topology for a mesh built from a soup");
  if(!report.is_valid())
    return 0;

  // The measures are computed in double precision: at extreme scales (squares that overflow or
  // underflow) or on slivers a valid triangle may measure 0 degrees, but never NaN.
  const CR::Mesh_quality_report q = CR::mesh_quality(mesh);
  if(q.number_of_faces != num_faces(mesh) || !(q.minimum_angle.min >= 0.) || !(q.maximum_angle.max <= 180.))
    fail("a valid mesh with angles that are not numbers in [0, 180]");

  // A valid mesh is a faithful remeshing of itself, whatever its geometry.
  try
  {
    const CR::Remesh_verification v = CR::verify_remesh<CGAL::Sequential_tag>(mesh, mesh);
    if(!v.valid_triangle_mesh || !v.manifold || !v.topology_kept || !v.on_input_surface || !v.locations_match
       || !v.self_intersections_checked)
      fail("a valid mesh fails the verification against itself");
  }
  catch(const CR::Error& e)
  {
    // Only coordinates whose squares overflow may be refused.
    if(e.code() != CR::Error_code::INVALID_INPUT)
      fail("verify_remesh() failed with an unexpected error");
  }

  // The parameterization check never trips on what the soup holds: its xy projection.
  auto uv = mesh.add_property_map<Mesh::Vertex_index, CGAL::Epick::Point_2>("v:uv").first;
  for(auto v : mesh.vertices())
    uv[v] = CGAL::Epick::Point_2(mesh.point(v).x(), mesh.point(v).y());
  const CR::Parameterization_verification p = CR::verify_parameterization(mesh, uv);
  if(p.summary().empty())
    fail("empty parameterization summary");
  return 0;
}
