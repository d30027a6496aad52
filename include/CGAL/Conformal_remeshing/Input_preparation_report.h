// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the input preparation of `remesh_conformal()` found and repaired.

#ifndef CGAL_CONFORMAL_REMESHING_INPUT_PREPARATION_REPORT_H
#define CGAL_CONFORMAL_REMESHING_INPUT_PREPARATION_REPORT_H

#include <cstddef>
#include <string>

namespace CGAL {
namespace Conformal_remeshing {

/// \ingroup PkgConformalRemeshingRef
/// What `remesh_conformal()` repaired in its input before remeshing it (see its named parameter
/// `repair_input`), and what it kept as it is.
struct Input_preparation_report
{
  /// input vertices at the same point as another one: kept as distinct points of the surface
  std::size_t coincident_vertices = 0;
  /// vertices added by the repair of non-manifold vertices (each fan of faces around one gets a
  /// vertex of its own)
  std::size_t split_non_manifold_vertices = 0;
  /// faces of zero area removed (collapsed or flipped away)
  std::size_t removed_degenerate_faces = 0;
  /// one example of each, as the input checks name it (e.g. "vertices 528 and 2209 at (-0.11,
  /// 0, 0)"); empty when there is none
  std::string coincident_example, non_manifold_example, degenerate_example;

  /// whether the input was repaired
  bool repaired() const { return split_non_manifold_vertices > 0 || removed_degenerate_faces > 0; }

  /// One line on the repairs with an example of each, e.g. "2 vertices added to split
  /// non-manifold vertices (e.g. vertex 4 at (4, 4, 0)); 5 degenerate faces removed (e.g. ...)"
  /// ("no repair" when there was none).
  std::string summary() const
  {
    std::string out;
    const auto add = [&](std::size_t n, const char* one, const char* many, const std::string& example) {
      if(n > 0)
        out += (out.empty() ? "" : "; ") + std::to_string(n) + " " + (n == 1 ? one : many)
               + (example.empty() ? std::string() : " (e.g. " + example + ")");
    };
    add(split_non_manifold_vertices, "vertex added to split non-manifold vertices", "vertices added to split non-manifold vertices",
        non_manifold_example);
    add(removed_degenerate_faces, "degenerate face removed", "degenerate faces removed", degenerate_example);
    return out.empty() ? std::string("no repair") : out;
  }
};

} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INPUT_PREPARATION_REPORT_H
