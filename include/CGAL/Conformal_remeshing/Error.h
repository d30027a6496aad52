// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The package's own error type. CGAL_precondition compiles to nothing with NDEBUG, so every
// check a user can trigger with bad input reports through this exception (or a result object
// carrying an Error_code), never through an assertion.

#ifndef CGAL_CONFORMAL_REMESHING_ERROR_H
#define CGAL_CONFORMAL_REMESHING_ERROR_H

#include <stdexcept>
#include <string>

namespace CGAL {
namespace Conformal_remeshing {

/// \ingroup PkgConformalRemeshingRef
/// What went wrong, for programs that branch on the kind of failure.
/// New values are appended; existing values keep their meaning.
enum class Error_code
{
  SUCCESS = 0,            ///< no error
  INVALID_INPUT,          ///< the input mesh or parameters do not meet the documented requirements
  FILE_NOT_READABLE,      ///< a file could not be opened or parsed
  UNSUPPORTED_FORMAT,     ///< the file extension names no format the readers know
  GAUSS_BONNET_VIOLATED,  ///< target curvatures do not sum to 2&pi; times the Euler characteristic
  NOT_CONVERGED,          ///< an iterative solver stopped before reaching its tolerance
  LINEAR_SOLVER_FAILED,   ///< a sparse factorization or solve failed
  DEGENERATE_METRIC,      ///< edge lengths violate the triangle inequality
  NOT_AN_EMBEDDING,       ///< a planar image folds or overlaps (found with exact predicates)
  TIME_LIMIT_EXCEEDED     ///< the call ran longer than its `maximum_running_time`
};

/// \ingroup PkgConformalRemeshingRef
/// A short English description of `code`.
inline const char* error_message(Error_code code)
{
  switch(code)
  {
    case Error_code::SUCCESS: return "success";
    case Error_code::INVALID_INPUT: return "invalid input";
    case Error_code::FILE_NOT_READABLE: return "file not readable";
    case Error_code::UNSUPPORTED_FORMAT: return "unsupported file format";
    case Error_code::GAUSS_BONNET_VIOLATED: return "target curvatures violate the Gauss-Bonnet condition";
    case Error_code::NOT_CONVERGED: return "did not converge";
    case Error_code::LINEAR_SOLVER_FAILED: return "sparse linear solver failed";
    case Error_code::DEGENERATE_METRIC: return "edge lengths violate the triangle inequality";
    case Error_code::NOT_AN_EMBEDDING: return "the planar image is not an embedding";
    case Error_code::TIME_LIMIT_EXCEEDED: return "the time limit was exceeded";
  }
  return "unknown error";
}

/// \ingroup PkgConformalRemeshingRef
/// The exception thrown by the package's functions on input they cannot process.
/// `what()` is a complete, user-readable sentence; `code()` says which kind of failure it is.
class Error : public std::runtime_error
{
public:
  Error(Error_code code, const std::string& message)
    : std::runtime_error(message), code_(code)
  {}

  Error_code code() const { return code_; }

private:
  Error_code code_;
};

} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_ERROR_H
