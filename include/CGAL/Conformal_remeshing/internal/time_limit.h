// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// CGAL's `maximum_running_time` named parameter: a limit on the wall-clock time of a call, checked
// between steps (Newton iterations, stages, patches). A call that exceeds it throws
// `Error(Error_code::TIME_LIMIT_EXCEEDED)`; the step under way when the limit passes finishes
// first, so a call may overrun by the duration of one step.
//
// The package's `stop_requested` named parameter, a callable `bool()`, is polled at the same
// checks: once it returns true, the call stops as if its time limit had passed (same error code,
// a message saying that a stop was requested). It lets a program end a long call from outside,
// e.g. on Ctrl-C in the Python module. It must be cheap, safe to call from several threads at
// once, and keep returning true once it has.

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_TIME_LIMIT_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_TIME_LIMIT_H

#include <CGAL/Conformal_remeshing/Error.h>
#include <CGAL/Conformal_remeshing/parameters.h>

#include <CGAL/Named_function_parameters.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <sstream>
#include <string>


namespace CGAL {
namespace Conformal_remeshing {
namespace internal {

// The time limit of one call, from the moment it is made. Unlimited when the parameter is absent
// or infinite. A function that calls another passes it `remaining()` seconds and `stop_request()`.
class Time_limit
{
public:
  typedef std::chrono::steady_clock Clock;
  typedef std::function<bool()> Stop_request; // empty: none

  /// \throws Error with `Error_code::INVALID_INPUT` if `seconds` is negative or not a number.
  Time_limit(double seconds, const std::string& caller, const Stop_request& stop_requested = Stop_request())
    : limit_(seconds), caller_(caller), start_(Clock::now()), stop_requested_(stop_requested)
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
                      caller, choose_parameter(get_parameter(np, internal_np::stop_requested), Stop_request()));
  }

  /// whether the time is limited (a stop request aside)
  bool is_limited() const { return std::isfinite(limit_); }
  double elapsed() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }
  bool stop_requested() const { return stop_requested_ && stop_requested_(); }
  /// the stop request, to pass on to the functions this call calls
  const Stop_request& stop_request() const { return stop_requested_; }
  /// seconds left (0 when exceeded or a stop was requested), infinity when unlimited
  double remaining() const
  {
    if(stop_requested())
      return 0.;
    return is_limited() ? (std::max)(0., limit_ - elapsed()) : limit_;
  }
  bool exceeded() const { return stop_requested() || (is_limited() && elapsed() > limit_); }

  /// Throws `Error(TIME_LIMIT_EXCEEDED)` once the limit has passed or a stop was requested; `where` says where the call
  /// stopped (e.g. "after 3 Newton iterations").
  void check(const std::string& where) const
  {
    if(stop_requested())
      throw Error(Error_code::TIME_LIMIT_EXCEEDED, caller_ + ": stopped " + where + ": a stop was requested (stop_requested).");
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
  Stop_request stop_requested_;
};

} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_TIME_LIMIT_H
