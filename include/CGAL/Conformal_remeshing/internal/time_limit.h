// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// CGAL's `maximum_running_time` named parameter: a limit on the wall-clock time of a call, checked
// between steps (Newton iterations, stages, patches). A call that exceeds it throws
// `Error(Error_code::TIME_LIMIT_EXCEEDED)`; the step under way when the limit passes finishes
// first, so a call may overrun by the duration of one step.

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_TIME_LIMIT_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_TIME_LIMIT_H

#include <CGAL/Conformal_remeshing/Error.h>
#include <CGAL/Conformal_remeshing/parameters.h>

#include <CGAL/Named_function_parameters.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>


namespace CGAL {
namespace Conformal_remeshing {
namespace internal {

// The time limit of one call, from the moment it is made. Unlimited when the parameter is absent
// or infinite. A function that calls another passes it `remaining()` seconds.
class Time_limit
{
public:
  typedef std::chrono::steady_clock Clock;

  /// \throws Error with `Error_code::INVALID_INPUT` if `seconds` is negative or not a number.
  Time_limit(double seconds, const std::string& caller)
    : limit_(seconds), caller_(caller), start_(Clock::now())
  {
    if(!(seconds >= 0.))
    {
      std::ostringstream os;
      os << caller << ": the maximum running time must be a non-negative number of seconds, not " << seconds << ".";
      throw Error(Error_code::INVALID_INPUT, os.str());
    }
  }

  template <typename NamedParameters>
  static Time_limit from(const NamedParameters& np, const std::string& caller)
  {
    using CGAL::parameters::choose_parameter;
    using CGAL::parameters::get_parameter;
    return Time_limit(double(choose_parameter(get_parameter(np, CGAL::internal_np::maximum_running_time),
                                              std::numeric_limits<double>::infinity())),
                      caller);
  }

  bool is_limited() const { return std::isfinite(limit_); }
  double elapsed() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }
  /// seconds left (0 when exceeded), infinity when unlimited
  double remaining() const { return is_limited() ? (std::max)(0., limit_ - elapsed()) : limit_; }
  bool exceeded() const { return is_limited() && elapsed() > limit_; }

  /// Throws `Error(TIME_LIMIT_EXCEEDED)` once the limit has passed; `where` says where the call
  /// stopped (e.g. "after 3 Newton iterations").
  void check(const std::string& where) const
  {
    if(!is_limited())
      return;
    const double t = elapsed();
    if(t <= limit_)
      return;
    std::ostringstream os;
    os << caller_ << ": stopped " << where << ": the time limit of " << limit_
       << " s (maximum_running_time) was exceeded (" << t << " s).";
    throw Error(Error_code::TIME_LIMIT_EXCEEDED, os.str());
  }

private:
  double limit_;
  std::string caller_;
  Clock::time_point start_;
};

} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_TIME_LIMIT_H
