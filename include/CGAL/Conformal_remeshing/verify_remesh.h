// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Independent verification of a remeshing result against its input, and of a parameterization:
// the checks a user (or a test) runs to trust an output without trusting the code that made it.

#ifndef CGAL_CONFORMAL_REMESHING_VERIFY_REMESH_H
#define CGAL_CONFORMAL_REMESHING_VERIFY_REMESH_H

#include <CGAL/Conformal_remeshing/Error.h>
#include <CGAL/Conformal_remeshing/check_mesh.h>
#include <CGAL/Conformal_remeshing/check_planar_embedding.h>
#include <CGAL/Conformal_remeshing/parameters.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Conformal_remeshing/internal/crossing_faces.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/prepare_input.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>


namespace CGAL {
namespace Conformal_remeshing {

/// \ingroup PkgConformalRemeshingRef
/// What `verify_remesh()` found. Each `bool` says whether one guarantee holds; the counts say
/// how often it is broken. `is_valid()` is the conjunction of all of them.
struct Remesh_verification
{
  std::size_t output_vertices = 0;
  std::size_t output_faces = 0;
  /// the input checks of the output (`check_mesh()`)
  Mesh_check_report output_checks;

  /// a non-empty triangle mesh with a valid halfedge structure and no defect of
  /// `Mesh_defect` other than the manifoldness ones (finite coordinates, no degenerate face,
  /// no duplicated or isolated vertex)
  bool valid_triangle_mesh = false;
  /// no non-manifold edge or vertex, consistently oriented, orientable
  bool manifold = false;

  /// whether the self-intersection test could run (it needs a valid triangle mesh)
  bool self_intersections_checked = false;
  /// pairs of faces that intersect where they should not (exact predicates)
  std::size_t self_intersecting_face_pairs = 0;
  /// the test ran and found no intersecting pair
  bool self_intersection_free = false;

  /// the topology of every connected component of the input and of the output
  std::vector<Component_topology> input_components, output_components;
  /// as many components as the input
  bool same_number_of_components = false;
  /// the same genera, component for component (compared as sorted lists)
  bool same_genera = false;
  /// the same numbers of boundary loops, component for component (compared as sorted lists)
  bool same_boundary_loops = false;
  /// all of the above, with each component's genus and boundary loops matched together
  bool topology_kept = false;

  /// the input's bounding-box diagonal
  double input_diagonal = 0.;
  /// the largest distance an output vertex may have from the input surface
  double tolerance = 0.;
  /// the largest distance of an output vertex from the input surface
  double max_distance_to_input = 0.;
  /// output vertices farther than `tolerance` from the input surface
  std::size_t vertices_off_surface = 0;
  bool on_input_surface = false;

  /// whether vertex locations were given
  bool locations_checked = false;
  /// vertices whose given location is missing, invalid (a face that does not exist, coordinates
  /// that are not barycentric) or farther than `tolerance` from the vertex
  std::size_t vertices_off_location = 0;
  /// the largest distance between a vertex and the point of its location
  double max_location_error = 0.;
  /// every location was checked and holds, or none was given
  bool locations_match = false;

  /// `true` when every check holds
  bool is_valid() const
  {
    return valid_triangle_mesh && manifold && self_intersection_free && topology_kept && on_input_surface
           && locations_match;
  }

  /// One line: "valid: ..." with the main numbers, or "INVALID: " and every failed check with
  /// its counts, e.g. "INVALID: 3 self-intersecting face pairs; genus per component 1 -> 0".
  std::string summary() const
  {
    std::ostringstream out;
    out.precision(3);
    auto topology = [](const std::vector<Component_topology>& components) {
      if(components.empty())
        return std::string("no component with a topology");
      std::ostringstream s;
      s << components.size() << (components.size() == 1 ? " component" : " components") << " (genus";
      for(const Component_topology& c : components)
        s << " " << c.genus;
      s << "; boundary loops";
      for(const Component_topology& c : components)
        s << " " << c.boundary_loops;
      s << ")";
      return s.str();
    };
    if(is_valid())
    {
      out << "valid: " << output_vertices << " vertices, " << output_faces << " faces, topology kept: "
          << topology(output_components) << ", no self-intersection, every vertex within " << max_distance_to_input
          << " of the input surface (tolerance " << tolerance << ")";
      if(locations_checked)
        out << ", every vertex at its location (error " << max_location_error << ")";
      return out.str();
    }
    out << "INVALID: ";
    const char* separator = "";
    auto item = [&](const std::string& text) {
      out << separator << text;
      separator = "; ";
    };
    if(!valid_triangle_mesh || !manifold)
      item("output mesh: " + (output_checks.is_valid() ? std::string("invalid halfedge structure")
                                                       : output_checks.summary()));
    if(!self_intersections_checked)
      item("self-intersections not checked (not a valid triangle mesh)");
    else if(self_intersecting_face_pairs > 0)
      item(std::to_string(self_intersecting_face_pairs) + " self-intersecting face pair"
           + (self_intersecting_face_pairs == 1 ? "" : "s"));
    if(!topology_kept)
      item("topology changed: input " + topology(input_components) + ", output " + topology(output_components));
    if(!on_input_surface && vertices_off_surface == 0)
      item("distances to the input not checked");
    else if(!on_input_surface)
    {
      std::ostringstream s;
      s.precision(3);
      s << vertices_off_surface << " of " << output_vertices << " vertices off the input surface (max distance "
        << max_distance_to_input << ", tolerance " << tolerance << ")";
      item(s.str());
    }
    if(!locations_match)
    {
      std::ostringstream s;
      s.precision(3);
      s << vertices_off_location << " vertices not at their given location (max error " << max_location_error
        << ", tolerance " << tolerance << ")";
      item(s.str());
    }
    return out.str();
  }
};

namespace internal {

// Compares the topologies of two lists of components; fills the topology flags of `v`.
inline void compare_topologies(Remesh_verification& v)
{
  const std::vector<Component_topology>& in = v.input_components;
  const std::vector<Component_topology>& out = v.output_components;
  auto sorted = [](const std::vector<Component_topology>& components, auto key) {
    std::vector<decltype(key(components.front()))> values;
    for(const Component_topology& c : components)
      values.push_back(key(c));
    std::sort(values.begin(), values.end());
    return values;
  };
  v.same_number_of_components = in.size() == out.size();
  if(in.empty() || out.empty())
  {
    v.same_genera = v.same_boundary_loops = v.topology_kept = v.same_number_of_components && in.empty();
    return;
  }
  auto genus = [](const Component_topology& c) { return c.genus; };
  auto loops = [](const Component_topology& c) { return c.boundary_loops; };
  auto both = [](const Component_topology& c) { return std::make_pair(c.genus, c.boundary_loops); };
  v.same_genera = sorted(in, genus) == sorted(out, genus);
  v.same_boundary_loops = sorted(in, loops) == sorted(out, loops);
  v.topology_kept = v.same_number_of_components && sorted(in, both) == sorted(out, both);
}

namespace verification {

// A point in double precision, in the kernel of the input's points.
template <typename Kernel, typename Point>
typename Kernel::Point_3 double_point(const Point& p)
{
  return typename Kernel::Point_3(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
}

// Whether the coordinates of a point are finite.
template <typename Point_3>
bool is_finite_point(const Point_3& p)
{
  return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z());
}

// The input must be able to serve as a reference: a non-empty manifold triangle mesh with finite
// coordinates and no degenerate face; `input_checks` are its checks.
template <typename InputMesh>
void check_reference_mesh(const InputMesh& input, const Mesh_check_report& input_checks)
{
  if(faces(input).empty() || !is_triangle_mesh(input) || input_checks.count(Mesh_defect::NON_FINITE_COORDINATES) > 0
     || input_checks.count(Mesh_defect::DEGENERATE_FACE) > 0 || !input_checks.topology_available)
    throw Error(Error_code::INVALID_INPUT,
                "verify_remesh: the input must be a non-empty manifold triangle mesh with finite coordinates and no "
                "degenerate face (" + input_checks.summary() + ")");
}

// The distance queries construct points (projections onto the input's faces) in double
// precision, and CGAL's exact fallback traps on the NaN that a vanishing or overflowing square
// gives them: every squared edge length and squared double area of the input must be a
// normal number.
template <typename Kernel, typename InputMesh>
void check_reference_face_sizes(const InputMesh& input)
{
  typedef typename boost::graph_traits<InputMesh>::face_descriptor input_face_descriptor;
  typedef typename boost::graph_traits<InputMesh>::halfedge_descriptor input_halfedge_descriptor;
  const auto input_points = get(CGAL::vertex_point, input);
  std::size_t index = 0;
  for(input_face_descriptor f : faces(input))
  {
    const input_halfedge_descriptor h = halfedge(f, input);
    const typename Kernel::Point_3 p = double_point<Kernel>(get(input_points, source(h, input)));
    const typename Kernel::Point_3 q = double_point<Kernel>(get(input_points, target(h, input)));
    const typename Kernel::Point_3 r = double_point<Kernel>(get(input_points, target(next(h, input), input)));
    const double squares[] = {CGAL::to_double((q - p).squared_length()), CGAL::to_double((r - q).squared_length()),
                              CGAL::to_double((p - r).squared_length()),
                              CGAL::to_double(CGAL::cross_product(q - p, r - p).squared_length())};
    for(double x : squares)
      if(!std::isnormal(x))
        throw Error(Error_code::INVALID_INPUT, "verify_remesh: input face " + std::to_string(index)
                                                 + " is too small or too large for distances in double precision");
    ++index;
  }
}

// The input's diagonal and the distance tolerance, from the parameters and the input's box.
template <typename NamedParameters>
void set_distance_tolerance(Remesh_verification& v, const CGAL::Bbox_3& box, const NamedParameters& np)
{
  v.input_diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin())
                               + CGAL::square(box.zmax() - box.zmin()));
  // Fourth powers of lengths up to a hundred diagonals stay finite (see the distance queries).
  if(!(v.input_diagonal <= 1e70))
    throw Error(Error_code::INVALID_INPUT, "verify_remesh: the input's bounding-box diagonal exceeds 1e70, too much for "
                                           "distances in double precision");
  // A point on a face is stored to the precision of a double at the magnitude of the
  // coordinates: a relative tolerance finer than a few units in the last place of the largest
  // coordinate would fail exact remeshings of small parts far from the origin.
  const double magnitude = (std::max)({std::abs(box.xmin()), std::abs(box.xmax()), std::abs(box.ymin()),
                                       std::abs(box.ymax()), std::abs(box.zmin()), std::abs(box.zmax())});
  const double precision = 16. * (std::nextafter(magnitude, std::numeric_limits<double>::infinity()) - magnitude);
  const double relative = CGAL::parameters::choose_parameter(
    CGAL::parameters::get_parameter(np, internal_np::relative_distance_tolerance), 1e-9);
  if(!(relative >= 0.) || !std::isfinite(relative))
    throw Error(Error_code::INVALID_INPUT, "verify_remesh: the distance tolerance must be finite and non-negative");
  v.tolerance = CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np::distance_tolerance),
                                                   (std::max)(relative * v.input_diagonal, precision));
  if(!(v.tolerance >= 0.) || !std::isfinite(v.tolerance))
    throw Error(Error_code::INVALID_INPUT, "verify_remesh: the distance tolerance must be finite and non-negative");
}

// The output as a mesh: its sizes, its checks, whether it is a valid triangle mesh and a
// manifold one.
template <typename OutputMesh>
void check_output_mesh(Remesh_verification& v, const OutputMesh& output)
{
  // num_vertices() of a CGAL::Surface_mesh counts removed elements too: count the ranges.
  v.output_vertices = std::size_t(std::distance(vertices(output).begin(), vertices(output).end()));
  v.output_faces = std::size_t(std::distance(faces(output).begin(), faces(output).end()));
  v.output_checks = check_mesh(output);
  const Mesh_check_report& c = v.output_checks;
  const bool finite = c.count(Mesh_defect::NON_FINITE_COORDINATES) == 0;
  // CGAL's structural check counts an isolated vertex as broken; the defect list reports it.
  v.valid_triangle_mesh = c.count(Mesh_defect::EMPTY_MESH) == 0 && c.count(Mesh_defect::INVALID_VERTEX_INDEX) == 0
                          && finite && c.count(Mesh_defect::NON_TRIANGLE_FACE) == 0
                          && c.count(Mesh_defect::DEGENERATE_FACE) == 0 && c.count(Mesh_defect::ISOLATED_VERTEX) == 0
                          && is_valid_polygon_mesh(output); // distinct vertices may share a point, as the input's do
  v.manifold = c.count(Mesh_defect::NON_MANIFOLD_EDGE) == 0 && c.count(Mesh_defect::NON_MANIFOLD_VERTEX) == 0
               && c.count(Mesh_defect::INCONSISTENT_ORIENTATION) == 0 && c.count(Mesh_defect::NON_ORIENTABLE) == 0;
}

// The self-intersections of the output (a valid triangle mesh), with exact predicates.
template <typename Concurrency_tag, typename OutputMesh>
void check_self_intersections(Remesh_verification& v, const OutputMesh& output)
{
  typedef typename boost::graph_traits<OutputMesh>::face_descriptor output_face_descriptor;
  namespace PMP = CGAL::Polygon_mesh_processing;
  // Faces that only touch at distinct vertices of one point are a contact, not a crossing.
  const std::vector<std::pair<output_face_descriptor, output_face_descriptor> > pairs =
    internal::crossing_face_pairs<Concurrency_tag>(output);
  v.self_intersections_checked = true;
  // A pair (f, f) stands for a degenerate face, which the mesh checks already report.
  v.self_intersecting_face_pairs = std::size_t(std::count_if(pairs.begin(), pairs.end(),
                                                             [](const auto& p) { return p.first != p.second; }));
  v.self_intersection_free = v.self_intersecting_face_pairs == 0;
}

// The topologies of the input's and the output's components, compared.
inline void check_topology(Remesh_verification& v, const Mesh_check_report& input_checks)
{
  v.input_components = input_checks.components;
  v.output_components = v.output_checks.components;
  internal::compare_topologies(v);
}

// Every output vertex on the input surface.
template <typename Kernel, typename InputMesh, typename OutputMesh>
void check_distances_to_input(Remesh_verification& v, const InputMesh& input, const OutputMesh& output,
                              const CGAL::Bbox_3& box)
{
  const double squared_tolerance = v.tolerance * v.tolerance;
  typedef CGAL::AABB_face_graph_triangle_primitive<InputMesh> Primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive> > Tree;
  const Tree tree(faces(input).first, faces(input).second, input);
  const auto output_points = get(CGAL::vertex_point, output);
  for(auto w : vertices(output))
  {
    const typename Kernel::Point_3 p = double_point<Kernel>(get(output_points, w));
    // The tree's projections multiply up to four differences of coordinates: a point more than
    // a hundred diagonals from the input's box (or a non-finite one) could make them overflow
    // to NaN, so it is kept away from the tree, and its distance to the box is a lower bound.
    const double outside = CGAL::square((std::max)({box.xmin() - p.x(), p.x() - box.xmax(), 0.}))
                           + CGAL::square((std::max)({box.ymin() - p.y(), p.y() - box.ymax(), 0.}))
                           + CGAL::square((std::max)({box.zmin() - p.z(), p.z() - box.zmax(), 0.}));
    double d2 = std::numeric_limits<double>::infinity();
    if(is_finite_point(p))
      d2 = outside <= CGAL::square(100. * v.input_diagonal) ? CGAL::to_double(tree.squared_distance(p)) : outside;
    if(!(d2 <= squared_tolerance))
      ++v.vertices_off_surface;
    v.max_distance_to_input = (std::max)(v.max_distance_to_input, std::sqrt(d2));
  }
  v.on_input_surface = v.vertices_off_surface == 0;
}

// Every output vertex at its given location, if locations are given.
template <typename Kernel, typename InputMesh, typename OutputMesh, typename NamedParameters>
void check_vertex_locations(Remesh_verification& v, const InputMesh& input, const OutputMesh& output,
                            const NamedParameters& np)
{
  typedef typename boost::graph_traits<InputMesh>::face_descriptor input_face_descriptor;
  typedef typename boost::graph_traits<InputMesh>::halfedge_descriptor input_halfedge_descriptor;
  v.locations_match = true;
  if constexpr(!CGAL::parameters::is_default_parameter<NamedParameters, internal_np::vertex_locations_t>::value)
  {
    const auto& locations = CGAL::parameters::get_parameter_reference(np, internal_np::vertex_locations);
    v.locations_checked = true;
    auto fim = CGAL::get_initialized_face_index_map(input, np);
    std::vector<input_face_descriptor> face_at;
    for(input_face_descriptor f : faces(input))
    {
      const std::size_t index = std::size_t(get(fim, f));
      if(index >= face_at.size())
        face_at.resize(index + 1, boost::graph_traits<InputMesh>::null_face());
      face_at[index] = f;
    }
    const auto input_points = get(CGAL::vertex_point, input);
    const auto output_points = get(CGAL::vertex_point, output);
    const std::size_t nb_locations = std::size_t(locations.size());
    std::size_t i = 0;
    for(auto w : vertices(output))
    {
      double error = std::numeric_limits<double>::infinity();
      if(i < nb_locations)
      {
        const auto& location = locations[i];
        const std::size_t f = std::size_t(location.input_face);
        const double b[3] = {double(location.coordinates[0]), double(location.coordinates[1]),
                             double(location.coordinates[2])};
        // Barycentric: no coordinate below -1e-9 and a sum of 1 within 1e-9 (rounding only).
        const bool barycentric = std::isfinite(b[0]) && std::isfinite(b[1]) && std::isfinite(b[2])
                                 && (std::min)({b[0], b[1], b[2]}) >= -1e-9 && std::abs(b[0] + b[1] + b[2] - 1.) <= 1e-9;
        if(f < face_at.size() && face_at[f] != boost::graph_traits<InputMesh>::null_face() && barycentric)
        {
          const input_halfedge_descriptor h = halfedge(face_at[f], input);
          const typename Kernel::Point_3 p = double_point<Kernel>(get(input_points, source(h, input)));
          const typename Kernel::Point_3 q = double_point<Kernel>(get(input_points, target(h, input)));
          const typename Kernel::Point_3 r = double_point<Kernel>(get(input_points, target(next(h, input), input)));
          // Relative to a corner, so that a mesh far from the origin loses no precision.
          const typename Kernel::Point_3 x = p + b[1] * (q - p) + b[2] * (r - p);
          const typename Kernel::Point_3 y = double_point<Kernel>(get(output_points, w));
          if(is_finite_point(y))
            error = std::sqrt(CGAL::to_double(CGAL::squared_distance(x, y)));
        }
      }
      if(!(error <= v.tolerance))
        ++v.vertices_off_location;
      v.max_location_error = (std::max)(v.max_location_error, error);
      ++i;
    }
    v.locations_match = v.vertices_off_location == 0 && nb_locations == v.output_vertices;
  }
}

} // namespace verification

} // namespace internal

namespace internal {
namespace verification {

// Every check of verify_remesh() but the locations, with `reference`, whose checks are
// `reference_checks`, as the input.
template <typename Concurrency_tag, typename Kernel, typename ReferenceMesh, typename OutputMesh, typename NamedParameters>
void verify_against_reference(Remesh_verification& v, const ReferenceMesh& reference, const Mesh_check_report& reference_checks,
                              const OutputMesh& output, const NamedParameters& np)
{
  check_reference_mesh(reference, reference_checks);
  check_reference_face_sizes<Kernel>(reference);
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(reference);
  set_distance_tolerance(v, box, np);
  check_output_mesh(v, output);
  if(v.valid_triangle_mesh)
    check_self_intersections<Concurrency_tag>(v, output);
  check_topology(v, reference_checks);
  check_distances_to_input<Kernel>(v, reference, output, box);
}

} // namespace verification
} // namespace internal

/// \ingroup PkgConformalRemeshingRef
/// Verifies that `output` is a faithful remeshing of `input`, independently of how it was made:
///
/// - `output` is a valid triangle mesh (`check_mesh()`: finite coordinates, no degenerate
///   face by exact predicates, no duplicated or isolated vertex, a valid halfedge structure)
///   and a manifold one (no non-manifold edge or vertex);
/// - `output` does not self-intersect
///   (`CGAL::Polygon_mesh_processing::self_intersections()`, exact predicates);
/// - `output` has the topology of `input`: as many connected components, and the same genus and
///   number of boundary loops component for component;
/// - every vertex of `output` lies on the surface of `input` within the tolerance (the distance
///   to the closest point of an AABB tree of the input's faces);
/// - if vertex locations are given, every vertex of `output` is at the point of its location.
///
/// \tparam Concurrency_tag `CGAL::Parallel_if_available_tag` (the default),
///         `CGAL::Parallel_tag` or `CGAL::Sequential_tag`, for the self-intersection test
/// \tparam InputMesh, OutputMesh models of `FaceListGraph` and `HalfedgeListGraph` with an
///         internal point property map, whose points have the same kernel
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{distance_tolerance}
///     \cgalParamDescription{the largest distance allowed between an output vertex and the input
///                           surface, or its location, in the units of the input
///                           (`Conformal_remeshing::parameters::distance_tolerance()`)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`relative_distance_tolerance` times the input's bounding-box diagonal}
///   \cgalParamNEnd
///   \cgalParamNBegin{relative_distance_tolerance}
///     \cgalParamDescription{the same tolerance as a fraction of the input's bounding-box diagonal
///                           (`Conformal_remeshing::parameters::relative_distance_tolerance()`)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`1e-9`, raised if needed to 16 units in the last place of the largest
///                       input coordinate (the precision of a point at that magnitude)}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_locations}
///     \cgalParamDescription{where each output vertex should be on the input
///                           (`Conformal_remeshing::parameters::vertex_locations()`): a random
///                           access range with one element per vertex of `output`, in the order of
///                           `vertices(output)`, with the members `input_face` (the index of an
///                           input face in its face index map) and `coordinates` (three barycentric
///                           coordinates, in the corner order of
///                           `CGAL::Polygon_mesh_processing::locate()`), such as the
///                           `Surface_location`s of `remesh_conformal()`; pass it as
///                           `std::cref(range)` to avoid a copy}
///     \cgalParamType{a random access range, e.g. `std::vector<Surface_location>`, or a
///                    `std::reference_wrapper` to one}
///     \cgalParamDefault{none: the locations are not checked}
///   \cgalParamNEnd
///   \cgalParamNBegin{face_index_map}
///     \cgalParamDescription{the face index map of `input` that `input_face` refers to}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<InputMesh>::%face_descriptor` as key type and `std::size_t` as value type}
///     \cgalParamDefault{the internal face index map of `input`, initialized if needed}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns a report with one flag per check and the counts of the failures; `is_valid()` says
///          whether every check holds and `summary()` says it in one line.
/// An input with non-manifold vertices or degenerate faces is compared, for the topology and the
/// distances, with its copy repaired as `remesh_conformal()` repairs it (see its `repair_input`).
///
/// \throws Error with `Error_code::INVALID_INPUT` if `input` cannot serve as a reference even
///         after those repairs: empty, not a triangle mesh, with non-finite coordinates, faces
///         whose squared edge lengths or area underflow or overflow in double precision, a
///         bounding-box diagonal above 1e70, or non-manifold edges; or if a tolerance is negative
///         or not finite.
template <typename Concurrency_tag = CGAL::Parallel_if_available_tag, typename InputMesh, typename OutputMesh,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Remesh_verification verify_remesh(const InputMesh& input, const OutputMesh& output,
                                  const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef typename boost::property_map<InputMesh, CGAL::vertex_point_t>::const_type Input_point_map;
  typedef typename boost::property_traits<Input_point_map>::value_type Point;
  typedef typename CGAL::Kernel_traits<Point>::Kernel Kernel;
  namespace PMP = CGAL::Polygon_mesh_processing;
  namespace verification = internal::verification;

  // An input with non-manifold vertices or degenerate faces is compared, for its topology and
  // distances, with the copy that remesh_conformal() repairs and remeshes; the locations refer to
  // the input itself.
  const Mesh_check_report checks = check_mesh(input);
  Remesh_verification v;
  if(checks.count(Mesh_defect::NON_MANIFOLD_VERTEX) > 0 || checks.count(Mesh_defect::DEGENERATE_FACE) > 0)
  {
    Input_preparation_report repairs;
    const internal::remeshing::Prepared_input prepared = internal::remeshing::prepare_input(input, np, true, repairs);
    verification::verify_against_reference<Concurrency_tag, Epick>(v, prepared.mesh, check_mesh(prepared.mesh), output, np);
  }
  else
    verification::verify_against_reference<Concurrency_tag, Kernel>(v, input, checks, output, np);
  verification::check_vertex_locations<Kernel>(v, input, output, np);
  return v;
}

/// \ingroup PkgConformalRemeshingRef
/// What `verify_parameterization()` found.
struct Parameterization_verification
{
  /// vertices whose `uv` has a non-finite coordinate (the embedding is then not checked)
  std::size_t non_finite_vertices = 0;
  /// vertices whose `uv` has a coordinate beyond &plusmn;1e70, where the interval filters of the
  /// overlap test overflow (the embedding is then not checked)
  std::size_t out_of_range_vertices = 0;
  /// faces with other than three vertices (the embedding is then not checked)
  std::size_t non_triangle_faces = 0;
  /// whether the embedding test ran
  bool embedding_checked = false;
  /// the exact embedding test (`check_parameterization()` with overlaps counted)
  Planar_embedding_report embedding;

  /// `true` when the parameterization is an embedding: no folded, degenerate or overlapping
  /// triangle, simple and nested boundaries
  bool is_valid() const { return embedding_checked && embedding.is_embedding(); }

  /// "valid: embedding", or "INVALID: " and what is wrong, in one line
  std::string summary() const
  {
    if(is_valid())
      return "valid: embedding";
    if(!embedding_checked)
      return "INVALID: " + std::to_string(non_finite_vertices) + " vertices with non-finite uv, "
             + std::to_string(out_of_range_vertices) + " with uv beyond 1e70, "
             + std::to_string(non_triangle_faces) + " non-triangle faces";
    return "INVALID: " + embedding.summary();
  }
};

/// \ingroup PkgConformalRemeshingRef
/// Verifies with exact predicates that a parameterization of a triangle mesh (a `uv` point per
/// vertex) is an embedding: every `uv` is finite, no triangle is folded or degenerate, no two
/// triangles overlap, the boundary polygons are simple and the holes lie inside the outer
/// boundary. It runs `check_parameterization()` with the overlap count, after the checks that
/// keep the exact computations away from non-finite numbers and from coordinates beyond
/// &plusmn;1e70 (whose products overflow the interval filters).
///
/// \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
/// \tparam UVMap a readable property map from vertices to `Epick::Point_2`
template <typename TriangleMesh, typename UVMap>
Parameterization_verification verify_parameterization(const TriangleMesh& mesh, UVMap uv_map)
{
  Parameterization_verification v;
  for(auto w : vertices(mesh))
  {
    const Epick::Point_2 p = get(uv_map, w);
    if(!std::isfinite(p.x()) || !std::isfinite(p.y()))
      ++v.non_finite_vertices;
    else if(!(std::abs(p.x()) <= 1e70 && std::abs(p.y()) <= 1e70))
      ++v.out_of_range_vertices;
  }
  for(auto f : faces(mesh))
    if(degree(f, mesh) != 3)
      ++v.non_triangle_faces;
  if(v.non_finite_vertices == 0 && v.out_of_range_vertices == 0 && v.non_triangle_faces == 0)
  {
    v.embedding = check_parameterization(mesh, uv_map, true);
    v.embedding_checked = true;
  }
  return v;
}

} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_VERIFY_REMESH_H
