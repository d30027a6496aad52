// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Pictures of a conformal flattening, in the spirit of the paper's Fig. 2 and 7: the welded
// domain (patch, hole fills and annulus in different colours), the patch's domain with a
// checkerboard drawn in the plane, a checkerboard texture, and a textured 3D view rendered in
// software so that the preserved right angles can be seen without a mesh viewer.

#ifndef CGAL_CONFORMAL_REMESHING_TOOLS_FLATTENING_PICTURES_H
#define CGAL_CONFORMAL_REMESHING_TOOLS_FLATTENING_PICTURES_H

#include "png_writer.h"

#include <CGAL/Conformal_remeshing/conformal_flatten.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace Conformal_remeshing_tools {

namespace CR = CGAL::Conformal_remeshing;

// Maps the plane's bounding box of some points onto a square picture (y upwards).
class Plane_view
{
public:
  Plane_view(const std::vector<CGAL::Epick::Point_2>& points, double size, double margin)
    : size_(size), margin_(margin)
  {
    for(const auto& p : points)
      box_ += p.bbox();
    extent_ = (std::max)(box_.xmax() - box_.xmin(), box_.ymax() - box_.ymin());
    if(!(extent_ > 0.))
      extent_ = 1.;
  }
  double x(const CGAL::Epick::Point_2& p) const { return margin_ + (p.x() - box_.xmin()) / extent_ * (size_ - 2 * margin_); }
  double y(const CGAL::Epick::Point_2& p) const { return size_ - margin_ - (p.y() - box_.ymin()) / extent_ * (size_ - 2 * margin_); }
  double scale() const { return (size_ - 2 * margin_) / extent_; }
  const CGAL::Bbox_2& box() const { return box_; }
  double extent() const { return extent_; }

private:
  double size_, margin_, extent_ = 1.;
  CGAL::Bbox_2 box_;
};

inline void svg_polygon_path(std::ostringstream& svg, const Plane_view& view, const std::vector<CR::Domain_point>& loop)
{
  for(std::size_t i = 0; i < loop.size(); ++i)
    svg << (i == 0 ? "M" : "L") << view.x(loop[i].uv) << " " << view.y(loop[i].uv) << " ";
  svg << "Z ";
}

// The whole welded disc, laid out flat: patch blue, hole fills orange, annulus green.
inline std::string welded_domain_svg(const CR::Conformal_flattening& f)
{
  const double size = 900;
  const Plane_view view(f.layout, size, 20);
  std::ostringstream svg;
  svg << "<?xml version='1.0' encoding='UTF-8'?>\n<svg xmlns='http://www.w3.org/2000/svg' width='" << size
      << "' height='" << size << "' viewBox='0 0 " << size << " " << size << "'>\n<rect width='100%' height='100%' fill='white'/>\n";
  const CR::Intrinsic_triangulation<double>& tri = f.triangulation;
  for(int t = 0; t < tri.number_of_faces(); ++t)
  {
    const char* colour = f.face_region[t] == CR::Welded_region::PATCH       ? "#9ecae1"
                         : f.face_region[t] == CR::Welded_region::HOLE_FILL ? "#fdae6b"
                                                                            : "#c7e9c0";
    svg << "<path d='";
    for(int c = 0; c < 3; ++c)
    {
      const auto& p = f.layout[tri.vertex(t, c)];
      svg << (c == 0 ? "M" : "L") << view.x(p) << " " << view.y(p) << " ";
    }
    svg << "Z' fill='" << colour << "' stroke='#555555' stroke-width='0.15'/>\n";
  }
  svg << "<path d='";
  svg_polygon_path(svg, view, f.outer_boundary);
  for(const auto& hole : f.holes)
    svg_polygon_path(svg, view, hole);
  svg << "' fill='none' stroke='black' stroke-width='1.2'/>\n</svg>\n";
  return svg.str();
}

// The patch's planar domain with a checkerboard of `squares` squares across, clipped to it.
inline std::string checkerboard_svg(const CR::Conformal_flattening& f, int squares = 24)
{
  std::vector<CGAL::Epick::Point_2> domain;
  for(const auto& q : f.outer_boundary)
    domain.push_back(q.uv);
  const double size = 900;
  const Plane_view view(domain, size, 20);
  std::ostringstream outline;
  svg_polygon_path(outline, view, f.outer_boundary);
  for(const auto& hole : f.holes)
    svg_polygon_path(outline, view, hole);

  std::ostringstream svg;
  svg << "<?xml version='1.0' encoding='UTF-8'?>\n<svg xmlns='http://www.w3.org/2000/svg' width='" << size
      << "' height='" << size << "' viewBox='0 0 " << size << " " << size << "'>\n<rect width='100%' height='100%' fill='white'/>\n"
      << "<defs><clipPath id='domain'><path clip-rule='evenodd' d='" << outline.str() << "'/></clipPath></defs>\n"
      << "<g clip-path='url(#domain)'>\n<rect width='100%' height='100%' fill='#fff7bc'/>\n";
  const double cell = (size - 40) / squares;
  for(int i = 0; i < squares; ++i)
    for(int j = 0; j < squares; ++j)
      if((i + j) % 2 == 0)
        svg << "<rect x='" << 20 + i * cell << "' y='" << 20 + j * cell << "' width='" << cell << "' height='" << cell
            << "' fill='#cc4c02'/>\n";
  svg << "</g>\n<path d='" << outline.str() << "' fill='none' stroke='black' stroke-width='1.5'/>\n</svg>\n";
  return svg.str();
}

// A parameterization without welding (uv of the input's vertices, its triangles and boundary
// loops), as the paper's Fig. 2 (b) shows one: every triangle translucent, so that where the map
// overlaps itself the layers add up to darker blue, folded (negatively oriented) triangles red,
// and the boundary loops, which cross where the map overlaps, in black.
inline std::string unwelded_parameterization_svg(const std::vector<CGAL::Epick::Point_2>& uv,
                                                 const std::vector<std::array<std::size_t, 3> >& triangles,
                                                 const std::vector<std::vector<std::size_t> >& loops)
{
  const double size = 900;
  const Plane_view view(uv, size, 20);
  std::ostringstream svg;
  svg << "<?xml version='1.0' encoding='UTF-8'?>\n<svg xmlns='http://www.w3.org/2000/svg' width='" << size
      << "' height='" << size << "' viewBox='0 0 " << size << " " << size << "'>\n<rect width='100%' height='100%' fill='white'/>\n";
  for(const auto& t : triangles)
  {
    const auto &a = uv[t[0]], &b = uv[t[1]], &c = uv[t[2]];
    const bool folded = CGAL::orientation(a, b, c) != CGAL::LEFT_TURN;
    svg << "<path d='M" << view.x(a) << " " << view.y(a) << " L" << view.x(b) << " " << view.y(b) << " L" << view.x(c)
        << " " << view.y(c) << " Z' fill='" << (folded ? "#e31a1c' fill-opacity='0.9'" : "#2171b5' fill-opacity='0.25'")
        << "/>\n";
  }
  svg << "<path d='";
  for(const auto& loop : loops)
    for(std::size_t i = 0; i <= loop.size(); ++i)
      svg << (i == 0 ? "M" : "L") << view.x(uv[loop[i % loop.size()]]) << " " << view.y(uv[loop[i % loop.size()]]) << " ";
  svg << "' fill='none' stroke='black' stroke-width='1.2'/>\n</svg>\n";
  return svg.str();
}

// A texture of `squares` x `squares` checks.
inline Rgb_image checker_texture(int pixels = 512, int squares = 16)
{
  Rgb_image image(pixels, pixels);
  for(int y = 0; y < pixels; ++y)
    for(int x = 0; x < pixels; ++x)
      image.set(x, y, ((x * squares / pixels + y * squares / pixels) % 2) ? std::array<std::uint8_t, 3>{{204, 76, 2}}
                                                                            : std::array<std::uint8_t, 3>{{255, 247, 188}});
  return image;
}

// Texture coordinates in [0, 1]: the uv scaled uniformly (so that squares stay square).
inline std::vector<std::array<double, 2> > normalized_texture_coordinates(const std::vector<CGAL::Epick::Point_2>& uv)
{
  const Plane_view view(uv, 1., 0.);
  std::vector<std::array<double, 2> > t;
  for(const auto& p : uv)
    t.push_back({{(p.x() - view.box().xmin()) / view.extent(), (p.y() - view.box().ymin()) / view.extent()}});
  return t;
}

// Renders triangles in 3D (orthographic, seen along `view_direction`, z-buffered, Lambert
// shading) with the checkerboard of `squares` checks across the texture coordinates.
inline Rgb_image render_textured(const std::vector<std::array<double, 3> >& points,
                                 const std::vector<std::array<std::size_t, 3> >& triangles,
                                 const std::vector<std::array<double, 2> >& texture, std::array<double, 3> view_direction,
                                 int pixels = 900, int squares = 16)
{
  typedef std::array<double, 3> V;
  auto cross = [](const V& a, const V& b) { return V{{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}}; };
  auto dot = [](const V& a, const V& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  auto unit = [&](V a) { const double n = std::sqrt(dot(a, a)); return V{{a[0] / n, a[1] / n, a[2] / n}}; };
  const V d = unit(view_direction);
  const V right = unit(cross(std::abs(d[2]) < 0.9 ? V{{0., 0., 1.}} : V{{1., 0., 0.}}, d));
  const V up = cross(d, right);

  std::vector<std::array<double, 3> > screen; // x, y, depth
  double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
  for(const V& p : points)
  {
    screen.push_back({{dot(p, right), dot(p, up), dot(p, d)}});
    xmin = (std::min)(xmin, screen.back()[0]);
    xmax = (std::max)(xmax, screen.back()[0]);
    ymin = (std::min)(ymin, screen.back()[1]);
    ymax = (std::max)(ymax, screen.back()[1]);
  }
  const double extent = (std::max)(xmax - xmin, ymax - ymin), margin = 10.;
  const double s = (pixels - 2 * margin) / (extent > 0. ? extent : 1.);
  for(auto& q : screen)
  {
    q[0] = margin + (q[0] - xmin) * s + 0.5 * ((pixels - 2 * margin) - (xmax - xmin) * s);
    q[1] = pixels - margin - (q[1] - ymin) * s - 0.5 * ((pixels - 2 * margin) - (ymax - ymin) * s);
  }

  Rgb_image image(pixels, pixels, {{240, 240, 240}});
  std::vector<double> depth(std::size_t(pixels) * std::size_t(pixels), std::numeric_limits<double>::infinity());
  const V light = unit(V{{-d[0] + 0.3 * up[0], -d[1] + 0.3 * up[1], -d[2] + 0.3 * up[2]}});
  for(const auto& t : triangles)
  {
    const auto &a = screen[t[0]], &b = screen[t[1]], &c = screen[t[2]];
    const double area = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    if(area == 0.)
      continue;
    const V n = unit(cross(V{{points[t[1]][0] - points[t[0]][0], points[t[1]][1] - points[t[0]][1], points[t[1]][2] - points[t[0]][2]}},
                           V{{points[t[2]][0] - points[t[0]][0], points[t[2]][1] - points[t[0]][1], points[t[2]][2] - points[t[0]][2]}}));
    const double shade = 0.35 + 0.65 * std::abs(dot(n, light)); // both sides lit
    const int x0 = (std::max)(0, int(std::floor((std::min)({a[0], b[0], c[0]})))), x1 = (std::min)(pixels - 1, int(std::ceil((std::max)({a[0], b[0], c[0]}))));
    const int y0 = (std::max)(0, int(std::floor((std::min)({a[1], b[1], c[1]})))), y1 = (std::min)(pixels - 1, int(std::ceil((std::max)({a[1], b[1], c[1]}))));
    for(int y = y0; y <= y1; ++y)
      for(int x = x0; x <= x1; ++x)
      {
        const double px = x + 0.5, py = y + 0.5;
        const double w0 = ((b[0] - px) * (c[1] - py) - (b[1] - py) * (c[0] - px)) / area;
        const double w1 = ((c[0] - px) * (a[1] - py) - (c[1] - py) * (a[0] - px)) / area;
        const double w2 = 1. - w0 - w1;
        if(w0 < 0. || w1 < 0. || w2 < 0.)
          continue;
        const double z = w0 * a[2] + w1 * b[2] + w2 * c[2];
        double& zbuffer = depth[std::size_t(y) * std::size_t(pixels) + std::size_t(x)];
        if(z >= zbuffer)
          continue;
        zbuffer = z;
        const double u = w0 * texture[t[0]][0] + w1 * texture[t[1]][0] + w2 * texture[t[2]][0];
        const double v = w0 * texture[t[0]][1] + w1 * texture[t[1]][1] + w2 * texture[t[2]][1];
        const bool dark = (int(std::floor(u * squares)) + int(std::floor(v * squares))) % 2 != 0;
        const std::array<double, 3> base = dark ? std::array<double, 3>{{204, 76, 2}} : std::array<double, 3>{{255, 247, 188}};
        image.set(x, y, {{std::uint8_t(base[0] * shade), std::uint8_t(base[1] * shade), std::uint8_t(base[2] * shade)}});
      }
  }
  return image;
}

} // namespace Conformal_remeshing_tools

#endif // CGAL_CONFORMAL_REMESHING_TOOLS_FLATTENING_PICTURES_H
