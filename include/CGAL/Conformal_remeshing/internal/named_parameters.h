// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The package's own named parameters. CGAL 5.5's list of named parameters is closed, so the
// package defines its tags in CGAL::Conformal_remeshing::internal_np and its builder functions
// in CGAL::Conformal_remeshing::parameters. A builder takes an optional second argument, the
// parameters to chain it with, CGAL's or the package's:
//   curvature_tolerance(1e-12, CGAL::parameters::number_of_iterations(20))

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_NAMED_PARAMETERS_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_NAMED_PARAMETERS_H

#include <CGAL/Named_function_parameters.h>

/// Declares the tag `CGAL::Conformal_remeshing::internal_np::NAME` and the builder
/// `CGAL::Conformal_remeshing::parameters::NAME(value[, chained parameters])`. Use it at global
/// scope.
#define CGAL_CONFORMAL_REMESHING_NAMED_PARAMETER(NAME)                                                        \
  namespace CGAL {                                                                                            \
  namespace Conformal_remeshing {                                                                             \
  namespace internal_np {                                                                                     \
  enum NAME##_t { NAME };                                                                                     \
  }                                                                                                           \
  namespace parameters {                                                                                      \
  template <typename T>                                                                                       \
  Named_function_parameters<T, internal_np::NAME##_t> NAME(const T& value)                                    \
  {                                                                                                           \
    return Named_function_parameters<T, internal_np::NAME##_t>(value);                                        \
  }                                                                                                           \
  template <typename T, typename T2, typename Tag, typename Base>                                             \
  Named_function_parameters<T, internal_np::NAME##_t, Named_function_parameters<T2, Tag, Base> >              \
  NAME(const T& value, const Named_function_parameters<T2, Tag, Base>& np)                                    \
  {                                                                                                           \
    return Named_function_parameters<T, internal_np::NAME##_t, Named_function_parameters<T2, Tag, Base> >(value, np); \
  }                                                                                                           \
  }                                                                                                           \
  }                                                                                                           \
  }

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_NAMED_PARAMETERS_H
