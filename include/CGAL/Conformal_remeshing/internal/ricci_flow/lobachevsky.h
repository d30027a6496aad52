// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Milnor's Lobachevsky function, needed to evaluate the Ricci energy for the line search.

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_RICCI_FLOW_LOBACHEVSKY_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_RICCI_FLOW_LOBACHEVSKY_H

#include <array>
#include <cmath>

namespace CGAL {
namespace Conformal_remeshing {
namespace internal {
namespace ricci_flow {

/// Clausen's function Cl2(x) = -int_0^x log|2 sin(t/2)| dt for x in [0, 2 pi], in double.
/// Series Cl2(x) = x - x log x + sum_k zeta(2k) / (k (2k+1)) x (x / 2pi)^(2k), used on [0, pi]
/// (ratio at most 1/4 per term) and reflected with Cl2(2 pi - x) = -Cl2(x).
inline double clausen2(double x)
{
  const double two_pi = 6.283185307179586476925286766559;
  static const std::array<double, 32> coefficients = [] {
    std::array<double, 32> c{};
    const double pi = 3.141592653589793238462643383279;
    for(int k = 1; k <= 32; ++k)
    {
      double zeta;
      if(k == 1) zeta = pi * pi / 6.;
      else if(k == 2) zeta = std::pow(pi, 4) / 90.;
      else if(k == 3) zeta = std::pow(pi, 6) / 945.;
      else if(k == 4) zeta = std::pow(pi, 8) / 9450.;
      else
      {
        zeta = 0.; // the tail beyond n = 64 is below 64^(1-2k) < 1e-30
        for(int n = 64; n >= 1; --n)
          zeta += std::pow(double(n), -2. * k);
      }
      c[k - 1] = zeta / (k * (2. * k + 1.));
    }
    return c;
  }();
  double sign = 1.;
  if(x > two_pi / 2.)
  {
    x = two_pi - x;
    sign = -1.;
  }
  if(x <= 0.)
    return 0.;
  const double r = (x / two_pi) * (x / two_pi);
  double sum = 0., p = r;
  for(double c : coefficients)
  {
    sum += c * p;
    p *= r;
    if(p < 1e-18)
      break;
  }
  return sign * (x - x * std::log(x) + x * sum);
}

/// Milnor's Lobachevsky function L(theta) = -int_0^theta log|2 sin t| dt = Cl2(2 theta) / 2,
/// for theta in [0, pi].
inline double lobachevsky(double theta) { return 0.5 * clausen2(2. * theta); }

} // namespace ricci_flow
} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_RICCI_FLOW_LOBACHEVSKY_H
