// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The kinds of input defects the checks report.

#ifndef CGAL_CONFORMAL_REMESHING_MESH_DEFECT_H
#define CGAL_CONFORMAL_REMESHING_MESH_DEFECT_H

#include <cstddef>
#include <string>

namespace CGAL {
namespace Conformal_remeshing {

/// \ingroup PkgConformalRemeshingRef
/// A defect that makes a mesh unfit for remeshing as it is.
enum class Mesh_defect
{
  EMPTY_MESH,               ///< no face at all
  INVALID_VERTEX_INDEX,     ///< a face refers to a vertex that does not exist
  NON_FINITE_COORDINATES,   ///< a vertex with an infinite or NaN coordinate
  NON_TRIANGLE_FACE,        ///< a face with other than three vertices
  DEGENERATE_FACE,          ///< a face with zero area (collinear or repeated vertices), by exact predicates
  DUPLICATED_VERTEX,        ///< two vertices at exactly the same position
  ISOLATED_VERTEX,          ///< a vertex that no face uses
  NON_MANIFOLD_EDGE,        ///< an edge shared by more than two faces
  NON_MANIFOLD_VERTEX,      ///< a vertex whose incident faces form more than one fan
  INCONSISTENT_ORIENTATION, ///< an orientable surface whose faces are not all oriented alike
  NON_ORIENTABLE            ///< a surface that cannot be oriented (a Möbius strip, for example)
};

/// \ingroup PkgConformalRemeshingRef
/// The English name of a defect, in the plural when `count != 1`.
inline std::string defect_name(Mesh_defect d, std::size_t count = 1)
{
  const bool one = (count == 1);
  switch(d)
  {
    case Mesh_defect::EMPTY_MESH: return "empty mesh";
    case Mesh_defect::INVALID_VERTEX_INDEX: return one ? "face with an invalid vertex index" : "faces with an invalid vertex index";
    case Mesh_defect::NON_FINITE_COORDINATES: return one ? "vertex with non-finite coordinates" : "vertices with non-finite coordinates";
    case Mesh_defect::NON_TRIANGLE_FACE: return one ? "non-triangle face" : "non-triangle faces";
    case Mesh_defect::DEGENERATE_FACE: return one ? "degenerate (zero-area) face" : "degenerate (zero-area) faces";
    case Mesh_defect::DUPLICATED_VERTEX: return one ? "duplicated vertex" : "duplicated vertices";
    case Mesh_defect::ISOLATED_VERTEX: return one ? "isolated vertex" : "isolated vertices";
    case Mesh_defect::NON_MANIFOLD_EDGE: return one ? "non-manifold edge" : "non-manifold edges";
    case Mesh_defect::NON_MANIFOLD_VERTEX: return one ? "non-manifold vertex" : "non-manifold vertices";
    case Mesh_defect::INCONSISTENT_ORIENTATION: return one ? "inconsistently oriented edge" : "inconsistently oriented edges";
    case Mesh_defect::NON_ORIENTABLE: return one ? "non-orientable component" : "non-orientable components";
  }
  return "unknown defect";
}

/// \ingroup PkgConformalRemeshingRef
/// How often one kind of defect occurs, with one example element described in words
/// (indices are 0-based positions in the input's vertex and face order).
struct Defect_summary
{
  Mesh_defect defect;
  std::size_t count;
  std::string example;
};

} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_MESH_DEFECT_H
