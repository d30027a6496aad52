// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A small software rasterizer for pictures of triangle meshes, offscreen and without any
// graphics library: an orthographic view along a fixed direction, flat-shaded triangles with a
// z-buffer, and the edges drawn as dark lines (so that the shapes of the triangles, the quality
// a remeshing is about, can be seen). Triangles whose smallest angle is below a threshold can
// be drawn in a warning colour.

#ifndef CGAL_CONFORMAL_REMESHING_TOOLS_MESH_RENDERING_H
#define CGAL_CONFORMAL_REMESHING_TOOLS_MESH_RENDERING_H

#include "png_writer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace Conformal_remeshing_tools {

typedef std::array<double, 3> Vector_3d;
typedef std::array<std::uint8_t, 3> Colour;

struct Mesh_rendering_options
{
  int width = 600, height = 450;
  Vector_3d view_direction = {{-0.6, -1., -0.9}}; // from the eye into the scene
  Vector_3d up = {{0., 0., 1.}};                  // projected to the picture's vertical
  double zoom = 1.;                               // 1: the whole mesh fits the picture
  bool has_focus = false;                         // with zoom: the point at the picture's centre
  Vector_3d focus = {{0., 0., 0.}};
  double edge_width = 1.2;                        // in pixels; 0: no edges
  double highlight_angle = 0.;                    // triangles with a smaller angle (degrees) in warning colour
  Colour face = {{190, 205, 230}}, highlight = {{230, 90, 60}}, edge = {{35, 35, 50}};
  Colour background = {{255, 255, 255}};
};

namespace internal {

inline double dot(const Vector_3d& a, const Vector_3d& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vector_3d cross(const Vector_3d& a, const Vector_3d& b)
{
  return {{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
}
inline Vector_3d minus(const Vector_3d& a, const Vector_3d& b) { return {{a[0] - b[0], a[1] - b[1], a[2] - b[2]}}; }
inline Vector_3d unit(const Vector_3d& a)
{
  const double n = std::sqrt(dot(a, a));
  return n > 0. ? Vector_3d{{a[0] / n, a[1] / n, a[2] / n}} : Vector_3d{{0., 0., 1.}};
}

// The smallest corner angle of a triangle, in degrees.
inline double smallest_angle(const Vector_3d& a, const Vector_3d& b, const Vector_3d& c)
{
  const Vector_3d p[3] = {a, b, c};
  double smallest = 180.;
  for(int i = 0; i < 3; ++i)
  {
    const Vector_3d u = minus(p[(i + 1) % 3], p[i]), v = minus(p[(i + 2) % 3], p[i]);
    const double angle = std::atan2(std::sqrt(dot(cross(u, v), cross(u, v))), dot(u, v)) * 180. / 3.14159265358979323846;
    smallest = (std::min)(smallest, angle);
  }
  return smallest;
}

// Picture frame of the view: right, up and depth axes, and the map of a point to pixels.
class Screen_projection
{
public:
  Screen_projection(const std::vector<Vector_3d>& points, const Mesh_rendering_options& o)
    : depth_(unit(o.view_direction))
  {
    const Vector_3d up_hint = std::abs(dot(unit(o.up), depth_)) < 0.99 ? unit(o.up) : Vector_3d{{1., 0., 0.}};
    right_ = unit(cross(depth_, up_hint));
    up_ = cross(right_, depth_);
    double xmin = std::numeric_limits<double>::infinity(), ymin = xmin, xmax = -xmin, ymax = -xmin;
    for(const Vector_3d& p : points)
    {
      xmin = (std::min)(xmin, dot(p, right_));
      xmax = (std::max)(xmax, dot(p, right_));
      ymin = (std::min)(ymin, dot(p, up_));
      ymax = (std::max)(ymax, dot(p, up_));
    }
    const double margin = 8.;
    const double sx = (o.width - 2 * margin) / (std::max)(xmax - xmin, 1e-300);
    const double sy = (o.height - 2 * margin) / (std::max)(ymax - ymin, 1e-300);
    scale_ = (std::min)(sx, sy) * o.zoom;
    centre_x_ = o.has_focus ? dot(o.focus, right_) : 0.5 * (xmin + xmax);
    centre_y_ = o.has_focus ? dot(o.focus, up_) : 0.5 * (ymin + ymax);
    width_ = o.width;
    height_ = o.height;
  }

  // Pixel column, pixel row (downwards) and depth (larger is farther) of a point.
  Vector_3d operator()(const Vector_3d& p) const
  {
    return {{0.5 * width_ + (dot(p, right_) - centre_x_) * scale_, 0.5 * height_ - (dot(p, up_) - centre_y_) * scale_,
             dot(p, depth_)}};
  }
  const Vector_3d& depth_axis() const { return depth_; }
  const Vector_3d& up_axis() const { return up_; }

private:
  Vector_3d depth_, right_, up_;
  double scale_ = 1., centre_x_ = 0., centre_y_ = 0.;
  int width_ = 1, height_ = 1;
};

inline Colour mix(const Colour& a, const Colour& b, double t)
{
  Colour c;
  for(int i = 0; i < 3; ++i)
    c[i] = std::uint8_t(std::lround(a[i] * (1. - t) + b[i] * t));
  return c;
}

inline Colour shaded(const Colour& c, double shade)
{
  return {{std::uint8_t(c[0] * shade), std::uint8_t(c[1] * shade), std::uint8_t(c[2] * shade)}};
}

// Draws one triangle, given in screen coordinates, into the image and the z-buffer. The
// distance of a pixel to the triangle's sides, in pixels, decides where its edges are drawn:
// half the width on each side of a shared edge, at the depth of the triangle itself, so that
// hidden edges stay hidden.
inline void rasterize_triangle(const Vector_3d s[3], const Colour& fill, const Mesh_rendering_options& o,
                               Rgb_image& image, std::vector<double>& depth)
{
  const double area = (s[1][0] - s[0][0]) * (s[2][1] - s[0][1]) - (s[1][1] - s[0][1]) * (s[2][0] - s[0][0]);
  if(!(std::abs(area) > 1e-12))
    return;
  double side[3];
  for(int i = 0; i < 3; ++i) // side i is opposite corner i
    side[i] = std::hypot(s[(i + 2) % 3][0] - s[(i + 1) % 3][0], s[(i + 2) % 3][1] - s[(i + 1) % 3][1]);
  const int x0 = (std::max)(0, int(std::floor((std::min)({s[0][0], s[1][0], s[2][0]}))));
  const int x1 = (std::min)(o.width - 1, int(std::ceil((std::max)({s[0][0], s[1][0], s[2][0]}))));
  const int y0 = (std::max)(0, int(std::floor((std::min)({s[0][1], s[1][1], s[2][1]}))));
  const int y1 = (std::min)(o.height - 1, int(std::ceil((std::max)({s[0][1], s[1][1], s[2][1]}))));
  for(int y = y0; y <= y1; ++y)
    for(int x = x0; x <= x1; ++x)
    {
      const double px = x + 0.5, py = y + 0.5;
      double w[3];
      w[0] = ((s[1][0] - px) * (s[2][1] - py) - (s[1][1] - py) * (s[2][0] - px)) / area;
      w[1] = ((s[2][0] - px) * (s[0][1] - py) - (s[2][1] - py) * (s[0][0] - px)) / area;
      w[2] = 1. - w[0] - w[1];
      if(w[0] < 0. || w[1] < 0. || w[2] < 0.)
        continue;
      const double z = w[0] * s[0][2] + w[1] * s[1][2] + w[2] * s[2][2];
      double& nearest = depth[std::size_t(y) * std::size_t(o.width) + std::size_t(x)];
      if(z >= nearest)
        continue;
      nearest = z;
      double to_side = std::numeric_limits<double>::infinity();
      for(int i = 0; i < 3; ++i)
        if(side[i] > 0.)
          to_side = (std::min)(to_side, w[i] * std::abs(area) / side[i]);
      // Coverage of the edge line, in quarters: a few colours keep the compressed PNG small.
      const double coverage = o.edge_width > 0. ? (std::clamp)(0.5 * o.edge_width + 0.5 - to_side, 0., 1.) : 0.;
      const double ink = std::round(coverage * 4.) / 4.;
      image.set(x, y, mix(fill, o.edge, ink));
    }
}

} // namespace internal

/// A colour for part `i` of a picture of several parts (patches, say): distinct pastel hues.
inline Colour part_colour(std::size_t i)
{
  static const Colour palette[] = {{{190, 205, 230}}, {{240, 200, 150}}, {{180, 225, 180}}, {{235, 180, 200}},
                                   {{210, 195, 235}}, {{240, 230, 150}}, {{160, 215, 220}}, {{220, 190, 170}}};
  return palette[i % (sizeof(palette) / sizeof(palette[0]))];
}

/// Renders `triangles` (indices into `points`) into a picture of `o.width` x `o.height` pixels,
/// triangle `t` in `(*colours)[t]` if colours are given, else in `o.face`.
inline Rgb_image render_mesh(const std::vector<Vector_3d>& points, const std::vector<std::array<std::size_t, 3> >& triangles,
                             const Mesh_rendering_options& o = Mesh_rendering_options(),
                             const std::vector<Colour>* colours = nullptr)
{
  using namespace internal;
  const Screen_projection project(points, o);
  std::vector<Vector_3d> screen;
  screen.reserve(points.size());
  for(const Vector_3d& p : points)
    screen.push_back(project(p));

  Rgb_image image(o.width, o.height, o.background);
  std::vector<double> depth(std::size_t(o.width) * std::size_t(o.height), std::numeric_limits<double>::infinity());
  const Vector_3d light = unit({{-project.depth_axis()[0] + 0.5 * project.up_axis()[0],
                                 -project.depth_axis()[1] + 0.5 * project.up_axis()[1],
                                 -project.depth_axis()[2] + 0.5 * project.up_axis()[2]}});
  for(std::size_t i = 0; i < triangles.size(); ++i)
  {
    const auto& t = triangles[i];
    const Vector_3d& a = points[t[0]];
    const Vector_3d& b = points[t[1]];
    const Vector_3d& c = points[t[2]];
    const Vector_3d n = unit(cross(minus(b, a), minus(c, a)));
    const double shade = 0.45 + 0.55 * std::abs(dot(n, light)); // both sides lit
    const bool bad = o.highlight_angle > 0. && smallest_angle(a, b, c) < o.highlight_angle;
    const Vector_3d s[3] = {screen[t[0]], screen[t[1]], screen[t[2]]};
    const Colour& fill = bad ? o.highlight : colours ? (*colours)[i] : o.face;
    rasterize_triangle(s, shaded(fill, shade), o, image, depth);
  }
  return image;
}

} // namespace Conformal_remeshing_tools

#endif // CGAL_CONFORMAL_REMESHING_TOOLS_MESH_RENDERING_H
