// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// libFuzzer target: conformal_flatten() on small meshes decoded from the bytes.
//
// The defined outcomes are: an Error, or a flattening whose status says what happened. Whenever
// the status is not NOT_AN_EMBEDDING (SUCCESS, or NOT_CONVERGED with the flow's best state), the
// patch region must be an embedding, which is checked again here from the result alone with
// exact predicates (overlaps counted too), and the map back to the surface must land in input
// faces. Anything else (a crash, a sanitizer report, another exception) is a bug.
//
// Layout of an input: a header of 10 bytes, then 3 bytes per grid vertex and 1 byte per cell
// (missing bytes read as 0):
//   0 shape: a sheet, a tube (the grid closed around; two boundary loops), or a sheet scaled by
//     2^e (e from byte 8, up to +-1000: underflows, overflows, huge and tiny coordinates)
//   1, 2 grid cells along x and y (1 to 7; a tube has at least 3 around)
//   3, 4 in-plane and height perturbation amplitudes (0 to beyond folding cells over)
//   5 annulus inner radius, 6 Newton iterations (a few to force NOT_CONVERGED, or 50),
//   7 which boundary loop to weld, 9 maximum edge length (none, or a fraction of a cell)
//   per vertex: x, y, z offsets; per cell: bit 0 picks the diagonal, a value >= 0xe0 drops the
//   cell (holes; cells that disconnect the grid or pinch a vertex are refused by the checks)

#include "fuzz_support.h"

#include <CGAL/Conformal_remeshing/Error.h>
#include <CGAL/Conformal_remeshing/check_mesh.h>
#include <CGAL/Conformal_remeshing/check_planar_embedding.h>
#include <CGAL/Conformal_remeshing/conformal_flatten.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

namespace CR = CGAL::Conformal_remeshing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;

namespace {

// FUZZ_FLATTEN_VERBOSE=1 prints the outcome of each input (when replaying files).
const bool verbose = std::getenv("FUZZ_FLATTEN_VERBOSE") != nullptr;

void fail(const char* what) { fuzz::fail("fuzz_flatten", what); }

// The boundary loops of a set of triangles (edges with no opposite), the one enclosing the
// largest area first; empty if a vertex has two outgoing boundary edges (a pinch).
std::vector<std::vector<std::size_t> > boundary_loops(const std::vector<CGAL::Epick::Point_2>& uv,
                                                      const std::vector<std::array<std::size_t, 3> >& triangles)
{
  std::map<std::pair<std::size_t, std::size_t>, int> directed;
  for(const auto& t : triangles)
    for(int c = 0; c < 3; ++c)
      ++directed[{t[c], t[(c + 1) % 3]}];
  std::map<std::size_t, std::size_t> next;
  for(const auto& e : directed)
    if(directed.count({e.first.second, e.first.first}) == 0)
      if(!next.emplace(e.first.first, e.first.second).second)
        return {};
  std::vector<std::vector<std::size_t> > loops;
  std::map<std::size_t, bool> used;
  for(const auto& start : next)
  {
    if(used[start.first])
      continue;
    loops.emplace_back();
    for(std::size_t v = start.first; !used[v];)
    {
      used[v] = true;
      loops.back().push_back(v);
      const auto it = next.find(v);
      if(it == next.end())
        return {};
      v = it->second;
    }
  }
  auto area = [&](const std::vector<std::size_t>& loop) {
    double a = 0.;
    for(std::size_t i = 0; i < loop.size(); ++i)
    {
      const CGAL::Epick::Point_2 &p = uv[loop[i]], &q = uv[loop[(i + 1) % loop.size()]];
      a += p.x() * q.y() - q.x() * p.y();
    }
    return std::abs(a);
  };
  for(std::size_t l = 1; l < loops.size(); ++l)
    if(area(loops[l]) > area(loops[0]))
      std::swap(loops[0], loops[l]);
  return loops;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  fuzz::Bytes bytes(data, size);
  const int shape = bytes.next() % 3;
  const bool tube = shape == 1;
  int nx = 1 + bytes.next() % 7;
  const int ny = 1 + bytes.next() % 7;
  if(tube && nx < 3)
    nx = 3;
  static const double amplitudes[] = {0., 0.05, 0.3, 0.49, 0.7, 2.};
  const double amplitude = amplitudes[bytes.next() % 6];
  const double height = amplitudes[bytes.next() % 6];
  static const double radii[] = {0.3, 0.3, 0.1, 0.5, 0.9, 0.01, 0.99};
  const double inner_radius = radii[bytes.next() % 7];
  const std::uint8_t iterations_byte = bytes.next();
  const int iterations = iterations_byte < 0x40 ? 1 + iterations_byte % 4 : 50;
  const std::uint8_t welded_byte = bytes.next();
  const int exponent = shape == 2 ? (int(bytes.next()) - 128) * 8 : (bytes.next(), 0);
  const std::uint8_t length_byte = bytes.next();
  // In grid cells, like the coordinates: a length meant for another scale is refused after a
  // million splits, too slow for a fuzzer (the tests check that refusal).
  const double maximum_edge_length = length_byte < 0xc0 ? 0. : std::ldexp(0.25 + (length_byte - 0xc0) / 32., exponent);

  // Grid vertices (i, j); a tube identifies column nx with column 0.
  const int columns = tube ? nx : nx + 1;
  std::vector<Point> points;
  for(int j = 0; j <= ny; ++j)
    for(int i = 0; i < columns; ++i)
    {
      const double dx = amplitude * bytes.signed_unit(), dy = amplitude * bytes.signed_unit(),
                   dz = height * bytes.signed_unit();
      double x = i + dx, y = j + dy, z = dz;
      if(tube)
      {
        const double angle = 2. * 3.141592653589793 * (i + dx) / nx, r = nx / 6.28 + dz;
        x = r * std::cos(angle);
        z = r * std::sin(angle);
      }
      points.emplace_back(std::ldexp(x, exponent), std::ldexp(y, exponent), std::ldexp(z, exponent));
    }
  auto id = [&](int i, int j) { return std::size_t(j * columns + i % columns); };
  std::vector<std::vector<std::size_t> > polygons;
  for(int j = 0; j < ny; ++j)
    for(int i = 0; i < nx; ++i)
    {
      const std::uint8_t cell = bytes.next();
      if(cell >= 0xe0)
        continue;
      const std::size_t a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if(cell & 1)
      {
        polygons.push_back({a, b, c});
        polygons.push_back({a, c, d});
      }
      else
      {
        polygons.push_back({a, b, d});
        polygons.push_back({b, c, d});
      }
    }
  // Drop the vertices of dropped cells, so that only real defects remain.
  std::vector<std::size_t> new_index(points.size(), std::size_t(-1));
  std::vector<Point> used_points;
  for(auto& polygon : polygons)
    for(std::size_t& v : polygon)
    {
      if(new_index[v] == std::size_t(-1))
      {
        new_index[v] = used_points.size();
        used_points.push_back(points[v]);
      }
      v = new_index[v];
    }
  if(polygons.empty() || !CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(polygons))
    return 0;
  Mesh mesh;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(used_points, polygons, mesh);

  // The loop to weld: any border halfedge, by the byte.
  std::vector<Mesh::Halfedge_index> border;
  for(Mesh::Halfedge_index h : mesh.halfedges())
    if(mesh.is_border(h))
      border.push_back(h);
  CR::Conformal_flattening flat;
  try
  {
    auto np = CR::parameters::annulus_inner_radius(
      inner_radius, CR::parameters::maximum_edge_length(maximum_edge_length,
                                                        CGAL::parameters::number_of_iterations(iterations)));
    flat = (welded_byte & 1) && !border.empty()
             ? CR::conformal_flatten(mesh, CR::parameters::welded_boundary(border[(welded_byte >> 1) % border.size()], np))
             : CR::conformal_flatten(mesh, np);
  }
  catch(const CR::Error& e)
  {
    if(verbose)
      std::fprintf(stderr, "fuzz_flatten: %zu vertices: Error: %s\n", std::size_t(num_vertices(mesh)), e.what());
    if(e.code() == CR::Error_code::SUCCESS || std::string(e.what()).empty())
      fail("an Error without a code or a message");
    return 0;
  }

  const CR::Flattening_report& report = flat.report;
  if(verbose)
    std::fprintf(stderr, "fuzz_flatten: %zu vertices, %zu loops: %s (%d iterations, curvature error %g), %s\n",
                 std::size_t(num_vertices(mesh)), report.boundary_loops, CR::error_message(report.status), report.iterations,
                 report.curvature_error, report.embedding.summary().c_str());
  if(report.status != CR::Error_code::SUCCESS && report.status != CR::Error_code::NOT_CONVERGED
     && report.status != CR::Error_code::NOT_AN_EMBEDDING)
    fail("an unexpected status");
  if(report.status == CR::Error_code::NOT_AN_EMBEDDING)
  {
    if(report.embedding.is_embedding() || report.embedding.summary() == "embedding")
      fail("NOT_AN_EMBEDDING without a failed check");
    return 0;
  }
  if((report.status == CR::Error_code::SUCCESS) != report.converged)
    fail("status and convergence disagree");

  // Not refused: the patch region must be an embedding, checked again from the result alone.
  if(!report.embedding.is_embedding())
    fail("a failed embedding check reported as success");
  if(flat.uv.size() != num_vertices(mesh) || flat.triangles.empty() || flat.outer_boundary.empty()
     || flat.holes.size() + 1 != report.boundary_loops)
    fail("a flattening of the wrong size");
  std::vector<std::array<std::size_t, 3> > triangles;
  for(const auto& t : flat.triangles)
  {
    for(int v : t)
      if(v < 0 || std::size_t(v) >= flat.layout.size())
        fail("a triangle index out of range");
    triangles.push_back({{std::size_t(t[0]), std::size_t(t[1]), std::size_t(t[2])}});
  }
  const std::vector<std::vector<std::size_t> > loops = boundary_loops(flat.layout, triangles);
  if(loops.size() != report.boundary_loops)
    fail("the patch region has a different number of boundary loops than the input");
  const CR::Planar_embedding_report again = CR::check_planar_embedding(flat.layout, triangles, loops, true);
  if(!again.is_embedding())
  {
    std::fprintf(stderr, "fuzz_flatten: %s\n", again.summary().c_str());
    fail("a flattening reported as an embedding is not one");
  }
  for(const auto& p : flat.uv)
    if(!std::isfinite(p.x()) || !std::isfinite(p.y()))
      fail("a non-finite uv");

  // The map back onto the surface: every triangle's centroid lands inside an input face.
  for(std::size_t t = 0; t < flat.triangles.size(); ++t)
  {
    CR::Domain_point q;
    try
    {
      q = flat.to_surface(t, {{1. / 3, 1. / 3, 1. / 3}});
    }
    catch(const CR::Error&)
    {
      fail("to_surface() failed on a flattening reported as an embedding");
    }
    double sum = 0.;
    for(double b : q.input_coordinates)
    {
      if(!(b >= -1e-6))
        fail("to_surface() gave negative barycentric coordinates");
      sum += b;
    }
    if(q.input_face >= num_faces(mesh) || !(std::abs(sum - 1.) < 1e-6))
      fail("to_surface() gave an invalid input location");
  }
  return 0;
}
