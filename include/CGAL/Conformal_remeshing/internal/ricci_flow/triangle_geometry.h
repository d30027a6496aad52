// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Numerically stable quantities of a Euclidean triangle known by its side lengths only.
// Everything goes through the tangents of the half angles, computed with Kahan's ordering of
// the side lengths, so that slivers (angles of 1e-6 degrees and less) keep full relative
// accuracy where acos of the cosine law would lose all of it.

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_RICCI_FLOW_TRIANGLE_GEOMETRY_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_RICCI_FLOW_TRIANGLE_GEOMETRY_H

#include <array>
#include <cmath>
#include <utility>

namespace CGAL {
namespace Conformal_remeshing {
namespace internal {
namespace ricci_flow {

/// Half-angle tangents of the triangle with side lengths `l[0]`, `l[1]`, `l[2]`:
/// `t[i]` = tan(theta_i / 2), theta_i the angle opposite side `l[i]`.
/// Returns false (and leaves `t` unspecified) when the strict triangle inequality fails.
template <typename FT>
bool half_angle_tangents(const std::array<FT, 3>& l, std::array<FT, 3>& t)
{
  using std::sqrt;
  // Kahan: sort x >= y >= z and group the sums so that no cancellation hits a small term.
  int o[3] = {0, 1, 2};
  if(l[o[0]] < l[o[1]]) std::swap(o[0], o[1]);
  if(l[o[1]] < l[o[2]]) std::swap(o[1], o[2]);
  if(l[o[0]] < l[o[1]]) std::swap(o[0], o[1]);
  const FT& x = l[o[0]];
  const FT& y = l[o[1]];
  const FT& z = l[o[2]];
  if(!(z > FT(0)))
    return false;
  std::array<FT, 3> d; // d[i] = 2 (s - l[i]), s the half perimeter
  d[o[0]] = z - (x - y);
  d[o[1]] = z + (x - y);
  d[o[2]] = x + (y - z);
  if(!(d[o[0]] > FT(0)))
    return false;
  const FT p = x + (y + z); // 2 s
  for(int i = 0; i < 3; ++i)
    t[i] = sqrt((d[(i + 1) % 3] * d[(i + 2) % 3]) / (p * d[i]));
  return true;
}

/// Area of the triangle with side lengths `l` (Kahan's formula); 0 if degenerate or invalid.
template <typename FT>
FT triangle_area(const std::array<FT, 3>& l)
{
  using std::sqrt;
  std::array<FT, 3> s = l;
  if(s[0] < s[1]) std::swap(s[0], s[1]);
  if(s[1] < s[2]) std::swap(s[1], s[2]);
  if(s[0] < s[1]) std::swap(s[0], s[1]);
  const FT q = (s[0] + (s[1] + s[2])) * (s[2] - (s[0] - s[1])) * (s[2] + (s[0] - s[1])) * (s[0] + (s[1] - s[2]));
  return q > FT(0) ? sqrt(q) / FT(4) : FT(0);
}

template <typename FT> FT angle_from_half_tangent(const FT& t) { using std::atan; return FT(2) * atan(t); }
template <typename FT> FT cot_from_half_tangent(const FT& t) { return (FT(1) - t * t) / (FT(2) * t); }
template <typename FT> FT cos_from_half_tangent(const FT& t) { return (FT(1) - t * t) / (FT(1) + t * t); }
template <typename FT> FT sin_from_half_tangent(const FT& t) { return (FT(2) * t) / (FT(1) + t * t); }

/// Third vertex `c` of the counterclockwise triangle (a, b, c) with |ca| = `l_ca` and the angle
/// at `a` given by its half tangent `t_a`. The direction of ab comes from the positions, so a
/// layout stays consistent with the points already placed.
template <typename FT>
std::array<FT, 2> third_point(const std::array<FT, 2>& a, const std::array<FT, 2>& b,
                              const FT& l_ca, const FT& t_a)
{
  using std::sqrt;
  const FT ex = b[0] - a[0], ey = b[1] - a[1];
  const FT n = sqrt(ex * ex + ey * ey);
  const FT c = cos_from_half_tangent(t_a) * l_ca / n;
  const FT s = sin_from_half_tangent(t_a) * l_ca / n;
  return {{a[0] + c * ex - s * ey, a[1] + c * ey + s * ex}};
}

/// Barycentric coordinates of `p` in the triangle (p0, p1, p2).
template <typename FT>
std::array<FT, 3> barycentric(const std::array<FT, 2>& p0, const std::array<FT, 2>& p1,
                              const std::array<FT, 2>& p2, const std::array<FT, 2>& p)
{
  auto cross = [](const std::array<FT, 2>& u, const std::array<FT, 2>& v, const std::array<FT, 2>& w) {
    return (v[0] - u[0]) * (w[1] - u[1]) - (v[1] - u[1]) * (w[0] - u[0]);
  };
  const FT total = cross(p0, p1, p2);
  return {{cross(p, p1, p2) / total, cross(p0, p, p2) / total, cross(p0, p1, p) / total}};
}

} // namespace ricci_flow
} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_RICCI_FLOW_TRIANGLE_GEOMETRY_H
