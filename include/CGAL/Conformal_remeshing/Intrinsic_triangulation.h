// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// An intrinsic triangulation: the connectivity of a triangulated surface plus one length per
// edge, with Euclidean edge flips, vertex scaling, planar layout, and a bijective map between
// the points of the current triangulation and the points of the input triangulation.

#ifndef CGAL_CONFORMAL_REMESHING_INTRINSIC_TRIANGULATION_H
#define CGAL_CONFORMAL_REMESHING_INTRINSIC_TRIANGULATION_H

#include <CGAL/Conformal_remeshing/Error.h>
#include <CGAL/Conformal_remeshing/internal/ricci_flow/triangle_geometry.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/number_utils.h>
#include <CGAL/property_map.h>

#include <boost/math/constants/constants.hpp>

#include <algorithm>
#include <array>
#include <limits>
#include <queue>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {

namespace internal {
namespace ricci_flow {

// Connectivity, per-corner lengths and per-corner constraint flags of a triangle face graph,
// indexed by the face index map. Kept outside the class, whose member names (next, source...)
// would hide the BGL free functions.
template <typename TriangleMesh, typename NamedParameters, typename FT>
void read_face_graph(const TriangleMesh& tm, const NamedParameters& np,
                     std::vector<std::array<int, 3>>& tris, std::vector<std::array<FT, 3>>& lens,
                     std::vector<char>& constrained)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename GetGeomTraits<TriangleMesh, NamedParameters>::type Geom_traits;
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename CGAL::internal_np::Lookup_named_param_def<CGAL::internal_np::edge_is_constrained_t, NamedParameters,
                                                             Static_boolean_property_map<typename GT::edge_descriptor, false>>::type Ecm;

  const Geom_traits gt = choose_parameter<Geom_traits>(get_parameter(np, CGAL::internal_np::geom_traits));
  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(vertex_point, tm));
  const Ecm ecm = choose_parameter<Ecm>(get_parameter(np, CGAL::internal_np::edge_is_constrained));
  auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  auto fim = CGAL::get_initialized_face_index_map(tm, np);
  auto sqd = gt.compute_squared_distance_3_object();

  const std::size_t nf = static_cast<std::size_t>(num_faces(tm));
  tris.assign(nf, std::array<int, 3>());
  lens.assign(nf, std::array<FT, 3>());
  constrained.assign(3 * nf, 0);
  for(typename GT::face_descriptor f : faces(tm))
  {
    if(!CGAL::is_triangle(halfedge(f, tm), tm))
      throw Error(Error_code::INVALID_INPUT, "Intrinsic_triangulation: the input mesh has a face that is not a triangle.");
    const std::size_t fi = get(fim, f);
    if(fi >= nf)
      throw Error(Error_code::INVALID_INPUT, "Intrinsic_triangulation: the face indices are not 0 .. number of faces - 1 (call collect_garbage()?).");
    typename GT::halfedge_descriptor h = halfedge(f, tm);
    for(int c = 0; c < 3; ++c, h = next(h, tm))
    {
      using std::sqrt;
      const std::size_t vi = get(vim, source(h, tm));
      if(vi >= static_cast<std::size_t>(num_vertices(tm)))
        throw Error(Error_code::INVALID_INPUT, "Intrinsic_triangulation: the vertex indices are not 0 .. number of vertices - 1 (call collect_garbage()?).");
      tris[fi][c] = static_cast<int>(vi);
      lens[fi][c] = sqrt(FT(CGAL::to_double(sqd(get(vpm, source(h, tm)), get(vpm, target(h, tm))))));
      constrained[3 * fi + c] = get(ecm, edge(h, tm)) ? 1 : 0;
    }
  }
}

} // namespace ricci_flow

namespace remeshing {
struct Patch_job_serialization; // writes a triangulation as bytes (remeshing/patch_job_io.h)
}
} // namespace internal

/// \ingroup PkgConformalRemeshingRef
///
/// A triangulation of a surface known only through its connectivity and its edge lengths
/// (a discrete Riemannian metric, paper Sec. 3.3), stored in compact index arrays.
///
/// **Indices.** Face `f` has the halfedges `3f`, `3f+1`, `3f+2` (its *corners* 0, 1, 2);
/// halfedge `3f+c` goes from `vertex(f,c)` to `vertex(f,(c+1)%3)`, counterclockwise. Vertices
/// keep the indices of the input. Faces keep the indices of the input until flips reuse them:
/// a flip replaces the two faces of an edge by two new faces with the same two indices.
///
/// **Flips.** Flips are *Euclidean*: the quadrilateral of the two triangles is laid out in the
/// plane and the new diagonal is measured there. The piecewise flat metric, hence every cone
/// angle and curvature, is unchanged by a flip, and the identity of the planar quadrilateral is
/// an exact bijection between the old and the new pair of triangles. A Euclidean flip is only
/// possible when the quadrilateral is strictly convex; this always holds for an edge that is not
/// Delaunay. (Ptolemy flips would change the metric of the quadrilateral and need a projective
/// point transfer through the hyperbolic picture; we do not use them.)
///
/// **Vertex scaling.** `scale_vertices(u)` multiplies the length of every edge `ij` by
/// `exp(u_i + u_j)` (paper Eqn. 3.5) on the current triangulation. It is *defined* to map each
/// triangle to its scaled self by keeping barycentric coordinates: an affine map per triangle,
/// which agrees on shared edges, hence a homeomorphism.
///
/// **Splits.** `split_edge()` inserts a point of an edge (its midpoint by default, in the current
/// metric) and joins it to the opposite corners. The planar layout of the edge's triangle(s) is again
/// shared by the old and new faces, so splits enter the correspondence like flips. A split
/// vertex gets the next vertex index; a new face gets the next face index.
///
/// **Correspondence.** Every flip and split is recorded with the planar layout of its triangles.
/// `to_input()` carries a point of the current triangulation back event by event (newest first),
/// `from_input()` carries a point of the input forward; each step is the identity of a planar
/// polygon cut in two ways and scaling keeps barycentric coordinates, so the composed map is a
/// bijection by construction. Only the events that touched the point's face are visited. Input locations use the convention of `CGAL::Polygon_mesh_processing::locate()`:
/// coordinate 0 belongs to `source(halfedge(f))`, 1 to `target(halfedge(f))`, 2 to
/// `target(next(halfedge(f)))`, which are exactly the corners 0, 1, 2 of the input face here.
///
/// \tparam FT_ the number type of lengths and coordinates, `double` by default; any field type
///         with `sqrt`, `atan`, `exp`, `log` found by argument-dependent lookup or in `std`
///         (e.g. `boost::multiprecision::mpfr_float`).
template <typename FT_ = double>
class Intrinsic_triangulation
{
public:
  /// Number type.
  typedef FT_ FT;
  /// A point of the plane.
  typedef std::array<FT, 2> Point_2;
  /// Barycentric coordinates with respect to the corners 0, 1, 2 of a face.
  typedef std::array<FT, 3> Barycentric_coordinates;
  /// A point of the surface: a face index and barycentric coordinates in that face.
  struct Face_location
  {
    int face;
    Barycentric_coordinates coordinates;
  };

  /// Creates an empty triangulation.
  Intrinsic_triangulation() {}

  /// Builds the triangulation of a triangle mesh `tm` (a model of `FaceListGraph`), with the
  /// Euclidean edge lengths of its embedding. Input vertices and faces are numbered by the
  /// vertex and face index maps.
  ///
  /// \cgalNamedParamsBegin
  ///   \cgalParamNBegin{vertex_point_map}
  ///     \cgalParamDescription{the 3D points of the vertices}
  ///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `%Point_3` as value type}
  ///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{geom_traits}
  ///     \cgalParamDescription{the traits class, of which only `Compute_squared_distance_3` is used}
  ///     \cgalParamType{a model of `Kernel`}
  ///     \cgalParamDefault{a kernel deduced from the point type, using `CGAL::Kernel_traits`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{vertex_index_map}
  ///     \cgalParamDescription{the numbering of the vertices, `0` to `num_vertices(tm) - 1`}
  ///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `std::size_t` as value type}
  ///     \cgalParamDefault{an automatically indexed internal map}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{face_index_map}
  ///     \cgalParamDescription{the numbering of the faces, `0` to `num_faces(tm) - 1`}
  ///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and `std::size_t` as value type}
  ///     \cgalParamDefault{an automatically indexed internal map}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{edge_is_constrained_map}
  ///     \cgalParamDescription{the edges that are marked unflippable}
  ///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%edge_descriptor` as key type and `bool` as value type}
  ///     \cgalParamDefault{no edge is constrained}
  ///   \cgalParamNEnd
  /// \cgalNamedParamsEnd
  ///
  /// \throws Error with `Error_code::INVALID_INPUT` when a face is not a triangle, a vertex is
  ///         isolated, an edge has length zero, or the index maps are not contiguous; with
  ///         `Error_code::DEGENERATE_METRIC` when a face is degenerate (collinear vertices).
  template <typename TriangleMesh, typename NamedParameters = CGAL::parameters::Default_named_parameters>
  explicit Intrinsic_triangulation(const TriangleMesh& tm,
                                   const NamedParameters& np = CGAL::parameters::default_values())
  {
    std::vector<std::array<int, 3>> tris;
    std::vector<std::array<FT, 3>> lens;
    std::vector<char> constrained;
    internal::ricci_flow::read_face_graph(tm, np, tris, lens, constrained);
    init(static_cast<std::size_t>(num_vertices(tm)), tris, lens);
    for(std::size_t h = 0; h < constrained.size(); ++h)
      if(constrained[h])
        unflippable_[he_edge_[h]] = 1;
  }

  /// Builds the triangulation from connectivity and lengths alone (no embedding needed, e.g. a
  /// welded mesh). `faces[f]` lists the vertices of face `f` counterclockwise;
  /// `lengths[f][c]` is the length of the edge from `faces[f][c]` to `faces[f][(c+1)%3]`.
  /// The two sides of an interior edge must give the same length (relative difference at most 1e-9).
  ///
  /// \throws Error with `Error_code::INVALID_INPUT` on a non-manifold or inconsistently oriented
  ///         connectivity, isolated vertices, out-of-range indices, or inconsistent lengths;
  ///         with `Error_code::DEGENERATE_METRIC` when a face violates the triangle inequality.
  Intrinsic_triangulation(std::size_t number_of_vertices,
                          const std::vector<std::array<int, 3>>& faces,
                          const std::vector<std::array<FT, 3>>& lengths)
  {
    init(number_of_vertices, faces, lengths);
  }

  /// \name Combinatorics
  /// @{
  int number_of_vertices() const { return nv_; }
  int number_of_faces() const { return static_cast<int>(he_vertex_.size() / 3); }
  int number_of_edges() const { return static_cast<int>(edge_he_.size()); }
  int number_of_halfedges() const { return static_cast<int>(he_vertex_.size()); }
  /// Euler characteristic V - E + F.
  int euler_characteristic() const { return number_of_vertices() - number_of_edges() + number_of_faces(); }

  static int face(int h) { return h / 3; }
  static int next(int h) { return 3 * (h / 3) + (h % 3 + 1) % 3; }
  static int prev(int h) { return 3 * (h / 3) + (h % 3 + 2) % 3; }
  static int halfedge(int f, int c) { return 3 * f + c; }
  /// The halfedge on the other side of the edge of `h`, or -1 on the boundary.
  int opposite(int h) const { return he_twin_[h]; }
  int source(int h) const { return he_vertex_[h]; }
  int target(int h) const { return he_vertex_[next(h)]; }
  int vertex(int f, int c) const { return he_vertex_[3 * f + c]; }
  int edge(int h) const { return he_edge_[h]; }
  /// One halfedge of edge `e` (the one of a face if `e` is on the boundary).
  int halfedge(int e) const { return edge_he_[e]; }
  bool is_border_edge(int e) const { return he_twin_[edge_he_[e]] < 0; }
  bool is_border_vertex(int v) const { return vertex_on_border_[v] != 0; }
  /// @}

  /// \name Metric
  /// @{
  FT length(int e) const { return length_[e]; }
  const std::vector<FT>& edge_lengths() const { return length_; }
  /// Replaces all edge lengths (indexed by edge) without any check; see `is_valid()`.
  void set_edge_lengths(const std::vector<FT>& l) { length_ = l; }
  /// Replaces the length of edge `e` without any check.
  void set_length(int e, const FT& l) { length_[e] = l; }

  /// Vertex scaling (paper Eqn. 3.5): the length of edge `ij` becomes `exp(u_i) l_ij exp(u_j)`.
  /// Barycentric coordinates in every face are kept (see the class documentation).
  void scale_vertices(const std::vector<FT>& u)
  {
    using std::exp;
    for(int e = 0; e < number_of_edges(); ++e)
    {
      const int h = edge_he_[e];
      length_[e] *= exp(u[source(h)] + u[target(h)]);
    }
  }

  /// The lengths of the sides of face `f`: side `c` joins corners `c` and `c+1`.
  std::array<FT, 3> face_lengths(int f) const
  {
    return {{length_[he_edge_[3 * f]], length_[he_edge_[3 * f + 1]], length_[he_edge_[3 * f + 2]]}};
  }

  /// Whether every face satisfies the strict triangle inequality.
  bool is_valid() const
  {
    std::array<FT, 3> t;
    for(int f = 0; f < number_of_faces(); ++f)
      if(!internal::ricci_flow::half_angle_tangents(opposite_lengths(f), t))
        return false;
    return true;
  }

  /// The angle at corner `c` of face `f` (from the half-angle tangent: accurate for slivers).
  /// \throws Error with `Error_code::DEGENERATE_METRIC` if the face violates the triangle inequality.
  FT corner_angle(int f, int c) const
  {
    return internal::ricci_flow::angle_from_half_tangent(half_tangents(f)[c]);
  }

  /// The sum of the corner angles at every vertex.
  /// \throws Error with `Error_code::DEGENERATE_METRIC` if a face violates the triangle inequality.
  std::vector<FT> angle_sums() const
  {
    std::vector<FT> sum(nv_, FT(0));
    for(int f = 0; f < number_of_faces(); ++f)
    {
      const std::array<FT, 3> t = half_tangents(f);
      for(int c = 0; c < 3; ++c)
        sum[vertex(f, c)] += internal::ricci_flow::angle_from_half_tangent(t[c]);
    }
    return sum;
  }

  /// Discrete Gaussian curvature (paper Eqn. 3.4): `2 pi - sum of angles` at interior
  /// vertices, `pi - sum of angles` at boundary vertices.
  std::vector<FT> vertex_curvatures() const
  {
    std::vector<FT> k = angle_sums();
    const FT pi = boost::math::constants::pi<FT>();
    for(int v = 0; v < nv_; ++v)
      k[v] = (is_border_vertex(v) ? pi : FT(2) * pi) - k[v];
    return k;
  }

  /// Cotangent weight of edge `e`: the sum of the cotangents of the angles opposite `e`
  /// (one term on the boundary), paper Eqn. 3.7.
  FT cotangent_weight(int e) const { return opposite_cotangents(e).sum; }
  /// @}

  /// \name Flips
  /// @{
  /// Marks edge `e` as a constraint (seam, feature): it is never flipped.
  void set_unflippable(int e, bool b = true) { unflippable_[e] = b ? 1 : 0; }
  bool is_unflippable(int e) const { return unflippable_[e] != 0; }
  /// The edge of corner side `c` of face `f`, for marking constraints by input face and corner.
  int edge(int f, int c) const { return he_edge_[3 * f + c]; }

  /// Whether edge `e` is locally Delaunay: its two opposite angles sum to at most pi (paper
  /// Eqn. 3.3), tested as "sum of cotangents >= -tolerance", so that quadrilaterals cocircular
  /// up to rounding are not flipped back and forth. The tolerance is a few hundred ulps times
  /// `1 + cot^2` of each angle: angles computed from rounded lengths are off by some ulps, and
  /// `d cot = -(1 + cot^2) d angle`, so the cotangents of a CAD sliver's tiny or near-flat
  /// angles (up to 1e12) are only known to within about their square times the ulp. With a
  /// fixed tolerance, fans of such slivers flip in circles up to the flip cap on large CAD
  /// parts instead of reaching the Delaunay triangulation. Boundary edges are Delaunay.
  bool is_delaunay(int e) const
  {
    if(is_border_edge(e))
      return true;
    const Cotangents c = opposite_cotangents(e);
    return c.sum >= -delaunay_tolerance() * c.uncertainty;
  }

  /// Whether every flippable edge is locally Delaunay (unflippable edges are not tested).
  bool is_delaunay() const
  {
    for(int e = 0; e < number_of_edges(); ++e)
      if(!is_unflippable(e) && !is_delaunay(e))
        return false;
    return true;
  }

  /// Euclidean flip of edge `e` (see the class documentation). Returns false and changes
  /// nothing if `e` is on the boundary, unflippable, has the same face on both sides, its faces
  /// share another edge too, or its quadrilateral is not strictly convex.
  bool flip(int e)
  {
    namespace rf = internal::ricci_flow;
    if(is_border_edge(e) || is_unflippable(e))
      return false;
    const int h = edge_he_[e], t = he_twin_[h];
    const int fa = face(h), fb = face(t);
    if(fa == fb || faces_meet_elsewhere(h))
      return false;
    const int hn = next(h), hp = prev(h), tn = next(t), tp = prev(t);
    const int vi = source(h), vj = target(h), vk = source(hp), vl = source(tp);

    // Quad layout: i at the origin, j on the positive x axis, k above, l below.
    std::array<FT, 3> ta, tb;
    if(!rf::half_angle_tangents(opposite_lengths(fa), ta) || !rf::half_angle_tangents(opposite_lengths(fb), tb))
      return false;
    const int ca = h % 3, cb = t % 3; // corner of i in fa, of j in fb
    // Angle sums at i and j must stay below pi: tan(a/2) tan(b/2) < 1  <=>  a + b < pi.
    if(!(ta[ca] * tb[(cb + 1) % 3] < FT(1)) || !(ta[(ca + 1) % 3] * tb[cb] < FT(1)))
      return false;
    std::array<Point_2, 4> P; // labels: 0 = i, 1 = j, 2 = k, 3 = l
    P[0] = {{FT(0), FT(0)}};
    P[1] = {{length_[e], FT(0)}};
    P[2] = rf::third_point(P[0], P[1], length_[he_edge_[hp]], ta[ca]);
    // Triangle (j, i, l) is counterclockwise: l is the third point seen from j towards i.
    P[3] = rf::third_point(P[1], P[0], length_[he_edge_[tp]], tb[cb]);
    const FT dx = P[2][0] - P[3][0], dy = P[2][1] - P[3][1];
    using std::sqrt;
    const FT new_length = sqrt(dx * dx + dy * dy);
    // Rounding must not leave a new triangle that violates the triangle inequality.
    {
      std::array<FT, 3> t_new;
      if(!rf::half_angle_tangents(std::array<FT, 3>{{length_[he_edge_[hp]], length_[he_edge_[tn]], new_length}}, t_new) ||
         !rf::half_angle_tangents(std::array<FT, 3>{{length_[he_edge_[tp]], length_[he_edge_[hn]], new_length}}, t_new))
        return false;
    }

    Flip_record r(P);
    r.face_a = fa;
    r.face_b = fb;
    r.old_a[ca] = 0; r.old_a[(ca + 1) % 3] = 1; r.old_a[(ca + 2) % 3] = 2;
    r.old_b[cb] = 1; r.old_b[(cb + 1) % 3] = 0; r.old_b[(cb + 2) % 3] = 3;

    // New faces: fa = (k, i, l), fb = (l, j, k); the diagonal is slot 2 of both.
    struct Slot { int vertex, twin, edge; };
    const Slot s_ki{vk, he_twin_[hp], he_edge_[hp]}, s_il{vi, he_twin_[tn], he_edge_[tn]};
    const Slot s_lj{vl, he_twin_[tp], he_edge_[tp]}, s_jk{vj, he_twin_[hn], he_edge_[hn]};
    auto put = [this](int slot, const Slot& s) {
      he_vertex_[slot] = s.vertex;
      he_twin_[slot] = s.twin;
      he_edge_[slot] = s.edge;
      edge_he_[s.edge] = slot;
      if(s.twin >= 0)
        he_twin_[s.twin] = slot;
    };
    put(3 * fa + 0, s_ki);
    put(3 * fa + 1, s_il);
    put(3 * fb + 0, s_lj);
    put(3 * fb + 1, s_jk);
    const int da = 3 * fa + 2, db = 3 * fb + 2;
    he_vertex_[da] = vl; he_vertex_[db] = vk;
    he_twin_[da] = db; he_twin_[db] = da;
    he_edge_[da] = e; he_edge_[db] = e;
    edge_he_[e] = da;
    length_[e] = new_length;

    if(!record_history_)
      return true;
    expand_history();
    const int time = static_cast<int>(timeline_.size());
    timeline_.push_back(static_cast<int>(flips_.size()));
    flips_.push_back(r);
    face_events_[fa].push_back(time);
    face_events_[fb].push_back(time);
    return true;
  }

  /// Splits edge `e` at the point `fraction` of the way from `source(halfedge(e))` (in the
  /// current metric; the midpoint by default) and joins the new vertex to the opposite
  /// corner(s): one new face on the boundary, two inside. The new vertex lies exactly on
  /// the edge, so a split boundary or constrained edge stays a boundary or constrained chain (it
  /// maps into the input edge it came from, or across the input faces the edge crosses). The
  /// halves of an unflippable edge are unflippable. Returns the new vertex, or -1 if a face of
  /// `e` has the same edge twice, the faces of `e` share another edge too, a face violates the
  /// triangle inequality (also after the split, by rounding), or `fraction` leaves no length on
  /// one side.
  int split_edge(int e, const FT& fraction = FT(1) / FT(2))
  {
    namespace rf = internal::ricci_flow;
    const int h = edge_he_[e], t = he_twin_[h];
    const int fa = face(h), fb = t >= 0 ? face(t) : -1;
    if(fa == fb || faces_meet_elsewhere(h))
      return -1;
    std::array<FT, 3> ta, tb;
    if(!rf::half_angle_tangents(opposite_lengths(fa), ta) || (fb >= 0 && !rf::half_angle_tangents(opposite_lengths(fb), tb)))
      return -1;
    const int hn = next(h), hp = prev(h);
    const int vi = source(h), vj = target(h), vk = source(hp);
    const int ca = h % 3, cb = t >= 0 ? t % 3 : 0;
    Split_record r;
    r.n_old = fb >= 0 ? 2 : 1;
    r.points[0] = {{FT(0), FT(0)}};
    r.points[1] = {{length_[e], FT(0)}};
    r.points[2] = rf::third_point(r.points[0], r.points[1], length_[he_edge_[hp]], ta[ca]);
    const FT before = length_[e] * fraction, after = length_[e] - before; // lengths of (i, m) and (m, j)
    r.points[4] = {{before, FT(0)}};
    r.old_face[0] = fa;
    r.old_label[0][ca] = 0; r.old_label[0][(ca + 1) % 3] = 1; r.old_label[0][(ca + 2) % 3] = 2;
    auto dist = [](const Point_2& a, const Point_2& b) {
      using std::sqrt;
      return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]));
    };

    // Rounding must not leave a new triangle that violates the triangle inequality.
    {
      std::array<FT, 3> t_new;
      const FT l_mk = dist(r.points[4], r.points[2]);
      if(!(FT(0) < before && FT(0) < after) ||
         !rf::half_angle_tangents(std::array<FT, 3>{{before, l_mk, length_[he_edge_[hp]]}}, t_new) ||
         !rf::half_angle_tangents(std::array<FT, 3>{{after, l_mk, length_[he_edge_[hn]]}}, t_new))
        return -1;
      if(fb >= 0)
      {
        const Point_2 pl = rf::third_point(r.points[1], r.points[0], length_[he_edge_[prev(t)]], tb[cb]);
        const FT l_ml = dist(r.points[4], pl);
        if(!rf::half_angle_tangents(std::array<FT, 3>{{before, l_ml, length_[he_edge_[next(t)]]}}, t_new) ||
           !rf::half_angle_tangents(std::array<FT, 3>{{after, l_ml, length_[he_edge_[prev(t)]]}}, t_new))
          return -1;
      }
    }
    const int vm = nv_++;
    vertex_on_border_.push_back(fb < 0 ? 1 : 0);
    const char constrained = unflippable_[e];
    auto new_edge = [this](const FT& l, char flag) {
      edge_he_.push_back(-1);
      length_.push_back(l);
      unflippable_.push_back(flag);
      return static_cast<int>(edge_he_.size()) - 1;
    };
    auto new_face = [this]() {
      const int f = number_of_faces();
      he_vertex_.resize(he_vertex_.size() + 3, -1);
      he_twin_.resize(he_twin_.size() + 3, -1);
      he_edge_.resize(he_edge_.size() + 3, -1);
      if(record_history_)
      {
        expand_history();
        face_events_.emplace_back();
      }
      return f;
    };
    struct Slot { int vertex, twin, edge; };
    auto put = [this](int slot, const Slot& s) {
      he_vertex_[slot] = s.vertex;
      he_twin_[slot] = s.twin;
      he_edge_[slot] = s.edge;
      if(s.twin >= 0)
        he_twin_[s.twin] = slot;
    };
    const Slot s_jk{vj, he_twin_[hn], he_edge_[hn]}, s_ki{vk, he_twin_[hp], he_edge_[hp]};
    const int e_mj = new_edge(after, constrained), e_mk = new_edge(dist(r.points[4], r.points[2]), 0);
    const int fa2 = new_face();
    length_[e] = before;
    // fa = (i, m, k), fa2 = (m, j, k)
    put(3 * fa + 0, Slot{vi, -1, e});
    put(3 * fa + 1, Slot{vm, -1, e_mk});
    put(3 * fa + 2, s_ki);
    put(3 * fa2 + 0, Slot{vm, -1, e_mj});
    put(3 * fa2 + 1, s_jk);
    put(3 * fa2 + 2, Slot{vk, 3 * fa + 1, e_mk});
    r.new_face[0] = fa; r.new_label[0] = {{0, 4, 2}};
    r.new_face[1] = fa2; r.new_label[1] = {{4, 1, 2}};
    if(fb >= 0)
    {
      const int tn = next(t), tp = prev(t);
      const int vl = source(tp);
      r.points[3] = rf::third_point(r.points[1], r.points[0], length_[he_edge_[tp]], tb[cb]);
      r.old_face[1] = fb;
      r.old_label[1][cb] = 1; r.old_label[1][(cb + 1) % 3] = 0; r.old_label[1][(cb + 2) % 3] = 3;
      const Slot s_il{vi, he_twin_[tn], he_edge_[tn]}, s_lj{vl, he_twin_[tp], he_edge_[tp]};
      const int e_ml = new_edge(dist(r.points[4], r.points[3]), 0);
      const int fb2 = new_face();
      // fb = (j, m, l), fb2 = (m, i, l)
      put(3 * fb + 0, Slot{vj, 3 * fa2, e_mj});
      put(3 * fb + 1, Slot{vm, -1, e_ml});
      put(3 * fb + 2, s_lj);
      put(3 * fb2 + 0, Slot{vm, 3 * fa, e});
      put(3 * fb2 + 1, s_il);
      put(3 * fb2 + 2, Slot{vl, 3 * fb + 1, e_ml});
      r.new_face[2] = fb; r.new_label[2] = {{1, 4, 3}};
      r.new_face[3] = fb2; r.new_label[3] = {{4, 0, 3}};
    }
    else
    {
      vertex_on_border_[vi] = vertex_on_border_[vj] = 1;
    }
    // Halfedges moved to new slots: point their edges at them (any halfedge of an edge will do).
    for(int k = 0; k < 2 * r.n_old; ++k)
      for(int c = 0; c < 3; ++c)
        edge_he_[he_edge_[3 * r.new_face[k] + c]] = 3 * r.new_face[k] + c;

    if(!record_history_)
      return vm;
    expand_history();
    const int time = static_cast<int>(timeline_.size());
    timeline_.push_back(-1 - static_cast<int>(splits_.size()));
    splits_.push_back(r);
    for(int k = 0; k < 2 * r.n_old; ++k)
      if(face_events_[r.new_face[k]].empty() || face_events_[r.new_face[k]].back() != time)
        face_events_[r.new_face[k]].push_back(time);
    return vm;
  }

  /// Flips edges that are not Delaunay until every flippable edge is (Euclidean flips keep the
  /// metric, so this is the intrinsic Delaunay triangulation with the unflippable edges kept).
  /// Returns the number of flips.
  std::size_t make_delaunay()
  {
    std::vector<int> edges(number_of_edges());
    for(int e = 0; e < number_of_edges(); ++e)
      edges[e] = number_of_edges() - 1 - e; // popped from the back: edge 0 first
    return make_delaunay(edges);
  }

  /// The same, starting from `edges` only: flips spread from them to the sides of every
  /// flipped quadrilateral. Enough where the rest is known to be Delaunay, e.g. the link of a
  /// vertex just inserted by `split_edge()`. Costs what it flips, not the size of the mesh.
  std::size_t make_delaunay(std::vector<int> edges)
  {
    std::vector<int>& stack = edges;
    if(queued_.size() < edge_he_.size())
      queued_.resize(edge_he_.size(), 0);
    for(int e : stack)
      queued_[e] = 1;
    std::size_t count = 0;
    // Flips terminate in exact arithmetic; with rounding, near-cocircular quads could flip back
    // and forth, so the number of flips is capped far above what converging runs need.
    const std::size_t cap = 20 * std::size_t(number_of_edges()) + 1000;
    while(!stack.empty() && count < cap)
    {
      const int e = stack.back();
      stack.pop_back();
      queued_[e] = 0;
      if(is_unflippable(e) || is_border_edge(e) || is_delaunay(e) || !flip(e))
        continue;
      ++count;
      const int h = edge_he_[e], t = he_twin_[h];
      for(int g : {next(h), prev(h), next(t), prev(t)})
      {
        const int eg = he_edge_[g];
        if(!queued_[eg])
        {
          queued_[eg] = 1;
          stack.push_back(eg);
        }
      }
    }
    for(int e : stack) // left by the cap
      queued_[e] = 0;
    return count;
  }

  /// A copy of the current triangulation and metric that records no correspondence: its flips
  /// and splits are cheaper, and `to_input()` / `from_input()` must not be called on it. For
  /// trial computations (the path-following line search of `discrete_ricci_flow()`).
  Intrinsic_triangulation without_history() const
  {
    Intrinsic_triangulation t;
    t.nv_ = nv_;
    t.he_vertex_ = he_vertex_;
    t.he_twin_ = he_twin_;
    t.he_edge_ = he_edge_;
    t.edge_he_ = edge_he_;
    t.length_ = length_;
    t.unflippable_ = unflippable_;
    t.vertex_on_border_ = vertex_on_border_;
    t.record_history_ = false;
    return t;
  }

  /// Number of flips performed since construction (the length of the correspondence record).
  std::size_t number_of_flips() const { return flips_.size(); }
  /// The two faces of the `i`-th flip (a flip keeps the indices of the faces it relinks).
  std::pair<int, int> faces_of_flip(std::size_t i) const { return {flips_[i].face_a, flips_[i].face_b}; }
  /// Number of edge splits performed since construction.
  std::size_t number_of_splits() const { return splits_.size(); }
  /// Number of changes of the connectivity (flips and splits) since construction.
  std::size_t number_of_connectivity_changes() const { return timeline_.size(); }
  /// @}

  /// \name Layout
  /// @{
  /// The three corners of face `f` laid out in the plane, counterclockwise, corner 0 at the
  /// origin and corner 1 on the positive x axis.
  std::array<Point_2, 3> layout_face(int f) const
  {
    const std::array<FT, 3> t = half_tangents(f);
    std::array<Point_2, 3> p;
    p[0] = {{FT(0), FT(0)}};
    p[1] = {{length_[he_edge_[3 * f]], FT(0)}};
    p[2] = internal::ricci_flow::third_point(p[0], p[1], length_[he_edge_[3 * f + 2]], t[0]);
    return p;
  }

  /// Lays the triangulation out in the plane face by face (breadth first from face `seed`,
  /// each face unfolded across an edge of an already placed face). The result is meaningful for
  /// a topological disc whose interior vertices have zero curvature, e.g. after
  /// `discrete_ricci_flow()` with zero interior targets; then all corners of a vertex agree up
  /// to rounding and the vertex gets the position of its first placed corner.
  /// \param seed the face laid out first (corner 0 at the origin, corner 1 on the positive x axis)
  /// \param corner_positions if not null, receives the position of corner `c` of face `f` at index `3f+c`.
  /// \throws Error with `Error_code::DEGENERATE_METRIC` if a face violates the triangle inequality.
  std::vector<Point_2> layout(int seed = 0, std::vector<Point_2>* corner_positions = nullptr) const
  {
    const int nf = number_of_faces();
    std::vector<Point_2> corner(3 * nf);
    std::vector<char> placed_face(nf, 0), placed_vertex(nv_, 0);
    std::vector<Point_2> pos(nv_, Point_2{{FT(0), FT(0)}});
    std::vector<int> queue;
    queue.reserve(nf);
    for(int start = seed; start < seed + nf; ++start)
    {
      const int f0 = start % nf;
      if(placed_face[f0])
        continue;
      const std::array<Point_2, 3> p = layout_face(f0);
      for(int c = 0; c < 3; ++c)
        corner[3 * f0 + c] = p[c];
      placed_face[f0] = 1;
      queue.push_back(f0);
      for(std::size_t q = queue.size() - 1; q < queue.size(); ++q)
      {
        const int f = queue[q];
        for(int c = 0; c < 3; ++c)
        {
          const int v = vertex(f, c);
          if(!placed_vertex[v])
          {
            placed_vertex[v] = 1;
            pos[v] = corner[3 * f + c];
          }
          const int g = he_twin_[3 * f + c];
          if(g < 0 || placed_face[face(g)])
            continue;
          // g goes from corner (c+1) of f to corner c of f; its third corner is unfolded.
          const int fg = face(g), cg = g % 3;
          const std::array<FT, 3> t = half_tangents(fg);
          corner[g] = corner[3 * f + (c + 1) % 3];
          corner[next(g)] = corner[3 * f + c];
          corner[prev(g)] = internal::ricci_flow::third_point(corner[g], corner[next(g)],
                                                                length_[he_edge_[prev(g)]], t[cg]);
          placed_face[fg] = 1;
          queue.push_back(fg);
        }
      }
    }
    if(corner_positions != nullptr)
      *corner_positions = std::move(corner);
    return pos;
  }
  /// @}

  /// \name Correspondence with the input triangulation
  /// @{
  /// Maps a point of the current triangulation to the input triangulation (input face index
  /// and barycentric coordinates in the input's corner order).
  Face_location to_input(Face_location p) const
  {
    int time = static_cast<int>(timeline_.size());
    for(;;)
    {
      const Events ev = events_of(p.face);
      const int* it = std::lower_bound(ev.first, ev.second, time);
      if(it == ev.first)
        return p;
      time = *(--it);
      p = apply_event(time, p, /*forward=*/false);
    }
  }

  /// Maps a point of the input triangulation (input face index and barycentric coordinates in
  /// the input's corner order) to the current triangulation.
  Face_location from_input(Face_location p) const
  {
    int time = -1;
    for(;;)
    {
      const Events ev = events_of(p.face);
      const int* it = std::upper_bound(ev.first, ev.second, time);
      if(it == ev.second)
        return p;
      time = *it;
      p = apply_event(time, p, /*forward=*/true);
    }
  }

  /// Stores the correspondence record in one array, for `to_input()` and `from_input()` once
  /// the connectivity no longer changes: a walk back then reads each face's events from one
  /// place instead of following a pointer per face, and the record takes less memory (a
  /// triangulation of a million faces has as many lists of a few events). The arrays that the
  /// flips and splits grew give back their unused room too. A later flip or split restores the
  /// growable form first.
  void compact_history()
  {
    if(history_is_compact_)
      return;
    for(std::vector<int>* a : {&he_vertex_, &he_twin_, &he_edge_, &edge_he_, &timeline_})
      a->shrink_to_fit();
    length_.shrink_to_fit();
    unflippable_.shrink_to_fit();
    vertex_on_border_.shrink_to_fit();
    flips_.shrink_to_fit();
    splits_.shrink_to_fit();
    compact_event_start_.assign(1, 0);
    compact_event_start_.reserve(face_events_.size() + 1);
    compact_events_.clear();
    for(const std::vector<int>& ev : face_events_)
    {
      compact_events_.insert(compact_events_.end(), ev.begin(), ev.end());
      compact_event_start_.push_back(compact_events_.size());
    }
    compact_events_.shrink_to_fit();
    std::vector<std::vector<int>>().swap(face_events_);
    history_is_compact_ = true;
  }

  /// Keeps the correspondence record alone, compacted, and frees the connectivity and the edge
  /// lengths: for a triangulation that, its flow over, is only walked back and forth (the
  /// remesher holds one per patch through all its later stages, where the connectivity and
  /// lengths are about a third of the triangulation's memory). Afterwards `to_input()` and
  /// `from_input()` still answer as before; every other query sees a triangulation of no vertex,
  /// face or edge, and a flip or split is not allowed.
  void keep_only_correspondence()
  {
    compact_history();
    nv_ = 0;
    for(std::vector<int>* a : {&he_vertex_, &he_twin_, &he_edge_, &edge_he_})
      std::vector<int>().swap(*a);
    std::vector<FT>().swap(length_);
    for(std::vector<char>* a : {&unflippable_, &vertex_on_border_, &queued_})
      std::vector<char>().swap(*a);
  }
  /// @}

private:
  typedef std::pair<const int*, const int*> Events;

  // The events of face `f`, in order.
  Events events_of(int f) const
  {
    if(history_is_compact_)
      return {compact_events_.data() + compact_event_start_[f], compact_events_.data() + compact_event_start_[f + 1]};
    return {face_events_[f].data(), face_events_[f].data() + face_events_[f].size()};
  }

  // The growable form of the record, before a flip or split records itself.
  void expand_history()
  {
    if(!history_is_compact_)
      return;
    face_events_.resize(compact_event_start_.size() - 1);
    for(std::size_t f = 0; f < face_events_.size(); ++f)
      face_events_[f].assign(compact_events_.begin() + compact_event_start_[f], compact_events_.begin() + compact_event_start_[f + 1]);
    std::vector<std::size_t>().swap(compact_event_start_);
    std::vector<int>().swap(compact_events_);
    history_is_compact_ = false;
  }

  struct Flip_record
  {
    int face_a, face_b;
    std::array<signed char, 3> old_a, old_b; // quad label (0 i, 1 j, 2 k, 3 l) of each old corner
    // The quad's layout at flip time, i at the origin and j on the x axis: the length of ij and
    // the coordinates of k and l (5 numbers instead of 8: the flips' records are most of the
    // flow's memory on CAD parts, tens of millions of them on a 300k-vertex part).
    std::array<FT, 5> layout;

    Flip_record(const std::array<Point_2, 4>& points)
      : layout{{points[1][0], points[2][0], points[2][1], points[3][0], points[3][1]}}
    {}
    Point_2 point(signed char label) const
    {
      switch(label)
      {
      case 0: return {{FT(0), FT(0)}};
      case 1: return {{layout[0], FT(0)}};
      case 2: return {{layout[1], layout[2]}};
      default: return {{layout[3], layout[4]}};
      }
    }
  };

  struct Split_record
  {
    int n_old;                                   // 1 (boundary edge) or 2 faces split
    std::array<int, 2> old_face;
    std::array<std::array<signed char, 3>, 2> old_label;
    std::array<int, 4> new_face;                 // 2 n_old new faces
    std::array<std::array<signed char, 3>, 4> new_label;
    std::array<Point_2, 5> points;               // labels: 0 i, 1 j, 2 k, 3 l, 4 the new vertex m
  };

  Face_location apply_event(int time, const Face_location& p, bool forward) const
  {
    const int index = timeline_[time];
    if(index >= 0)
      return transfer(flips_[index], p, forward);
    const Split_record& r = splits_[-1 - index];
    const int n_from = forward ? r.n_old : 2 * r.n_old, n_to = forward ? 2 * r.n_old : r.n_old;
    const signed char* from = nullptr;
    for(int k = 0; k < n_from; ++k)
      if((forward ? r.old_face[k] : r.new_face[k]) == p.face)
        from = forward ? r.old_label[k].data() : r.new_label[k].data();
    CGAL_assertion(from != nullptr);
    Point_2 q{{FT(0), FT(0)}};
    for(int c = 0; c < 3; ++c)
      for(int d = 0; d < 2; ++d)
        q[d] += p.coordinates[c] * r.points[from[c]][d];
    Face_location best{-1, Barycentric_coordinates()};
    FT best_min(0);
    for(int k = 0; k < n_to; ++k)
    {
      const signed char* to = forward ? r.new_label[k].data() : r.old_label[k].data();
      const Barycentric_coordinates b = internal::ricci_flow::barycentric(r.points[to[0]], r.points[to[1]], r.points[to[2]], q);
      const FT m = (std::min)({b[0], b[1], b[2]});
      if(best.face < 0 || m > best_min)
      {
        best = Face_location{forward ? r.new_face[k] : r.old_face[k], b};
        best_min = m;
      }
    }
    return best;
  }

  static FT delaunay_tolerance() { return FT(256) * std::numeric_limits<FT>::epsilon(); }

  // Whether the faces on the two sides of halfedge `h` also meet along another side (a vertex
  // of degree 2 between them), or one of them along two of its own sides. flip() and
  // split_edge() relink the other sides of the two faces assuming they lead to other faces;
  // here they would leave twins that no longer point at each other, and walks around a vertex
  // that never end, filling the memory.
  bool faces_meet_elsewhere(int h) const
  {
    const int t = he_twin_[h];
    const int fa = face(h), fb = t >= 0 ? face(t) : -1;
    for(int g : {next(h), prev(h), t >= 0 ? next(t) : -1, t >= 0 ? prev(t) : -1})
      if(g >= 0 && he_twin_[g] >= 0 && (face(he_twin_[g]) == fa || face(he_twin_[g]) == fb))
        return true;
    return false;
  }

  // The cotangents of the angles opposite edge `e` (one on the boundary): their sum, and the
  // factor by which their rounding error exceeds an angle's (1 + the sum of their squares).
  struct Cotangents
  {
    FT sum, uncertainty;
  };
  Cotangents opposite_cotangents(int e) const
  {
    Cotangents c{FT(0), FT(1)};
    const int h = edge_he_[e];
    for(int g : {h, he_twin_[h]})
      if(g >= 0)
      {
        const FT cot = internal::ricci_flow::cot_from_half_tangent(half_tangents(face(g))[(g % 3 + 2) % 3]);
        c.sum += cot;
        c.uncertainty += cot * cot;
      }
    return c;
  }

  // Lengths of face f ordered as the sides opposite corners 0, 1, 2.
  std::array<FT, 3> opposite_lengths(int f) const
  {
    return {{length_[he_edge_[3 * f + 1]], length_[he_edge_[3 * f + 2]], length_[he_edge_[3 * f]]}};
  }

  std::array<FT, 3> half_tangents(int f) const
  {
    std::array<FT, 3> t;
    if(!internal::ricci_flow::half_angle_tangents(opposite_lengths(f), t))
      throw Error(Error_code::DEGENERATE_METRIC,
                  "Intrinsic_triangulation: face " + std::to_string(f) + " violates the triangle inequality.");
    return t;
  }

  // One flip step of the correspondence, forward (old pair -> new pair) or backward.
  static Face_location transfer(const Flip_record& r, const Face_location& p, bool forward)
  {
    static const signed char new_a[3] = {2, 0, 3}, new_b[3] = {3, 1, 2};
    const signed char* src;
    if(forward)
      src = (p.face == r.face_a) ? r.old_a.data() : r.old_b.data();
    else
      src = (p.face == r.face_a) ? new_a : new_b;
    const std::array<Point_2, 4> points{{r.point(0), r.point(1), r.point(2), r.point(3)}};
    Point_2 q{{FT(0), FT(0)}};
    for(int c = 0; c < 3; ++c)
      for(int d = 0; d < 2; ++d)
        q[d] += p.coordinates[c] * points[src[c]][d];
    const signed char* dst_a = forward ? new_a : r.old_a.data();
    const signed char* dst_b = forward ? new_b : r.old_b.data();
    const Barycentric_coordinates ba = internal::ricci_flow::barycentric(
        points[dst_a[0]], points[dst_a[1]], points[dst_a[2]], q);
    const Barycentric_coordinates bb = internal::ricci_flow::barycentric(
        points[dst_b[0]], points[dst_b[1]], points[dst_b[2]], q);
    const FT ma = (std::min)({ba[0], ba[1], ba[2]}), mb = (std::min)({bb[0], bb[1], bb[2]});
    return ma >= mb ? Face_location{r.face_a, ba} : Face_location{r.face_b, bb};
  }

  // The twin of each of the halfedges `0, ..., count - 1` (-1 on a border), given their vertices
  // (valid indices), found by bucketing them by their smaller vertex and sorting each bucket by
  // the other one (on a large mesh a hash map of directed edges spends its time missing the
  // cache). `repeated` receives the first halfedge whose directed edge is that of an earlier one, or
  // `count` if there is none: the connectivity is then non-manifold or inconsistently oriented
  // (three or more halfedges on one edge always repeat a direction).
  static std::vector<int> twins_of_halfedges(const std::vector<int>& he_vertex, int count, int number_of_vertices,
                                             int& repeated)
  {
    const auto source = [&](int h) { return he_vertex[h]; };
    const auto target = [&](int h) { return he_vertex[next(h)]; };
    const auto other_end = [&](int h) { return (std::max)(source(h), target(h)); }; // in its bucket
    std::vector<int> start(number_of_vertices + 1, 0);
    for(int h = 0; h < count; ++h)
      ++start[(std::min)(source(h), target(h)) + 1];
    for(int v = 0; v < number_of_vertices; ++v)
      start[v + 1] += start[v];
    std::vector<int> bucketed(count);
    {
      std::vector<int> fill(start.begin(), start.end() - 1);
      for(int h = 0; h < count; ++h)
        bucketed[fill[(std::min)(source(h), target(h))]++] = h;
    }
    std::vector<int> twin(count, -1);
    repeated = count;
    for(int v = 0; v < number_of_vertices; ++v)
    {
      const auto first = bucketed.begin() + start[v], last = bucketed.begin() + start[v + 1];
      // By the other vertex, then by direction (from `v` first), then in order.
      const auto order = [&](int h) { return std::make_tuple(other_end(h), source(h) != v, h); };
      std::sort(first, last, [&](int g, int h) { return order(g) < order(h); });
      for(auto i = first; i != last;)
      {
        const int w = other_end(*i);
        auto j = i;
        while(j != last && other_end(*j) == w)
          ++j;
        // [i, j): the halfedges of one edge, those leaving `v` first, each direction in order.
        const auto split = std::find_if(i, j, [&](int h) { return source(h) != v; });
        if(split - i > 1)
          repeated = (std::min)(repeated, *(i + 1));
        if(j - split > 1)
          repeated = (std::min)(repeated, *(split + 1));
        if(split - i == 1 && j - split == 1)
        {
          twin[*i] = *split;
          twin[*split] = *i;
        }
        i = j;
      }
    }
    return twin;
  }

  void init(std::size_t number_of_vertices,
            const std::vector<std::array<int, 3>>& faces,
            const std::vector<std::array<FT, 3>>& lengths)
  {
    if(faces.size() != lengths.size())
      throw Error(Error_code::INVALID_INPUT, "Intrinsic_triangulation: one length triple per face is required.");
    if(faces.empty())
      throw Error(Error_code::INVALID_INPUT, "Intrinsic_triangulation: the input has no face.");
    nv_ = static_cast<int>(number_of_vertices);
    const int nf = static_cast<int>(faces.size());
    he_vertex_.assign(3 * nf, -1);
    he_twin_.assign(3 * nf, -1);
    he_edge_.assign(3 * nf, -1);
    edge_he_.clear();
    length_.clear();
    // The first halfedge, in face order, with an invalid or repeated vertex index, and the first
    // with a non-positive length; the halfedges before the first are checked for a repeated
    // directed edge. The first of the three in face order is reported (at one halfedge, in this
    // order).
    for(int f = 0; f < nf; ++f)
      for(int c = 0; c < 3; ++c)
        he_vertex_[3 * f + c] = faces[f][c];
    int invalid = 3 * nf, non_positive = 3 * nf;
    for(int f = 0; f < nf && invalid == 3 * nf; ++f)
      for(int c = 0; c < 3; ++c)
      {
        const int a = faces[f][c], b = faces[f][(c + 1) % 3];
        if(a < 0 || a >= nv_ || b < 0 || b >= nv_ || a == b)
        {
          invalid = 3 * f + c;
          break;
        }
        if(!(lengths[f][c] > FT(0)) && non_positive == 3 * nf)
          non_positive = 3 * f + c;
      }
    int repeated = invalid; // the halfedges before `invalid` have valid vertices at both ends
    const std::vector<int> twin = twins_of_halfedges(he_vertex_, invalid, nv_, repeated);
    if(repeated < invalid && repeated <= non_positive)
      throw Error(Error_code::INVALID_INPUT, "Intrinsic_triangulation: edge (" + std::to_string(he_vertex_[repeated]) +
                                                 ", " + std::to_string(he_vertex_[next(repeated)]) +
                                                 ") is non-manifold or faces are inconsistently oriented.");
    if(non_positive < invalid)
      throw Error(Error_code::INVALID_INPUT, "Intrinsic_triangulation: face " + std::to_string(non_positive / 3) +
                                                 " has an edge of non-positive length.");
    if(invalid < 3 * nf)
      throw Error(Error_code::INVALID_INPUT, "Intrinsic_triangulation: face " + std::to_string(invalid / 3) +
                                                 " has an invalid or repeated vertex index.");
    std::vector<char> used(nv_, 0);
    for(int a : he_vertex_)
      used[a] = 1;
    for(int v = 0; v < nv_; ++v)
      if(!used[v])
        throw Error(Error_code::INVALID_INPUT, "Intrinsic_triangulation: vertex " + std::to_string(v) + " is isolated.");
    vertex_on_border_.assign(nv_, 0);
    for(int h = 0; h < 3 * nf; ++h)
    {
      if(he_edge_[h] >= 0)
        continue;
      const int a = he_vertex_[h], b = he_vertex_[next(h)];
      const int e = static_cast<int>(edge_he_.size());
      edge_he_.push_back(h);
      he_edge_[h] = e;
      const FT lh = lengths[h / 3][h % 3];
      length_.push_back(lh);
      const int t = twin[h];
      if(t < 0)
      {
        vertex_on_border_[a] = vertex_on_border_[b] = 1;
        continue;
      }
      using std::abs;
      const FT lt = lengths[t / 3][t % 3];
      if(abs(lh - lt) > FT(1e-9) * (lh > lt ? lh : lt))
        throw Error(Error_code::INVALID_INPUT, "Intrinsic_triangulation: the two sides of edge (" + std::to_string(a) +
                                                   ", " + std::to_string(b) + ") give different lengths.");
      he_twin_[h] = t;
      he_twin_[t] = h;
      he_edge_[t] = e;
    }
    unflippable_.assign(edge_he_.size(), 0);
    flips_.clear();
    splits_.clear();
    timeline_.clear();
    face_events_.assign(nf, std::vector<int>());
    compact_event_start_.clear();
    compact_events_.clear();
    history_is_compact_ = false;
    std::array<FT, 3> t;
    for(int f = 0; f < nf; ++f)
      if(!internal::ricci_flow::half_angle_tangents(opposite_lengths(f), t))
        throw Error(Error_code::DEGENERATE_METRIC, "Intrinsic_triangulation: face " + std::to_string(f) +
                                                       " violates the triangle inequality.");
  }

  int nv_ = 0;
  std::vector<int> he_vertex_, he_twin_, he_edge_, edge_he_;
  std::vector<FT> length_;
  std::vector<char> unflippable_, vertex_on_border_;
  std::vector<char> queued_; // make_delaunay()'s scratch: all 0 between calls
  std::vector<Flip_record> flips_;
  std::vector<Split_record> splits_;
  std::vector<int> timeline_;                   // event -> flip index, or -1 - split index
  std::vector<std::vector<int>> face_events_;   // per face, the events that touched it, in order
  // The same after compact_history(): the events of face f at [start[f], start[f + 1]).
  std::vector<std::size_t> compact_event_start_;
  std::vector<int> compact_events_;
  bool history_is_compact_ = false;
  bool record_history_ = true;

  friend struct internal::remeshing::Patch_job_serialization;
};

} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTRINSIC_TRIANGULATION_H
