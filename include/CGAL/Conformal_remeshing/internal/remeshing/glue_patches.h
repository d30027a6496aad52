// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The gluing stage of `remesh_conformal()`: the remeshed patches merged on their shared boundary
// samples into one triangle soup, improved across the cuts between patches (collapses of short
// edges at samples, flips, and moves of the cuts' samples on the input surface), made a mesh and checked for self-intersections with
// exact predicates. Improvements that make the output intersect itself are given up here; what
// still intersects is returned for the caller to mesh again finer (see mesh_and_glue.h).

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_GLUE_PATCHES_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_GLUE_PATCHES_H

#include <CGAL/Conformal_remeshing/Error.h>
#include <CGAL/Conformal_remeshing/Remeshing_report.h>
#include <CGAL/Conformal_remeshing/segment_into_poly_annuli.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/collapses_after_gluing.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/flips_after_gluing.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/mesh_patches.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/moves_after_gluing.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/sizing.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/tuning.h>

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Conformal_remeshing/internal/crossing_faces.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/property_map.h>

#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <functional>
#include <iterator>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace internal {
namespace remeshing {

// Why glued triangles are not a manifold surface: an edge used twice in the same direction, or a
// vertex where separate fans of triangles meet, with the place and the patches involved.
inline std::string describe_glue_defect(const std::vector<std::array<std::size_t, 3> >& triangles,
                                        const std::vector<std::size_t>& patch_of_triangle, const std::vector<Epick::Point_3>& points)
{
  auto at = [&](std::size_t v) {
    std::ostringstream out;
    out << "(" << points[v].x() << ", " << points[v].y() << ", " << points[v].z() << ")";
    return out.str();
  };
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> user; // directed edge -> triangle
  std::map<std::size_t, std::vector<std::pair<std::size_t, std::size_t> > > link; // vertex -> (next, previous) corners
  for(std::size_t t = 0; t < triangles.size(); ++t)
    for(int c = 0; c < 3; ++c)
    {
      const std::size_t a = triangles[t][c], b = triangles[t][(c + 1) % 3], z = triangles[t][(c + 2) % 3];
      const auto used = user.emplace(std::make_pair(a, b), t);
      if(!used.second)
        return "the edge from " + at(a) + " to " + at(b) + " is used in the same direction by patches "
               + std::to_string(patch_of_triangle[used.first->second]) + " and " + std::to_string(patch_of_triangle[t]);
      link[a].emplace_back(b, z);
    }
  for(const auto& star : link)
  {
    // The triangles around a manifold vertex form one fan: walk it from one triangle, forwards,
    // then backwards if it does not close (a border vertex). Edges are unique by now.
    std::map<std::size_t, std::size_t> next_of, previous_of;
    for(const auto& corner : star.second)
    {
      next_of[corner.first] = corner.second;
      previous_of[corner.second] = corner.first;
    }
    const std::size_t start = star.second.front().first;
    std::size_t walked = 1, v = star.second.front().second;
    for(; v != start && next_of.count(v) && walked < star.second.size(); ++walked)
      v = next_of[v];
    if(v != start)
      for(v = start; previous_of.count(v) && walked < star.second.size(); ++walked)
        v = previous_of[v];
    if(walked < star.second.size())
      return "the vertex at " + at(star.first) + " joins separate fans of triangles";
  }
  return "no defect found (internal error)";
}

/// The remeshed patches as one soup: the shared samples first, then each patch's interior points.
struct Glued_soup
{
  std::vector<Epick::Point_3> points;
  std::vector<Poly_annulus_segmentation::Face> point_face; ///< the segmented face holding each point
  std::vector<std::array<std::size_t, 3> > triangles;
  std::vector<std::size_t> patch_of_triangle;
};

/// \throws Error with `Error_code::NOT_AN_EMBEDDING` when the patches do not glue into a manifold
/// (an internal error: the patches were meshed so that they do).
inline Glued_soup glued_soup(const Meshed_patches& meshed)
{
  const Curve_samples& samples = meshed.samples;
  Glued_soup soup;
  soup.points = samples.points;
  soup.point_face = samples.face;
  for(const Remeshed_patch& r : meshed.remeshed)
  {
    soup.patch_of_triangle.insert(soup.patch_of_triangle.end(), r.triangles.size(), std::size_t(&r - meshed.remeshed.data()));
    const std::size_t offset = soup.points.size() - samples.points.size();
    soup.points.insert(soup.points.end(), r.interior_points.begin(), r.interior_points.end());
    soup.point_face.insert(soup.point_face.end(), r.interior_faces.begin(), r.interior_faces.end());
    for(std::array<std::size_t, 3> t : r.triangles)
    {
      for(std::size_t& c : t)
        if(c >= samples.points.size())
          c += offset;
      soup.triangles.push_back(t);
    }
  }
  if(!Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(soup.triangles))
    throw Error(Error_code::NOT_AN_EMBEDDING, "remesh_conformal: the remeshed patches do not glue into a manifold: "
                                                + describe_glue_defect(soup.triangles, soup.patch_of_triangle, soup.points)
                                                + " (internal error)");
  return soup;
}

/// The improvements of a glued soup across the cuts between patches, which the patches could not
/// make alone: their boundary chords and samples were fixed. The short edges at samples are
/// collapsed (collapses_after_gluing.h), chords between two samples flipped for shape, the cuts'
/// samples and their neighbours moved on the input surface (moves_after_gluing.h), the edges at
/// moved points flipped for shape again, then the triangles below 30 degrees (or the minimum
/// angle) flipped. `apply()` can be called again, without the moves, and `undo()` gives up the
/// collapses and flips: each starts from the soup as glued.
class Improvement_after_gluing
{
public:
  Improvement_after_gluing(Glued_soup& soup, const Curve_samples& samples, const Poly_annulus_segmentation& segmentation,
                           const Sizing& sizing, double longest_edge, double minimum_angle)
    : soup_(soup), samples_(samples), segmentation_(segmentation), sizing_(sizing), unmoved_points_(soup.points),
      unmoved_faces_(soup.point_face), glued_triangles_(soup.triangles), glued_patch_of_triangle_(soup.patch_of_triangle),
      longest_edge_(longest_edge), angle_((std::max)(30., minimum_angle))
  {}

  void apply(bool with_moves, Remeshing_statistics& statistics)
  {
    undo(statistics);
    soup_.points = unmoved_points_;
    soup_.point_face = unmoved_faces_;
    const auto size_at = [&](std::size_t i) { return sizing_.at(soup_.points[i], soup_.point_face[i]); };
    std::vector<Poly_annulus_segmentation::Face> visited;
    Glued_soup_collapser collapser(soup_.points, soup_.triangles, soup_.patch_of_triangle, samples_, angle_,
                                   [&](const Epick::Point_3& p, std::size_t near) {
                                     const auto closest = closest_point_nearby(segmentation_, soup_.point_face[near], p, size_at(near), visited);
                                     return CGAL::squared_distance(p, closest.first);
                                   });
    statistics.collapses_after_gluing =
      collapser.collapse_short_edges([&](std::size_t a, std::size_t b) { return (std::min)(size_at(a), size_at(b)); }, sizing_.target());
    const auto is_sample = [&](std::size_t i) { return i < samples_.points.size(); };
    Glued_soup_flipper flipper(
      soup_.points, soup_.triangles, [&](std::size_t a, std::size_t b) { return collapser.is_kept_chord(a, b); }, angle_);
    flipper.shape_passes([&](std::size_t a, std::size_t b) { return is_sample(a) && is_sample(b); }, 3);
    statistics.moves_after_gluing = 0;
    if(with_moves)
    {
      const std::vector<char> movable = points_around_cuts(samples_, soup_.triangles, soup_.points.size());
      statistics.moves_after_gluing = move_points_after_gluing(segmentation_, soup_.points, soup_.point_face, soup_.triangles,
                                                           movable, angle_, longest_edge_, 5);
      if(statistics.moves_after_gluing > 0)
        flipper.shape_passes([&](std::size_t a, std::size_t b) { return movable[a] || movable[b]; }, 3);
    }
    flipper.angle_passes();
    statistics.flips_after_gluing = flipper.result().flips;
  }

  void undo(Remeshing_statistics& statistics)
  {
    soup_.triangles = glued_triangles_;
    soup_.patch_of_triangle = glued_patch_of_triangle_;
    statistics.flips_after_gluing = 0;
    statistics.collapses_after_gluing = 0;
  }

private:
  Glued_soup& soup_;
  const Curve_samples& samples_;
  const Poly_annulus_segmentation& segmentation_;
  const Sizing& sizing_;
  const std::vector<Epick::Point_3> unmoved_points_;
  const std::vector<Poly_annulus_segmentation::Face> unmoved_faces_;
  const std::vector<std::array<std::size_t, 3> > glued_triangles_;
  const std::vector<std::size_t> glued_patch_of_triangle_;
  double longest_edge_, angle_;
};

/// A glued output: the mesh, and for each of its vertices (in the order of `vertices(mesh)`) its
/// point and the segmented face holding it. Where the mesh intersects itself, `crossings` has the
/// centroids of the intersecting triangles, two per intersecting pair, and `crossing_patches`
/// the patches these triangles belong to.
template <typename TriangleMesh>
struct Glued_output
{
  TriangleMesh mesh;
  std::vector<Epick::Point_3> vertex_points;
  std::vector<Poly_annulus_segmentation::Face> vertex_faces;
  bool intersects = false;
  std::vector<Epick::Point_3> crossings;
  std::set<std::size_t> crossing_patches;
};

/// The mesh of the triangles of `soup`. Only the points some triangle uses become vertices: the
/// curves are sampled before the patches are meshed, and a sample that no patch triangle ends up
/// using must not stay an isolated vertex.
template <typename TriangleMesh>
void soup_to_mesh(const Glued_soup& soup, Glued_output<TriangleMesh>& output)
{
  typedef typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::type Point_map;
  typedef typename boost::property_traits<Point_map>::value_type Output_point;
  std::vector<std::array<std::size_t, 3> > triangles = soup.triangles;
  std::vector<std::size_t> vertex_index(soup.points.size(), 0), used_points;
  for(auto& t : triangles)
    for(std::size_t& c : t)
    {
      if(vertex_index[c] == 0)
      {
        used_points.push_back(c);
        vertex_index[c] = used_points.size();
      }
      c = vertex_index[c] - 1;
    }
  std::vector<Output_point> output_points;
  output_points.reserve(used_points.size());
  output.vertex_points.clear();
  output.vertex_faces.clear();
  for(std::size_t i : used_points)
  {
    output_points.push_back(Output_point(soup.points[i].x(), soup.points[i].y(), soup.points[i].z()));
    output.vertex_points.push_back(soup.points[i]);
    output.vertex_faces.push_back(soup.point_face[i]);
  }
  output.mesh = TriangleMesh();
  Polygon_mesh_processing::polygon_soup_to_polygon_mesh(output_points, triangles, output.mesh);
}

template <typename TriangleMesh>
std::vector<Epick::Point_3> centroids_of_intersecting_faces(const TriangleMesh& mesh)
{
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor Face;
  const std::vector<std::pair<Face, Face> > intersecting = crossing_face_pairs<CGAL::Sequential_tag>(mesh);
  const auto vp = get(CGAL::vertex_point, mesh);
  auto centroid = [&](Face f) {
    double c[3] = {0., 0., 0.};
    for(auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
    {
      const auto& p = get(vp, v);
      c[0] += CGAL::to_double(p.x()) / 3.;
      c[1] += CGAL::to_double(p.y()) / 3.;
      c[2] += CGAL::to_double(p.z()) / 3.;
    }
    return Epick::Point_3(c[0], c[1], c[2]);
  };
  std::vector<Epick::Point_3> centroids;
  for(const auto& pair : intersecting)
  {
    centroids.push_back(centroid(pair.first));
    centroids.push_back(centroid(pair.second));
  }
  return centroids;
}

/// The patches whose triangles in `soup` intersect others. (The soup is meshed again as a
/// `Surface_mesh`, whose faces are the soup's triangles in order.)
inline std::set<std::size_t> patches_of_intersecting_triangles(const Glued_soup& soup)
{
  typedef CGAL::Surface_mesh<Epick::Point_3> Soup_mesh;
  Soup_mesh mesh;
  Polygon_mesh_processing::polygon_soup_to_polygon_mesh(soup.points, soup.triangles, mesh);
  const std::vector<std::pair<Soup_mesh::Face_index, Soup_mesh::Face_index> > intersecting =
    crossing_face_pairs<CGAL::Sequential_tag>(mesh);
  std::set<std::size_t> patches;
  for(const auto& pair : intersecting)
    for(Soup_mesh::Face_index f : {pair.first, pair.second})
      if(std::size_t(f) < soup.patch_of_triangle.size())
        patches.insert(soup.patch_of_triangle[std::size_t(f)]);
  return patches;
}

/// The patches of `meshed` glued, improved after gluing and checked: no self-intersection may be
/// created (exact predicates). Where the output intersects itself and the input does not
/// (`input_self_intersects`, asked only then), the improvements with the moves are given up
/// first, then the flips too; what still intersects is in `crossings`.
template <typename ConcurrencyTag, typename TriangleMesh>
Glued_output<TriangleMesh> glue_patches(const Meshed_patches& meshed, const Poly_annulus_segmentation& segmentation,
                                        const Sizing& sizing, double minimum_angle,
                                        const std::function<bool()>& input_self_intersects, Remeshing_statistics& statistics)
{
  Glued_soup soup = glued_soup(meshed);
  Improvement_after_gluing improvement(soup, meshed.samples, segmentation, sizing, longest_edge_factor * sizing.target(), minimum_angle);
  improvement.apply(true, statistics);
  Glued_output<TriangleMesh> output;
  soup_to_mesh(soup, output);
  // Each glued mesh is checked once.
  output.intersects = has_crossing_faces<ConcurrencyTag>(output.mesh) && !input_self_intersects();
  if(output.intersects && statistics.moves_after_gluing > 0)
  {
    improvement.apply(false, statistics);
    soup_to_mesh(soup, output);
    output.intersects = has_crossing_faces<ConcurrencyTag>(output.mesh);
  }
  if(output.intersects && statistics.flips_after_gluing > 0)
  {
    improvement.undo(statistics);
    soup_to_mesh(soup, output);
    output.intersects = has_crossing_faces<ConcurrencyTag>(output.mesh);
  }
  if(output.intersects)
  {
    output.crossings = centroids_of_intersecting_faces(output.mesh);
    output.crossing_patches = patches_of_intersecting_triangles(soup); // the soup is as glued again
  }
  return output;
}

} // namespace remeshing
} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_GLUE_PATCHES_H
