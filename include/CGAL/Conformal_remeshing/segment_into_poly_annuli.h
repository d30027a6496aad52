// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Segmentation of any orientable manifold triangle mesh into poly-annuli (connected, genus 0,
// at least one boundary loop): along sharp features, user patches and planes, then plane
// bisection of every piece that still has a handle or no boundary (paper Sec. 3).

#ifndef CGAL_CONFORMAL_REMESHING_SEGMENT_INTO_POLY_ANNULI_H
#define CGAL_CONFORMAL_REMESHING_SEGMENT_INTO_POLY_ANNULI_H

#include <CGAL/Conformal_remeshing/Error.h>
#include <CGAL/Conformal_remeshing/check_mesh.h>
#include <CGAL/Conformal_remeshing/internal/segmentation/grid_cells.h>
#include <CGAL/Conformal_remeshing/internal/segmentation/narrow_feature_strips.h>
#include <CGAL/Conformal_remeshing/parameters.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <string>
#include <utility>
#include <vector>


namespace CGAL {
namespace Conformal_remeshing {

/// \ingroup PkgConformalRemeshingRef
/// A surface cut into poly-annuli. `mesh` is the input refined along the cutting planes (new
/// vertices lie on input edges, new edges inside input faces, so the surface is the same); each
/// face knows its patch and the input face it lies in, each edge whether it is a sharp feature.
struct Poly_annulus_segmentation
{
  typedef CGAL::Surface_mesh<Epick::Point_3> Mesh;
  typedef Mesh::Vertex_index Vertex;
  typedef Mesh::Face_index Face;
  typedef Mesh::Edge_index Edge;

  Mesh mesh;
  Mesh::Property_map<Face, std::size_t> patch;
  Mesh::Property_map<Face, std::size_t> input_face;
  Mesh::Property_map<Edge, bool> is_feature;
  /// edges between two user patches (`face_patch_map`): kept in the output like the features
  Mesh::Property_map<Edge, bool> is_user_border;
  std::size_t number_of_patches = 0;
  std::size_t feature_edges = 0;
  /// feature edges inside a patch (the same patch on both sides): the patch is slit open along them
  std::size_t dangling_feature_edges = 0;
  /// sharp edges that are no features: one side of a strip between features narrower than half
  /// the snap distance (see `segment_into_poly_annuli()`)
  std::size_t narrow_strip_feature_edges = 0;
  std::size_t plane_cuts = 0;

  Poly_annulus_segmentation() { reset(); }

  /// Empties the mesh and its properties.
  void reset()
  {
    mesh.clear();
    patch = mesh.add_property_map<Face, std::size_t>("f:patch", 0).first;
    input_face = mesh.add_property_map<Face, std::size_t>("f:input_face", 0).first;
    is_feature = mesh.add_property_map<Edge, bool>("e:feature", false).first;
    is_user_border = mesh.add_property_map<Edge, bool>("e:user_border", false).first;
    number_of_patches = feature_edges = dangling_feature_edges = narrow_strip_feature_edges = plane_cuts = 0;
  }
  Poly_annulus_segmentation(const Poly_annulus_segmentation&) = delete;
  Poly_annulus_segmentation& operator=(const Poly_annulus_segmentation&) = delete;

  /// `true` if `e` separates two patches or lies on the border of the mesh.
  bool is_patch_boundary(Edge e) const
  {
    const auto h = mesh.halfedge(e);
    return mesh.is_border(e) || patch[mesh.face(h)] != patch[mesh.face(mesh.opposite(h))];
  }

  /// `true` if `e` bounds a patch on at least one side: a patch boundary or a sharp feature.
  bool is_curve_edge(Edge e) const { return is_feature[e] || is_patch_boundary(e); }

  /// Renumbers the patches `0 .. number_of_patches - 1` by connected components: two faces are
  /// in the same patch when they share an edge that is not a feature and had the same label.
  void renumber_patches()
  {
    const std::size_t unset = std::size_t(-1);
    std::vector<std::size_t> label(mesh.number_of_faces(), unset);
    std::size_t count = 0;
    std::vector<Face> stack;
    for(Face seed : mesh.faces())
    {
      if(label[seed] != unset)
        continue;
      label[seed] = count;
      stack.push_back(seed);
      while(!stack.empty())
      {
        const Face f = stack.back();
        stack.pop_back();
        for(auto h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh))
        {
          const Face g = mesh.face(mesh.opposite(h));
          if(g == Mesh::null_face() || label[g] != unset || is_feature[mesh.edge(h)] || patch[g] != patch[f])
            continue;
          label[g] = count;
          stack.push_back(g);
        }
      }
      ++count;
    }
    for(Face f : mesh.faces())
      patch[f] = label[f];
    number_of_patches = count;
  }

  /// The faces of patch `p`.
  std::vector<Face> faces_of_patch(std::size_t p) const
  {
    std::vector<Face> result;
    for(Face f : mesh.faces())
      if(patch[f] == p)
        result.push_back(f);
    return result;
  }

  /// The faces of every patch.
  std::vector<std::vector<Face> > faces_of_patches() const
  {
    std::vector<std::vector<Face> > result(number_of_patches);
    for(Face f : mesh.faces())
      result[patch[f]].push_back(f);
    return result;
  }
};

/// \ingroup PkgConformalRemeshingRef
/// One patch as a mesh of its own. Vertices where the patch touches itself (a pinched vertex)
/// are duplicated, so `mesh` is always a manifold. The patch is also cut open along the sharp
/// features inside it (a slit, whose two sides are boundary edges), so that these features are
/// patch boundaries too and survive as chains of output edges.
struct Extracted_patch
{
  typedef CGAL::Surface_mesh<Epick::Point_3> Mesh;
  Mesh mesh;
  std::vector<Poly_annulus_segmentation::Vertex> segmented_vertex; ///< by vertex index of `mesh`
  std::vector<Poly_annulus_segmentation::Face> segmented_face;     ///< by face index of `mesh`
  std::size_t boundary_loops = 0;
  long genus = 0;

  bool is_poly_annulus() const { return genus == 0 && boundary_loops > 0; }
};

namespace internal {
namespace segmentation {

typedef Poly_annulus_segmentation Segmentation;
typedef Segmentation::Mesh Mesh;

// Union-find over face corners.
inline std::size_t find_root(std::vector<std::size_t>& parent, std::size_t i)
{
  while(parent[i] != i)
    i = parent[i] = parent[parent[i]];
  return i;
}

} // namespace segmentation
} // namespace internal

namespace internal {
namespace segmentation {

// The vertex of the patch at each corner of `faces` (corner 3i+c: the target of the c-th halfedge
// of `faces[i]` from its `halfedge()`), as a representative corner: corners of the same vertex
// in faces joined through an edge of the patch that is not a feature are the same patch vertex
// (a fan), so a pinched vertex gives one vertex per fan, and a vertex inside a feature chain one
// per side.
inline std::vector<std::size_t> patch_vertex_of_corners(const Segmentation& s, const std::vector<Segmentation::Face>& faces)
{
  typedef Segmentation::Face Face;
  const Mesh& m = s.mesh;
  std::map<Face, std::size_t> local_face;
  for(std::size_t i = 0; i < faces.size(); ++i)
    local_face[faces[i]] = i;
  std::vector<std::size_t> parent(3 * faces.size());
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  auto corner = [&](Face f, Segmentation::Vertex v) {
    std::size_t c = 0;
    for(auto h : CGAL::halfedges_around_face(m.halfedge(f), m))
    {
      if(m.target(h) == v)
        return 3 * local_face.at(f) + c;
      ++c;
    }
    return std::size_t(-1);
  };
  for(std::size_t i = 0; i < faces.size(); ++i)
    for(auto h : CGAL::halfedges_around_face(m.halfedge(faces[i]), m))
    {
      const Face g = m.face(m.opposite(h));
      if(g == Mesh::null_face() || s.patch[g] != s.patch[faces[i]] || !(faces[i] < g) || s.is_feature[m.edge(h)])
        continue;
      for(auto v : {m.source(h), m.target(h)})
        parent[find_root(parent, corner(faces[i], v))] = find_root(parent, corner(g, v));
    }
  for(std::size_t c = 0; c < parent.size(); ++c)
    parent[c] = find_root(parent, c);
  return parent;
}

// The genus and the number of boundary loops of the patch that `extract_patch(s, faces)` builds,
// counted without building it (the segmentation asks them of every patch in every round): its
// vertices are the corners' patch vertices, its edges the distinct pairs of them along the
// faces' sides, and each of its boundary loops a cycle of the sides with no face across (a
// patch vertex is one fan, so at most one such side leaves it).
inline std::pair<long, std::size_t> patch_topology(const Segmentation& s, const std::vector<Segmentation::Face>& faces)
{
  const std::vector<std::size_t> vertex = patch_vertex_of_corners(s, faces);
  std::vector<std::pair<std::size_t, std::size_t> > sides; // directed, as the faces run
  sides.reserve(vertex.size());
  std::size_t vertices = 0;
  for(std::size_t c = 0; c < vertex.size(); ++c)
  {
    vertices += vertex[c] == c;
    const std::size_t previous = c % 3 == 0 ? c + 2 : c - 1;
    sides.emplace_back(vertex[previous], vertex[c]);
  }
  std::sort(sides.begin(), sides.end());
  if(std::adjacent_find(sides.begin(), sides.end()) != sides.end())
    throw Error(Error_code::INVALID_INPUT, "extract_patch: the patch is not a manifold surface (internal error)");
  // The boundary sides run backwards along the sides without a twin: from each one's target on.
  std::map<std::size_t, std::size_t> boundary_next; // patch vertex -> the next along the boundary
  std::size_t edges = 0;
  for(const auto& side : sides)
  {
    const bool twin = std::binary_search(sides.begin(), sides.end(), std::make_pair(side.second, side.first));
    edges += !twin || side.first < side.second;
    if(!twin)
      boundary_next[side.second] = side.first;
  }
  std::size_t loops = 0;
  std::set<std::size_t> seen;
  for(const auto& start : boundary_next)
    if(seen.insert(start.first).second)
    {
      ++loops;
      for(std::size_t v = start.second; seen.insert(v).second; v = boundary_next.at(v))
      {
      }
    }
  const long euler = long(vertices) - long(edges) + long(faces.size());
  return {(2 - euler - long(loops)) / 2, loops};
}

} // namespace segmentation
} // namespace internal

/// \ingroup PkgConformalRemeshingRef
/// Copies the faces `faces` of one patch of `s` into a mesh of their own, with its topology.
inline Extracted_patch extract_patch(const Poly_annulus_segmentation& s, const std::vector<Poly_annulus_segmentation::Face>& faces)
{
  const Poly_annulus_segmentation::Mesh& m = s.mesh;
  const std::vector<std::size_t> vertex_of_corner = internal::segmentation::patch_vertex_of_corners(s, faces);
  Extracted_patch patch;
  std::map<std::size_t, Extracted_patch::Mesh::Vertex_index> vertex_of_root;
  for(std::size_t i = 0; i < faces.size(); ++i)
  {
    std::array<Extracted_patch::Mesh::Vertex_index, 3> corners;
    std::size_t c = 0;
    for(auto h : CGAL::halfedges_around_face(m.halfedge(faces[i]), m))
    {
      const std::size_t root = vertex_of_corner[3 * i + c];
      auto found = vertex_of_root.find(root);
      if(found == vertex_of_root.end())
      {
        found = vertex_of_root.emplace(root, patch.mesh.add_vertex(m.point(m.target(h)))).first;
        patch.segmented_vertex.push_back(m.target(h));
      }
      corners[c++] = found->second;
    }
    if(patch.mesh.add_face(corners[0], corners[1], corners[2]) == Extracted_patch::Mesh::null_face())
      throw Error(Error_code::INVALID_INPUT, "extract_patch: the patch is not a manifold surface (internal error)");
    patch.segmented_face.push_back(faces[i]);
  }
  std::vector<bool> seen(patch.mesh.number_of_halfedges(), false);
  for(auto h : patch.mesh.halfedges())
    if(patch.mesh.is_border(h) && !seen[h])
    {
      ++patch.boundary_loops;
      for(auto g : CGAL::halfedges_around_face(h, patch.mesh))
        seen[g] = true;
    }
  const long euler = long(patch.mesh.number_of_vertices()) - long(patch.mesh.number_of_edges()) + long(patch.mesh.number_of_faces());
  patch.genus = (2 - euler - long(patch.boundary_loops)) / 2;
  return patch;
}

namespace internal {
namespace segmentation {

// Splits every face of polygon `f` (more than 3 sides) into a fan around the target of `h`.
inline void fan_triangulate(Segmentation& s, Mesh::Halfedge_index h)
{
  Mesh& m = s.mesh;
  const Segmentation::Face f = m.face(h);
  while(m.degree(m.face(h)) > 3)
  {
    const Mesh::Halfedge_index far = m.next(m.next(h));
    const Mesh::Halfedge_index diagonal = CGAL::Euler::split_face(h, far, m);
    for(Segmentation::Face g : {m.face(diagonal), m.face(m.opposite(diagonal))})
    {
      s.patch[g] = s.patch[f];
      s.input_face[g] = s.input_face[f];
    }
    // Keep `h` in the part that still has more than 3 sides.
    if(m.degree(m.face(h)) == 3 && m.degree(m.face(m.opposite(diagonal))) > 3)
      h = m.prev(m.opposite(diagonal));
  }
}

// Cuts the faces `faces` (one patch) by `plane`: edges crossing it are split at the crossing,
// faces on both sides are split along the cut, and the faces on the negative side get the new
// label `negative_label`. Vertices within `snap` of the plane count as on it, so the cut does
// not make needlessly tiny triangles. Returns false if the plane leaves every face on one side.
inline bool cut_by_plane(Segmentation& s, const std::vector<Segmentation::Face>& faces, const Epick::Plane_3& plane,
                         double snap, std::size_t negative_label)
{
  Mesh& m = s.mesh;
  const double norm = std::sqrt(CGAL::to_double(plane.orthogonal_vector().squared_length()));
  auto distance = [&](Segmentation::Vertex v) {
    const Epick::Point_3& p = m.point(v);
    return (plane.a() * p.x() + plane.b() * p.y() + plane.c() * p.z() + plane.d()) / norm;
  };
  // Vertices on patch boundaries snap from farther: a cut that meets a boundary near one of its
  // vertices ends there, rather than making a short boundary piece next to it (which would
  // leave a short output edge and thin triangles beside it).
  auto on_curve = [&](Segmentation::Vertex v) {
    for(auto h : CGAL::halfedges_around_target(m.halfedge(v), m))
      if(s.is_curve_edge(m.edge(h)))
        return true;
    return false;
  };
  std::map<Segmentation::Vertex, int> side;
  bool positive = false, negative = false;
  for(Segmentation::Face f : faces)
    for(auto v : CGAL::vertices_around_face(m.halfedge(f), m))
      if(!side.count(v))
      {
        const double d = distance(v);
        side[v] = std::abs(d) <= (on_curve(v) ? 5. * snap : snap) ? 0 : (d > 0. ? 1 : -1);
        positive = positive || side[v] > 0;
        negative = negative || side[v] < 0;
      }
  if(!positive || !negative)
    return false;

  // 1. Split the crossing edges at the crossing point (on the input edge, so on the surface).
  std::vector<Segmentation::Edge> crossing;
  for(Segmentation::Face f : faces)
    for(auto h : CGAL::halfedges_around_face(m.halfedge(f), m))
      if(side[m.source(h)] * side[m.target(h)] < 0)
        crossing.push_back(m.edge(h));
  std::sort(crossing.begin(), crossing.end());
  crossing.erase(std::unique(crossing.begin(), crossing.end()), crossing.end());
  std::vector<Segmentation::Face> touched;
  std::vector<Segmentation::Vertex> on_cut;
  for(Segmentation::Edge e : crossing)
  {
    const Mesh::Halfedge_index h = m.halfedge(e);
    const Epick::Point_3 a = m.point(m.source(h)), b = m.point(m.target(h));
    const double da = distance(m.source(h)), db = distance(m.target(h));
    const double t = da / (da - db);
    const bool feature = s.is_feature[e], user_border = s.is_user_border[e];
    const Mesh::Halfedge_index to_new = CGAL::Euler::split_edge(h, m);
    const Segmentation::Vertex v = m.target(to_new);
    m.point(v) = Epick::Point_3(a.x() + t * (b.x() - a.x()), a.y() + t * (b.y() - a.y()), a.z() + t * (b.z() - a.z()));
    side[v] = 0;
    on_cut.push_back(v);
    s.is_feature[m.edge(to_new)] = s.is_feature[e] = feature;
    s.is_user_border[m.edge(to_new)] = s.is_user_border[e] = user_border;
    for(auto g : {to_new, m.opposite(to_new)})
      if(!m.is_border(g))
        touched.push_back(m.face(g));
  }

  // 2. Faces of the patch with vertices on both sides are split between their two cut
  //    vertices; every face left with more than 3 sides is split into a fan.
  std::vector<Segmentation::Face> patch_faces(faces);
  for(Segmentation::Face f : touched)
    patch_faces.push_back(f);
  std::sort(patch_faces.begin(), patch_faces.end());
  patch_faces.erase(std::unique(patch_faces.begin(), patch_faces.end()), patch_faces.end());
  const std::size_t label = s.patch[faces.front()];
  for(Segmentation::Face f : patch_faces)
  {
    if(m.degree(f) == 3)
      continue;
    std::vector<Mesh::Halfedge_index> to_cut; // halfedges of f whose target is on the plane
    bool has_positive = false, has_negative = false;
    for(auto h : CGAL::halfedges_around_face(m.halfedge(f), m))
    {
      has_positive = has_positive || (side.count(m.target(h)) && side[m.target(h)] > 0);
      has_negative = has_negative || (side.count(m.target(h)) && side[m.target(h)] < 0);
      if(side.count(m.target(h)) && side[m.target(h)] == 0)
        to_cut.push_back(h);
    }
    Mesh::Halfedge_index apex = to_cut.empty() ? m.halfedge(f) : to_cut.front();
    if(s.patch[f] == label && has_positive && has_negative)
    {
      // The two cut vertices that are not neighbours along the face separate the sides.
      for(std::size_t i = 0; i < to_cut.size(); ++i)
        for(std::size_t j = i + 1; j < to_cut.size(); ++j)
          if(m.next(to_cut[i]) != to_cut[j] && m.next(to_cut[j]) != to_cut[i])
          {
            const Mesh::Halfedge_index diagonal = CGAL::Euler::split_face(to_cut[i], to_cut[j], m);
            for(Segmentation::Face g : {m.face(diagonal), m.face(m.opposite(diagonal))})
            {
              s.patch[g] = s.patch[f];
              s.input_face[g] = s.input_face[f];
            }
            fan_triangulate(s, diagonal);
            fan_triangulate(s, m.opposite(diagonal));
            i = j = to_cut.size();
          }
      continue;
    }
    fan_triangulate(s, apex);
  }

  // 3. The faces of the patch on the negative side get their own label.
  std::vector<Segmentation::Face> stack;
  for(Segmentation::Vertex v : on_cut)
    for(Segmentation::Face f : CGAL::faces_around_target(m.halfedge(v), m))
      if(f != Mesh::null_face())
        stack.push_back(f);
  for(Segmentation::Face f : faces)
    stack.push_back(f);
  for(Segmentation::Face f : stack)
  {
    if(s.patch[f] != label)
      continue;
    int sum = 0;
    for(auto v : CGAL::vertices_around_face(m.halfedge(f), m))
      sum += side.count(v) ? side[v] : 0;
    if(sum < 0)
      s.patch[f] = negative_label;
  }
  ++s.plane_cuts;
  return true;
}

// The principal axes of a patch (area-weighted face centroids): the centroid and the axes from
// the smallest variance to the largest.
inline std::pair<Epick::Point_3, std::array<Epick::Vector_3, 3> > principal_axes(const Segmentation& s,
                                                                                const std::vector<Segmentation::Face>& faces)
{
  double area = 0.;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  std::vector<std::pair<double, Eigen::Vector3d> > samples;
  for(Segmentation::Face f : faces)
  {
    const auto h = s.mesh.halfedge(f);
    const Epick::Point_3 &a = s.mesh.point(s.mesh.source(h)), &b = s.mesh.point(s.mesh.target(h)),
                         &c = s.mesh.point(s.mesh.target(s.mesh.next(h)));
    const double w = std::sqrt(CGAL::cross_product(b - a, c - a).squared_length()) + 1e-300;
    const Eigen::Vector3d g((a.x() + b.x() + c.x()) / 3., (a.y() + b.y() + c.y()) / 3., (a.z() + b.z() + c.z()) / 3.);
    samples.emplace_back(w, g);
    centre += w * g;
    area += w;
  }
  centre /= area;
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for(const auto& sample : samples)
    covariance += sample.first * (sample.second - centre) * (sample.second - centre).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  std::array<Epick::Vector_3, 3> axes;
  for(int i = 0; i < 3; ++i) // eigenvalues in increasing order
    axes[i] = Epick::Vector_3(solver.eigenvectors()(0, i), solver.eigenvectors()(1, i), solver.eigenvectors()(2, i));
  return {Epick::Point_3(centre.x(), centre.y(), centre.z()), axes};
}

} // namespace segmentation
} // namespace internal

namespace internal {
namespace segmentation {

// After a cut of one patch into the labels `a` and `b`: each edge-connected piece of either label
// narrower than `min_width` (twice its area over its perimeter, the width of a strip) joins the
// piece across the cut with which it shares the longest boundary. A plane that grazes a long
// sliver face leaves such pieces; a patch thinner than the target edge length has a nearly
// degenerate sample polygon in the plane, which cannot be meshed. Returns false if one label is
// left without faces (the cut is undone).
inline bool merge_thin_pieces(Segmentation& s, std::size_t a, std::size_t b, double min_width)
{
  Mesh& m = s.mesh;
  const std::size_t none = std::size_t(-1);
  std::map<Segmentation::Face, std::size_t> piece;
  std::vector<Segmentation::Face> seeds;
  for(Segmentation::Face f : m.faces())
    if(s.patch[f] == a || s.patch[f] == b)
      piece[f] = none;
  std::vector<double> area, perimeter;
  std::vector<std::size_t> label;
  std::vector<std::vector<Segmentation::Face> > faces_of_piece;
  for(auto& seed : piece)
  {
    if(seed.second != none)
      continue;
    const std::size_t id = area.size();
    area.push_back(0.);
    perimeter.push_back(0.);
    label.push_back(s.patch[seed.first]);
    faces_of_piece.emplace_back();
    seed.second = id;
    std::vector<Segmentation::Face> stack{seed.first};
    while(!stack.empty())
    {
      const Segmentation::Face f = stack.back();
      stack.pop_back();
      faces_of_piece[id].push_back(f);
      const auto h0 = m.halfedge(f);
      area[id] += 0.5 * std::sqrt(CGAL::cross_product(m.point(m.target(h0)) - m.point(m.source(h0)),
                                                      m.point(m.target(m.next(h0))) - m.point(m.source(h0))).squared_length());
      for(auto h : CGAL::halfedges_around_face(h0, m))
      {
        const Segmentation::Face g = m.face(m.opposite(h));
        if(g == Mesh::null_face() || s.is_feature[m.edge(h)] || s.patch[g] != s.patch[f])
        {
          perimeter[id] += std::sqrt(CGAL::squared_distance(m.point(m.source(h)), m.point(m.target(h))));
          continue;
        }
        std::size_t& seen = piece.at(g);
        if(seen == none)
        {
          seen = id;
          stack.push_back(g);
        }
      }
    }
  }
  for(std::size_t id = 0; id < area.size(); ++id)
  {
    if(!(2. * area[id] < min_width * perimeter[id]))
      continue;
    std::map<std::size_t, double> shared; // neighbouring piece across the cut -> boundary length
    for(Segmentation::Face f : faces_of_piece[id])
      for(auto h : CGAL::halfedges_around_face(m.halfedge(f), m))
      {
        const Segmentation::Face g = m.face(m.opposite(h));
        if(g != Mesh::null_face() && !s.is_feature[m.edge(h)] && piece.count(g) && piece[g] != id)
          shared[piece[g]] += std::sqrt(CGAL::squared_distance(m.point(m.source(h)), m.point(m.target(h))));
      }
    if(shared.empty())
      continue;
    const auto longest = std::max_element(shared.begin(), shared.end(),
                                          [](const auto& x, const auto& y) { return x.second < y.second; });
    label[id] = label[longest->first];
    for(Segmentation::Face f : faces_of_piece[id])
    {
      s.patch[f] = label[id];
      piece[f] = longest->first;
    }
  }
  return std::count(label.begin(), label.end(), a) > 0 && std::count(label.begin(), label.end(), b) > 0;
}

// The angle between the normals of the two faces of edge `e` in degrees (0: flat), 0 on a border.
inline double dihedral_turn(const Mesh& m, Segmentation::Edge e)
{
  const auto h = m.halfedge(e), o = m.opposite(h);
  if(m.is_border(h) || m.is_border(o))
    return 0.;
  const Epick::Vector_3 a = CGAL::Polygon_mesh_processing::compute_face_normal(m.face(h), m);
  const Epick::Vector_3 b = CGAL::Polygon_mesh_processing::compute_face_normal(m.face(o), m);
  return std::acos((std::max)(-1., (std::min)(1., a * b))) * 180. / CGAL_PI;
}

// The chains of the edges for which `in_chain` holds (edges joined at a vertex), each with its
// length, in the order of their first edge.
template <typename In_chain>
std::vector<std::pair<std::vector<Segmentation::Edge>, double> > edge_chains(const Mesh& m, const In_chain& in_chain)
{
  std::vector<std::pair<std::vector<Segmentation::Edge>, double> > chains;
  std::vector<char> seen(m.number_of_edges(), 0);
  for(Segmentation::Edge seed : m.edges())
  {
    if(seen[seed] || !in_chain(seed))
      continue;
    std::vector<Segmentation::Edge> chain, stack{seed};
    seen[seed] = 1;
    double length = 0.;
    while(!stack.empty())
    {
      const Segmentation::Edge e = stack.back();
      stack.pop_back();
      chain.push_back(e);
      length += std::sqrt(CGAL::squared_distance(m.point(m.vertex(e, 0)), m.point(m.vertex(e, 1))));
      for(int k = 0; k < 2; ++k)
        for(auto h : CGAL::halfedges_around_target(m.halfedge(m.vertex(e, k)), m))
          if(!seen[m.edge(h)] && in_chain(m.edge(h)))
          {
            seen[m.edge(h)] = 1;
            stack.push_back(m.edge(h));
          }
    }
    chains.emplace_back(std::move(chain), length);
  }
  return chains;
}

// Feature chains inside a patch (the same patch on both sides) shorter than `min_length` in all
// are no features: they separate nothing, and a slit shorter than the target edge length opens
// so little in the plane that the mesher must split the edges that would join both of its sides
// (see `mesh_planar_domain()`). Unless an edge of the chain turns by more than `kept_turn`
// degrees: a crease that sharp is a detail of the shape, which the output would cut off (on a
// scanned model the short chains are wrinkles that turn much less, and are dropped).
inline void drop_short_dangling_features(Segmentation& s, double min_length, double kept_turn)
{
  const Mesh& m = s.mesh;
  const auto dangling = [&](Segmentation::Edge e) { return bool(s.is_feature[e]) && !s.is_patch_boundary(e); };
  for(const auto& chain : edge_chains(m, dangling))
    if(chain.second < min_length
       && std::none_of(chain.first.begin(), chain.first.end(), [&](Segmentation::Edge e) { return dihedral_turn(m, e) > kept_turn; }))
      for(Segmentation::Edge e : chain.first)
        s.is_feature[e] = false;
}

// The midpoints of the `crease` edges in cells of side `clearance`, to find the creases near a
// point.
class Crease_grid
{
public:
  Crease_grid(const Mesh& m, const std::vector<char>& crease, double clearance) : m_(m), cells_(clearance)
  {
    for(Segmentation::Edge e : m.edges())
      if(crease[e])
        cells_.cell_of(midpoint(e)).push_back(e);
  }

  Epick::Point_3 midpoint(Segmentation::Edge e) const { return CGAL::midpoint(m_.point(m_.vertex(e, 0)), m_.point(m_.vertex(e, 1))); }

  // Whether a crease edge for which `is_other` holds, sharing no vertex with `e`, has its
  // midpoint closer than the clearance to `e`'s.
  template <typename Is_other>
  bool has_other_crease_near(Segmentation::Edge e, const Is_other& is_other) const
  {
    const Epick::Point_3 p = midpoint(e);
    const double clearance = cells_.side();
    return cells_.any_near(p, [&](Segmentation::Edge f) {
      return is_other(f) && !shares_a_vertex(e, f) && CGAL::squared_distance(p, midpoint(f)) < clearance * clearance;
    });
  }

private:
  bool shares_a_vertex(Segmentation::Edge e, Segmentation::Edge f) const
  {
    for(int i = 0; i < 2; ++i)
      for(int j = 0; j < 2; ++j)
        if(m_.vertex(e, i) == m_.vertex(f, j))
          return true;
    return false;
  }

  const Mesh& m_;
  Grid_cells<Segmentation::Edge> cells_;
};

// Whether each end of `chain` (a vertex with one edge of the chain) is on a feature or a border
// outside the chain; a closed chain has no end.
inline bool ends_on_features(const Segmentation& s, const std::vector<Segmentation::Edge>& chain,
                             const std::vector<std::size_t>& chain_of, std::size_t c)
{
  const Mesh& m = s.mesh;
  for(Segmentation::Edge e : chain)
    for(int k = 0; k < 2; ++k)
    {
      int in_chain = 0;
      bool on_feature = false;
      for(auto h : CGAL::halfedges_around_target(m.halfedge(m.vertex(e, k)), m))
      {
        const Segmentation::Edge f = m.edge(h);
        if(chain_of[f] == c)
          ++in_chain;
        else if(s.is_feature[f] || m.is_border(f))
          on_feature = true;
      }
      if(in_chain == 1 && !on_feature)
        return false;
    }
  return true;
}

// Creases sharper than `angle` degrees but not features become features where they are the edges
// of a CAD part: chains at least `min_length` long that run from features to features (or
// borders, or close on themselves), at least 80% of whose edges have no other crease within
// `clearance`. An output that does not follow such a crease (a chamfer's edges, typically 30 to
// 60 degrees) cuts or bridges it, by up to a fifth of the target length. Short chains and chains
// that end in the open (the folds and wrinkles of scans and of coarse smooth models, where a
// feature's end would leave small angles) and creases close to parallel ones (the facets of a
// coarsely tessellated fillet or of a blade's sliver strips, where features would leave strips
// narrower than the target) stay inside their patches.
inline void add_cad_creases(Segmentation& s, double angle, double min_length, double clearance)
{
  const Mesh& m = s.mesh;
  std::vector<char> crease(m.number_of_edges(), 0);
  for(Segmentation::Edge e : m.edges())
    crease[e] = s.is_feature[e] || dihedral_turn(m, e) > angle;
  const std::vector<std::pair<std::vector<Segmentation::Edge>, double> > chains
    = edge_chains(m, [&](Segmentation::Edge e) { return crease[e] && !s.is_feature[e]; });
  std::vector<std::size_t> chain_of(m.number_of_edges(), chains.size());
  for(std::size_t c = 0; c < chains.size(); ++c)
    for(Segmentation::Edge e : chains[c].first)
      chain_of[e] = c;
  const Crease_grid grid(m, crease, clearance);
  std::vector<Segmentation::Edge> kept;
  for(std::size_t c = 0; c < chains.size(); ++c)
  {
    if(chains[c].second < min_length || !ends_on_features(s, chains[c].first, chain_of, c))
      continue;
    const auto is_other = [&](Segmentation::Edge f) { return chain_of[f] != c; };
    const std::size_t crowded = std::size_t(std::count_if(chains[c].first.begin(), chains[c].first.end(), [&](Segmentation::Edge e) {
      return grid.has_other_crease_near(e, is_other);
    }));
    if(double(crowded) <= 0.2 * double(chains[c].first.size()))
      kept.insert(kept.end(), chains[c].first.begin(), chains[c].first.end());
  }
  for(Segmentation::Edge e : kept)
    s.is_feature[e] = true;
}

} // namespace segmentation
} // namespace internal

/// \ingroup PkgConformalRemeshingRef
/// Cuts patch `patch_faces` of `s` in two by the plane through its centroid orthogonal to one
/// of its principal axes (`axis` 0: the axis of least extent, 2: of largest), trying the other
/// axes if that plane leaves the patch whole. The negative side gets the label
/// `s.number_of_patches` (incremented); call `s.renumber_patches()` after the last bisection.
/// Vertices closer than `snap` to the plane are taken as on it, and pieces narrower than
/// `5 * snap` that the cut leaves join the other side (pieces of grazed slivers), unless every
/// plane leaves only such pieces.
/// \returns false if no plane cuts the patch
inline bool bisect_patch(Poly_annulus_segmentation& s, const std::vector<Poly_annulus_segmentation::Face>& patch_faces,
                         int axis, double snap)
{
  const std::size_t label = s.patch[patch_faces.front()];
  const auto frame = internal::segmentation::principal_axes(s, patch_faces);
  // Thin pieces are merged back unless every cut makes only thin pieces (a strip narrower than
  // that): then the first cut is taken as it is.
  for(int attempt = 0; attempt < 6; ++attempt)
  {
    const int k = attempt % 3;
    const double min_width = attempt < 3 ? 5. * snap : 0.;
    // Listed afresh: a cut whose pieces all merged back has split faces all the same.
    const std::size_t negative = s.number_of_patches;
    if(!internal::segmentation::cut_by_plane(s, attempt == 0 ? patch_faces : s.faces_of_patch(label),
                                             Epick::Plane_3(frame.first, frame.second[(axis + k) % 3]), snap, negative))
      continue;
    if(internal::segmentation::merge_thin_pieces(s, label, negative, min_width))
    {
      ++s.number_of_patches;
      return true;
    }
    for(Poly_annulus_segmentation::Face f : s.faces_of_patch(negative))
      s.patch[f] = label;
    --s.plane_cuts;
  }
  return false;
}

/// \ingroup PkgConformalRemeshingRef
/// Segments a triangle mesh into poly-annuli: connected patches of genus 0 with at least one
/// boundary loop, each of which `conformal_flatten()` can flatten.
///
/// The surface is first cut by the given planes, then along sharp features (given, or detected
/// by dihedral angle) and the borders of user patches. Each piece that still has a handle or no
/// boundary is bisected by the plane through its centroid orthogonal to a principal axis (the
/// axis of least extent first, which cuts a plate or a brake disc through its mid-plane like
/// the paper's Fig. 9; a closed genus-0 piece along its largest axis), until every piece is a
/// poly-annulus. Cuts along planes are planar sections, not zig-zag edge paths.
///
/// \tparam TriangleMesh a model of `FaceListGraph`
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the 3D points of the vertices}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `%Point_3` as value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, mesh)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{edge_is_constrained_map}
///     \cgalParamDescription{the sharp features (a property map from edges to `bool`); replaces the detection}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%edge_descriptor` as key type and `bool` as value type}
///     \cgalParamDefault{detected with `features_angle`}
///   \cgalParamNEnd
///   \cgalParamNBegin{features_angle}
///     \cgalParamDescription{the dihedral angle in degrees above which an edge is sharp (`Conformal_remeshing::parameters::features_angle()`; 0 or less: no feature)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{60}
///   \cgalParamNEnd
///   \cgalParamNBegin{crease_angle}
///     \cgalParamDescription{edges with a dihedral angle in degrees above this but not above `features_angle` are sharp too where they are the edges of a CAD part: chains at least 50 times `snap_distance` long (5 target edge lengths in `remesh_conformal()`) that run from sharp features to sharp features or borders, most of whose edges have no other such crease within 10 times `snap_distance` (one target length), as a chamfer's edges; not the short folds of a scan, nor the facets of a coarsely tessellated fillet (`Conformal_remeshing::parameters::crease_angle()`; 0 or at least `features_angle`: none). Not used with `edge_is_constrained_map`}
///     \cgalParamType{`double`}
///     \cgalParamDefault{40}
///   \cgalParamNEnd
///   \cgalParamNBegin{face_patch_map}
///     \cgalParamDescription{user patches: a property map from faces to patch ids; their borders are cuts, kept as chains of output edges by `remesh_conformal()`}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and a value type convertible to `std::size_t`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{cut_planes}
///     \cgalParamDescription{planes (a `std::vector<CGAL::Epick::Plane_3>`) that cut the surface first (`Conformal_remeshing::parameters::cut_planes()`)}
///     \cgalParamType{`std::vector<CGAL::Epick::Plane_3>`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{snap_distance}
///     \cgalParamDescription{vertices closer to a cutting plane than this are taken as on it (`Conformal_remeshing::parameters::snap_distance()`); the scale of the smallest detail kept: pieces of a bisection narrower than 5 times this join the other side, of a strip between sharp features (or a feature and the border) narrower than half this the side that turns less is no feature along its edges at least 10 times this long (but not with `edge_is_constrained_map`), and feature chains inside a patch shorter than 10 times this are dropped unless they turn by more than 90 degrees somewhere (`remesh_conformal()` passes a tenth of the target edge length)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{0.001 times the bounding-box diagonal}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws Error with `Error_code::INVALID_INPUT` when the mesh is not a valid, manifold,
///         orientable triangle mesh (the message names the defect and one example; vertices at
///         the same point are accepted as distinct, see `Mesh_check_report::is_manifold_surface()`),
///         or when a piece cannot be made a poly-annulus.
template <typename TriangleMesh, typename NamedParameters = CGAL::parameters::Default_named_parameters>
void segment_into_poly_annuli(const TriangleMesh& input, Poly_annulus_segmentation& s,
                              const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor input_face;
  typedef typename boost::graph_traits<TriangleMesh>::edge_descriptor input_edge;
  typedef Poly_annulus_segmentation::Face Face;

  const Mesh_check_report checks = check_mesh(input, np);
  if(!checks.is_manifold_surface())
    throw Error(Error_code::INVALID_INPUT, "invalid input mesh: " + checks.summary());

  // --- a copy that remembers the input faces -------------------------------------------------
  s.reset();
  auto fim = CGAL::get_initialized_face_index_map(input, np);
  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(vertex_point, input));
  std::vector<std::pair<input_face, Face> > face_pairs;
  CGAL::copy_face_graph(input, s.mesh,
                        CGAL::parameters::vertex_point_map(vpm).face_to_face_output_iterator(std::back_inserter(face_pairs)));
  for(const auto& fp : face_pairs)
    s.input_face[fp.second] = get(fim, fp.first);

  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(s.mesh);
  const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin())
                                    + CGAL::square(box.zmax() - box.zmin()));
  const double snap = choose_parameter(get_parameter(np, internal_np::snap_distance), 1e-3 * diagonal);

  // --- features -------------------------------------------------------------------------------
  const auto given_features = get_parameter(np, CGAL::internal_np::edge_is_constrained);
  if constexpr(!std::is_same<std::decay_t<decltype(given_features)>, CGAL::internal_np::Param_not_found>::value)
  {
    // The copy keeps the edge order of a Surface_mesh input; in general, match by endpoints.
    std::map<std::pair<Epick::Point_3, Epick::Point_3>, bool> sharp;
    for(input_edge e : edges(input))
      if(get(given_features, e))
      {
        const auto a = get(vpm, source(e, input)), b = get(vpm, target(e, input));
        const Epick::Point_3 p(a.x(), a.y(), a.z()), q(b.x(), b.y(), b.z());
        sharp[std::minmax(p, q)] = true;
      }
    for(Poly_annulus_segmentation::Edge e : s.mesh.edges())
      s.is_feature[e] = sharp.count(std::minmax(s.mesh.point(s.mesh.vertex(e, 0)), s.mesh.point(s.mesh.vertex(e, 1)))) > 0;
  }
  else
  {
    const double angle = choose_parameter(get_parameter(np, internal_np::features_angle), 60.);
    const double crease = choose_parameter(get_parameter(np, internal_np::crease_angle), 40.);
    if(angle > 0.)
      CGAL::Polygon_mesh_processing::detect_sharp_edges(s.mesh, angle, s.is_feature);
    if(angle > 0. && crease > 0. && crease < angle && snap > 0.)
      internal::segmentation::add_cad_creases(s, crease, 50. * snap, 10. * snap);
    if(angle > 0.)
      s.narrow_strip_feature_edges = internal::segmentation::drop_narrow_strip_features(
        s.mesh, s.is_feature, 0.5 * snap, 10. * snap, [&](Poly_annulus_segmentation::Edge e) { return internal::segmentation::dihedral_turn(s.mesh, e); });
  }

  // --- user patches and planes ----------------------------------------------------------------
  const auto user_patches = get_parameter(np, CGAL::internal_np::face_patch);
  if constexpr(!std::is_same<std::decay_t<decltype(user_patches)>, CGAL::internal_np::Param_not_found>::value)
  {
    std::map<input_face, std::size_t> label;
    for(input_face f : faces(input))
      label[f] = std::size_t(get(user_patches, f));
    std::map<std::size_t, std::size_t> by_index;
    for(input_face f : faces(input))
      by_index[get(fim, f)] = label[f];
    for(Face f : s.mesh.faces())
      s.patch[f] = by_index[s.input_face[f]];
    for(Poly_annulus_segmentation::Edge e : s.mesh.edges())
      s.is_user_border[e] = s.is_patch_boundary(e) && !s.mesh.is_border(e);
  }
  s.renumber_patches();
  const std::vector<Epick::Plane_3> planes = choose_parameter(get_parameter(np, internal_np::cut_planes), std::vector<Epick::Plane_3>());
  for(const Epick::Plane_3& plane : planes)
  {
    // Faces are listed afresh for each patch: cutting one splits faces of its neighbours.
    const std::size_t before = s.number_of_patches;
    for(std::size_t p = 0; p < before; ++p)
      if(internal::segmentation::cut_by_plane(s, s.faces_of_patch(p), plane, snap, s.number_of_patches))
        ++s.number_of_patches;
    s.renumber_patches();
  }

  // --- bisection until every piece is a poly-annulus -------------------------------------------
  for(int round = 0;; ++round)
  {
    std::vector<std::pair<std::size_t, long> > pieces_to_cut; // patch, genus
    const std::vector<std::vector<Face> > patches = s.faces_of_patches();
    for(std::size_t p = 0; p < patches.size(); ++p)
    {
      const std::pair<long, std::size_t> genus_and_loops = internal::segmentation::patch_topology(s, patches[p]);
      if(genus_and_loops.first != 0 || genus_and_loops.second == 0) // not a poly-annulus
        pieces_to_cut.emplace_back(p, genus_and_loops.first);
    }
    if(pieces_to_cut.empty())
      break;
    for(const auto& piece : pieces_to_cut)
    {
      // Listed afresh: cutting one patch splits faces of its neighbours.
      const std::vector<Face> faces = s.faces_of_patch(piece.first);
      if(round >= 64)
        throw Error(Error_code::INVALID_INPUT, "segment_into_poly_annuli: a piece of " + std::to_string(faces.size())
                                                 + " faces keeps genus " + std::to_string(piece.second)
                                                 + " after 64 rounds of plane bisection");
      // A handle: the plane of least extent first (a plate's mid-plane), then the others in
      // turn from round to round; a closed sphere: across its largest extent.
      const int axis = piece.second > 0 ? (round % 3 == 0 ? 0 : round % 3 == 1 ? 2 : 1) : 2;
      if(!bisect_patch(s, faces, axis, snap))
        throw Error(Error_code::INVALID_INPUT, "segment_into_poly_annuli: no plane through its centroid cuts a piece of "
                                                 + std::to_string(faces.size()) + " faces of genus " + std::to_string(piece.second));
    }
    s.renumber_patches();
  }

  internal::segmentation::drop_short_dangling_features(s, 10. * snap, 90.);
  s.feature_edges = 0;
  s.dangling_feature_edges = 0;
  for(Poly_annulus_segmentation::Edge e : s.mesh.edges())
    if(s.is_feature[e])
    {
      ++s.feature_edges;
      s.dangling_feature_edges += !s.is_patch_boundary(e);
    }
}

} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_SEGMENT_INTO_POLY_ANNULI_H
