// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Growth exponents of measured costs: the least-squares line through (log n, log y).

#ifndef CGAL_CONFORMAL_REMESHING_BENCHMARKS_POWER_LAW_FIT_H
#define CGAL_CONFORMAL_REMESHING_BENCHMARKS_POWER_LAW_FIT_H

#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace benchmarks {

/// y ~ coefficient * n^exponent; `points` pairs were used (those with n > 0 and y > 0), and
/// `r_squared` says how well the line fits in log-log.
struct Power_law_fit
{
  double exponent = std::numeric_limits<double>::quiet_NaN();
  double coefficient = std::numeric_limits<double>::quiet_NaN();
  double r_squared = std::numeric_limits<double>::quiet_NaN();
  std::size_t points = 0;

  bool is_valid() const { return points >= 2 && std::isfinite(exponent); }
};

/// Fits y = c n^k by least squares on the logarithms. Pairs with a non-positive or non-finite
/// value are skipped (a stage too fast to time, a run that did not finish); fewer than two
/// pairs leave the fit invalid.
inline Power_law_fit fit_power_law(const std::vector<double>& n, const std::vector<double>& y)
{
  std::vector<double> x, z;
  for(std::size_t i = 0; i < n.size() && i < y.size(); ++i)
    if(n[i] > 0. && y[i] > 0. && std::isfinite(n[i]) && std::isfinite(y[i]))
    {
      x.push_back(std::log(n[i]));
      z.push_back(std::log(y[i]));
    }
  Power_law_fit fit;
  fit.points = x.size();
  if(x.size() < 2)
    return fit;
  double mx = 0., mz = 0.;
  for(std::size_t i = 0; i < x.size(); ++i)
  {
    mx += x[i];
    mz += z[i];
  }
  mx /= double(x.size());
  mz /= double(x.size());
  double sxx = 0., sxz = 0., szz = 0.;
  for(std::size_t i = 0; i < x.size(); ++i)
  {
    sxx += (x[i] - mx) * (x[i] - mx);
    sxz += (x[i] - mx) * (z[i] - mz);
    szz += (z[i] - mz) * (z[i] - mz);
  }
  if(!(sxx > 0.))
    return fit;
  fit.exponent = sxz / sxx;
  fit.coefficient = std::exp(mz - fit.exponent * mx);
  fit.r_squared = szz > 0. ? sxz * sxz / (sxx * szz) : 1.;
  return fit;
}

/// The exponent the same fit gives for n log n on the same sizes: what "grows like n log n"
/// means in the fitted exponents (about 1.09 from 10^4 to 10^6).
inline double n_log_n_exponent(const std::vector<double>& n)
{
  std::vector<double> y;
  for(double v : n)
    y.push_back(v > 1. ? v * std::log(v) : 0.);
  return fit_power_law(n, y).exponent;
}

} // namespace benchmarks
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_BENCHMARKS_POWER_LAW_FIT_H
