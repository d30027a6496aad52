// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Small analytic surfaces with known topology and geometry, for tests and benchmarks of the
// flattening: strongly concave strips, spherical caps, planar discs.

#ifndef CGAL_CONFORMAL_REMESHING_BENCHMARKS_TEST_SURFACES_H
#define CGAL_CONFORMAL_REMESHING_BENCHMARKS_TEST_SURFACES_H

#include <CGAL/Surface_mesh.h>
#include <CGAL/number_type_config.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace benchmarks {

/// Parameters of `make_wavy_c_strip()`.
struct Wavy_c_strip_parameters
{
  double inner_radius = 1.;
  double outer_radius = 2.;
  double opening_degrees = 20.;  ///< the gap of the C
  double amplitude = 0.6;        ///< height of the waves at the outer radius
  int waves = 8;                 ///< waves along the strip
  int radial_segments = 6;
  int angular_segments = 240;
};

/// A C-shaped strip (an annulus sector, a topological disc with a strongly concave boundary)
/// made wavy along its length, `z = amplitude * t * sin(waves * theta)` with `t` going from 0 on
/// the inner to 1 on the outer arc. The waves lengthen the outer arc, so a flattening that keeps
/// lengths near the boundary must close the gap of the C and overlap.
template <typename Point_3>
void make_wavy_c_strip(CGAL::Surface_mesh<Point_3>& mesh, const Wavy_c_strip_parameters& p = Wavy_c_strip_parameters())
{
  if(!(p.inner_radius > 0. && p.outer_radius > p.inner_radius && p.opening_degrees > 0. && p.opening_degrees < 360.
       && p.radial_segments >= 1 && p.angular_segments >= 2))
    throw std::invalid_argument("make_wavy_c_strip: invalid parameters");
  typedef typename CGAL::Surface_mesh<Point_3>::Vertex_index Vertex;
  mesh.clear();
  const double span = (360. - p.opening_degrees) * CGAL_PI / 180.;
  std::vector<Vertex> grid;
  for(int i = 0; i <= p.angular_segments; ++i)
    for(int j = 0; j <= p.radial_segments; ++j)
    {
      const double theta = span * i / p.angular_segments;
      const double t = double(j) / p.radial_segments;
      const double r = p.inner_radius + t * (p.outer_radius - p.inner_radius);
      grid.push_back(mesh.add_vertex(Point_3(r * std::cos(theta), r * std::sin(theta),
                                             p.amplitude * t * std::sin(p.waves * theta))));
    }
  auto at = [&](int i, int j) { return grid[i * (p.radial_segments + 1) + j]; };
  for(int i = 0; i < p.angular_segments; ++i)
    for(int j = 0; j < p.radial_segments; ++j)
    {
      mesh.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      mesh.add_face(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
}

/// A spherical cap of the unit sphere around the north pole, of polar angle
/// `cap_degrees`, as rings of triangles around the pole (a topological disc).
template <typename Point_3>
void make_spherical_cap(CGAL::Surface_mesh<Point_3>& mesh, double cap_degrees = 120., int rings = 16, int sectors = 48)
{
  if(!(cap_degrees > 0. && cap_degrees < 180. && rings >= 1 && sectors >= 3))
    throw std::invalid_argument("make_spherical_cap: invalid parameters");
  typedef typename CGAL::Surface_mesh<Point_3>::Vertex_index Vertex;
  mesh.clear();
  const Vertex pole = mesh.add_vertex(Point_3(0, 0, 1));
  std::vector<std::vector<Vertex> > ring(rings + 1);
  for(int k = 1; k <= rings; ++k)
    for(int s = 0; s < sectors; ++s)
    {
      const double phi = cap_degrees * CGAL_PI / 180. * k / rings;
      const double theta = 2 * CGAL_PI * (s + 0.5 * (k % 2)) / sectors;
      ring[k].push_back(mesh.add_vertex(Point_3(std::sin(phi) * std::cos(theta), std::sin(phi) * std::sin(theta), std::cos(phi))));
    }
  for(int s = 0; s < sectors; ++s)
    mesh.add_face(pole, ring[1][s], ring[1][(s + 1) % sectors]);
  for(int k = 1; k < rings; ++k)
    for(int s = 0; s < sectors; ++s)
    {
      const int t = (s + 1) % sectors;
      // Odd rings are turned by half a sector: split each quad along its shorter diagonal.
      if(k % 2 == 1)
      {
        mesh.add_face(ring[k][s], ring[k + 1][t], ring[k][t]);
        mesh.add_face(ring[k][s], ring[k + 1][s], ring[k + 1][t]);
      }
      else
      {
        mesh.add_face(ring[k][s], ring[k + 1][s], ring[k][t]);
        mesh.add_face(ring[k][t], ring[k + 1][s], ring[k + 1][t]);
      }
    }
}

} // namespace benchmarks
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_BENCHMARKS_TEST_SURFACES_H
