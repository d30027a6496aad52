// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Dynamic discrete Ricci flow (paper Sec. 3.3, Alg. 4): Newton's method on the Ricci energy
// over vertex-scaling conformal factors, with the triangulation kept Delaunay by flips.

#ifndef CGAL_CONFORMAL_REMESHING_DISCRETE_RICCI_FLOW_H
#define CGAL_CONFORMAL_REMESHING_DISCRETE_RICCI_FLOW_H

#include <CGAL/Conformal_remeshing/Error.h>
#include <CGAL/Conformal_remeshing/parameters.h>
#include <CGAL/Conformal_remeshing/Intrinsic_triangulation.h>
#include <CGAL/Conformal_remeshing/internal/ricci_flow/lobachevsky.h>
#include <CGAL/Conformal_remeshing/internal/ricci_flow/triangle_geometry.h>
#include <CGAL/Conformal_remeshing/internal/time_limit.h>

#include <CGAL/Named_function_parameters.h>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <boost/math/constants/constants.hpp>

#include <chrono>
#include <cmath>
#include <functional>
#include <queue>
#include <sstream>
#include <string>
#include <tuple>
#include <type_traits>
#include <vector>


namespace CGAL {
namespace Conformal_remeshing {

/// \ingroup PkgConformalRemeshingRef
/// What `discrete_ricci_flow()` did.
template <typename FT>
struct Ricci_flow_result
{
  /// `SUCCESS` if the flow converged; `NOT_CONVERGED` if it stopped above the tolerance (too
  /// few iterations, or a line search that found no step), in which case the triangulation holds
  /// the best state seen: the one of the lowest curvature error
  Error_code status = Error_code::NOT_CONVERGED;
  bool converged = false;           ///< max |K̄ - K| fell below the tolerance, or reached its rounding floor (below)
  /// converged at the rounding floor: a full Newton step left the error within 100 times the
  /// tolerance without halving it (on large meshes with slivers the angle sums cannot be computed
  /// more accurately than ~1e-10, and further iterations only shuffle rounding errors)
  bool at_rounding_floor = false;
  int iterations = 0;               ///< Newton iterations
  int best_iteration = 0;           ///< the iteration whose state is returned (`iterations` unless the flow stopped in a worse state)
  int number_of_factorizations = 0; ///< numeric factorizations of the Hessian (the other iterations reuse one as a preconditioner)
  FT max_curvature_error = FT(0);   ///< max over vertices of |K̄ - K| in the returned state
  std::size_t number_of_flips = 0;  ///< edge flips from the input to the returned state
  std::size_t number_of_splits = 0; ///< edge splits from the input to the returned state (each adds one vertex)
  std::vector<FT> target_curvatures; ///< the targets of all vertices, including those added by splits (0)
  std::vector<FT> conformal_factors; ///< u per vertex, accumulated over the call (u[0] = 0; a vertex added by a split starts at 0)
  double seconds_flips = 0;         ///< time in flips to Delaunay
  double seconds_assembly = 0;      ///< time computing angles, curvatures and the Hessian
  double seconds_factorization = 0; ///< time in symbolic analysis and numeric factorization
  double seconds_solve = 0;         ///< time in triangular solves and preconditioned conjugate gradients
  double seconds_line_search = 0;   ///< time evaluating trial steps
  double seconds_total = 0;         ///< wall time of the call
  std::string message;              ///< why the flow stopped
};

/// \ingroup PkgConformalRemeshingRef
/// Target curvatures of the paper's disc flattening (Sec. 4.4): 0 at interior vertices and
/// 2&pi;/n at each of the n boundary vertices, so the layout is a convex polygon inscribed in a
/// circle. \throws Error with `Error_code::INVALID_INPUT` if the triangulation has no boundary.
template <typename FT>
std::vector<FT> disc_flattening_targets(const Intrinsic_triangulation<FT>& tri)
{
  int n = 0;
  for(int v = 0; v < tri.number_of_vertices(); ++v)
    n += tri.is_border_vertex(v) ? 1 : 0;
  if(n == 0)
    throw Error(Error_code::INVALID_INPUT, "disc_flattening_targets: the triangulation has no boundary.");
  const FT k = FT(2) * boost::math::constants::pi<FT>() / FT(n);
  std::vector<FT> targets(tri.number_of_vertices(), FT(0));
  for(int v = 0; v < tri.number_of_vertices(); ++v)
    if(tri.is_border_vertex(v))
      targets[v] = k;
  return targets;
}

namespace internal {
namespace ricci_flow {

template <typename T> struct Unwrap { typedef T type; };
template <typename T> struct Unwrap<std::reference_wrapper<T>> { typedef typename std::remove_const<T>::type type; };

// The Ricci energy of the fixed triangulation `tri` at lengths `l` (convex in the conformal
// factors; its gradient is K - K̄, its Hessian the cotangent matrix). Up to a constant:
//   E = sum_faces sum_corners [ (theta - pi/2) log l_opposite + Lob(theta) ] + sum_v Theta_v u_v
// with Theta_v the target angle sum. Evaluated in double: it only decides whether a step is
// accepted, and near convergence the gradient test takes over.
template <typename FT>
double ricci_energy(const Intrinsic_triangulation<FT>& tri, const std::vector<FT>& l,
                    const std::vector<double>& target_angle_sum, const std::vector<double>& u)
{
  const double half_pi = 1.5707963267948966;
  double e = 0;
  std::array<double, 3> len, t;
  for(int f = 0; f < tri.number_of_faces(); ++f)
  {
    for(int c = 0; c < 3; ++c)
      len[c] = static_cast<double>(l[tri.edge(Intrinsic_triangulation<FT>::halfedge(f, (c + 1) % 3))]);
    if(!half_angle_tangents(len, t))
      return std::numeric_limits<double>::infinity();
    for(int c = 0; c < 3; ++c)
    {
      const double theta = 2. * std::atan(t[c]);
      e += (theta - half_pi) * std::log(len[c]) + lobachevsky(theta);
    }
  }
  for(std::size_t v = 0; v < u.size(); ++v)
    e += target_angle_sum[v] * u[v];
  return e;
}

} // namespace ricci_flow
} // namespace internal

/// \ingroup PkgConformalRemeshingRef
///
/// Computes conformal factors `u` (paper Eqn. 3.5) such that the metric of `tri` scaled by `u`
/// has the curvature `target_curvature` at every vertex, and leaves `tri` in that metric,
/// Delaunay (apart from unflippable edges).
///
/// Each iteration computes the curvature K, solves the Newton system `H d = K̄ - K` with the
/// cotangent Hessian H (Eqn. 3.7-3.8) and the conformal factor of vertex 0 fixed (the global
/// scale is free: this is the gauge), then searches along `d` for a step that decreases the
/// convex Ricci energy of the current triangulation (Armijo test; when the energy difference is
/// below its rounding, a decrease of the residual norm is accepted instead) and keeps every
/// triangle valid; after the step, Euclidean flips restore the Delaunay property (paper Alg. 4).
/// Flips keep the metric, so the curvature is unchanged by them and the correspondence of `tri`
/// with its input stays a bijection.
///
/// Because edges are flipped after a finite step rather than at the moment they stop being
/// Delaunay, the result depends slightly on the steps taken when flips happen during the flow:
/// it is a flat metric with the target curvatures, reached by vertex scalings and
/// metric-preserving flips (the paper's Alg. 4), but not exactly the path-independent discrete
/// conformal metric of Gu, Luo, Sun and Wu. `exact_conformal_path(true)` gives that metric
/// (flipping each edge at the moment it stops being Delaunay), see below.
///
/// Boundary and unflippable edges cannot be flipped; when an angle opposite such an edge
/// exceeds the split angle (the triangle is close to degenerate and no flip can help), the edge
/// is split instead, at the foot of the altitude from the obtuse corner: both new triangles are
/// right-angled there, so one split cures the corner (a midpoint split does not when the corner
/// is off the middle, and slivers of CAD fans then take many rounds). A new vertex has target
/// curvature 0 (it lies on a straight piece of the target boundary, or in the flat interior);
/// `Ricci_flow_result::target_curvatures` lists the targets of all vertices, old and new.
///
/// \param tri the triangulation; on return it holds the final metric and triangulation
/// \param target_curvature K̄ per vertex, summing to 2&pi; times the Euler characteristic
/// \param np optional named parameters:
///   - `CGAL::parameters::number_of_iterations(n)`: maximum Newton iterations (default 50)
///   - `CGAL::Conformal_remeshing::parameters::curvature_tolerance(t)`: stop when max |K̄ - K| < t (default 1e-10),
///     or when a full Newton step leaves it below 100 t without halving it (its rounding floor,
///     `Ricci_flow_result::at_rounding_floor`)
///   - `CGAL::parameters::sparse_linear_solver(s)`: only the *type* of `s` is used: an Eigen sparse
///     solver for `Eigen::SparseMatrix<FT>` (default `Eigen::SimplicialLDLT<Eigen::SparseMatrix<FT>>`;
///     `Eigen::CholmodSupernodalLLT` is faster above a few 100k vertices);
///     the symbolic analysis is redone only after the connectivity changed, and an earlier
///     factorization is reused as a preconditioner of conjugate gradients while that converges
///     in a few iterations.
///   - `CGAL::parameters::callback(f)`: called as `f(iteration, max_error)` (`int`, `double`) before each iteration
///   - `CGAL::Conformal_remeshing::parameters::use_edge_flips(b)`: flips and splits (default `true`)
///   - `CGAL::Conformal_remeshing::parameters::edge_split_angle(a)`: the split angle in radians
///     (default 0.9&pi;; &pi; or more disables splitting)
///   - `CGAL::Conformal_remeshing::parameters::exact_conformal_path(b)`: path-following line
///     search, path-independent result (default `false`)
///   - `CGAL::Conformal_remeshing::parameters::maximum_running_time(s)`: a limit in seconds on
///     the wall-clock time of the call, checked before each Newton iteration (default: none)
///
/// A flow that stops above the tolerance (after `number_of_iterations`, or when the line search
/// finds no acceptable step) leaves `tri` in the best state it reached, the one with the lowest
/// curvature error, and reports `Error_code::NOT_CONVERGED` in `Ricci_flow_result::status`.
///
/// \throws Error with `Error_code::INVALID_INPUT` if the target vector has the wrong size or the
///         maximum running time is negative; with `Error_code::GAUSS_BONNET_VIOLATED` (before
///         any iteration or flip) if the targets do not sum to 2&pi;&chi;; with
///         `Error_code::DEGENERATE_METRIC` if the input metric is not valid; with
///         `Error_code::LINEAR_SOLVER_FAILED` if a factorization fails; with
///         `Error_code::TIME_LIMIT_EXCEEDED` when the maximum running time has passed before an
///         iteration (`tri` then holds the best state reached, like after non-convergence).
///         Non-convergence is reported in the result, not thrown.
template <typename FT, typename NamedParameters = CGAL::parameters::Default_named_parameters>
Ricci_flow_result<FT> discrete_ricci_flow(Intrinsic_triangulation<FT>& tri,
                                          const std::vector<FT>& target_curvature,
                                          const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using std::abs;
  using std::exp;
  namespace rf = internal::ricci_flow;
  typedef Eigen::SparseMatrix<FT> Matrix;
  typedef Eigen::Matrix<FT, Eigen::Dynamic, 1> Vector;
  typedef typename CGAL::internal_np::Lookup_named_param_def<CGAL::internal_np::sparse_linear_solver_t, NamedParameters,
                                                             Eigen::SimplicialLDLT<Matrix>>::type Solver_param;
  typedef typename rf::Unwrap<Solver_param>::type Solver;
  typedef std::chrono::steady_clock Clock;
  auto seconds = [](Clock::time_point a) { return std::chrono::duration<double>(Clock::now() - a).count(); };
  const Clock::time_point start = Clock::now();
  const FT pi = boost::math::constants::pi<FT>();

  const int max_iterations = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), 50);
  const FT tolerance = choose_parameter(get_parameter(np, internal_np::curvature_tolerance), FT(1e-10));
  const bool flips = choose_parameter(get_parameter(np, internal_np::use_edge_flips), true);
  const bool exact_path = choose_parameter(get_parameter(np, internal_np::exact_conformal_path), false);
  const FT split_angle = choose_parameter(get_parameter(np, internal_np::edge_split_angle), FT(9) * pi / FT(10));
  const std::function<void(int, double)> callback =
      choose_parameter(get_parameter(np, CGAL::internal_np::callback), std::function<void(int, double)>());
  const internal::Time_limit time_limit = internal::Time_limit::from(np, "discrete_ricci_flow");

  if(static_cast<int>(target_curvature.size()) != tri.number_of_vertices())
    throw Error(Error_code::INVALID_INPUT, "discrete_ricci_flow: expected " + std::to_string(tri.number_of_vertices()) +
                                               " target curvatures, got " + std::to_string(target_curvature.size()) + ".");
  {
    FT sum(0), magnitude(0);
    for(const FT& k : target_curvature)
    {
      sum += k;
      magnitude += abs(k);
    }
    const FT expected = FT(2) * pi * FT(tri.euler_characteristic());
    if(abs(sum - expected) > FT(1e-9) * (FT(1) + magnitude))
    {
      std::ostringstream os;
      os.precision(17);
      os << "discrete_ricci_flow: the target curvatures sum to " << static_cast<double>(sum)
         << " but the Gauss-Bonnet theorem requires 2*pi*chi = " << static_cast<double>(expected)
         << " (Euler characteristic " << tri.euler_characteristic() << ").";
      throw Error(Error_code::GAUSS_BONNET_VIOLATED, os.str());
    }
  }
  if(!tri.is_valid())
    throw Error(Error_code::DEGENERATE_METRIC, "discrete_ricci_flow: the input metric violates the triangle inequality.");

  Ricci_flow_result<FT> result;
  result.target_curvatures = target_curvature;
  result.conformal_factors.assign(tri.number_of_vertices(), FT(0));
  std::vector<FT>& target = result.target_curvatures;
  std::vector<double> target_angle_sum;
  auto update_angle_sums = [&]() {
    target_angle_sum.resize(target.size());
    for(std::size_t v = 0; v < target.size(); ++v)
      target_angle_sum[v] = static_cast<double>((tri.is_border_vertex(int(v)) ? pi : FT(2) * pi) - target[v]);
  };
  update_angle_sums();

  auto residual_on = [&](const Intrinsic_triangulation<FT>& T, std::vector<FT>& g) { // g = K - K̄; returns max |g|
    const std::vector<FT> k = T.vertex_curvatures();
    g.resize(k.size());
    FT m(0);
    for(std::size_t v = 0; v < k.size(); ++v)
    {
      g[v] = k[v] - target[v];
      if(abs(g[v]) > m)
        m = abs(g[v]);
    }
    return m;
  };
  auto residual = [&](std::vector<FT>& g) { return residual_on(tri, g); };

  // Flip to Delaunay; split boundary / unflippable edges whose opposite angles are too large.
  const std::size_t max_splits = 4 * static_cast<std::size_t>(tri.number_of_vertices()) + 1000;
  // Where the altitude from the corner opposite halfedge `h` meets it, as a fraction from its source.
  auto altitude_foot = [&tri](int h) {
    const FT l = tri.length(tri.edge(h)), to_source = tri.length(tri.edge(tri.prev(h))),
             to_target = tri.length(tri.edge(tri.next(h)));
    return (l * l + to_source * to_source - to_target * to_target) / (FT(2) * l * l);
  };
  auto restore_delaunay = [&]() {
    const Clock::time_point t0 = Clock::now();
    result.number_of_flips += tri.make_delaunay();
    // Each round of splits is followed by flips; the time limit is also checked between rounds
    // (the caller's Newton loop then stops with TIME_LIMIT_EXCEEDED). A split at the altitude's
    // foot cures its corner, so a few rounds suffice; more mean splits feeding each other across
    // a constraint in a collapsing metric (thousands of rounds, with lengths shrinking towards
    // 1e-26), which the Newton loop then reports as not converging.
    for(int round = 0; round < 16 && split_angle < pi && result.number_of_splits < max_splits && !time_limit.exceeded(); ++round)
    {
      std::vector<std::pair<int, FT> > todo; // edge, where to split it (fraction from its halfedge's source)
      for(int e = 0; e < tri.number_of_edges(); ++e)
      {
        if(!tri.is_border_edge(e) && !tri.is_unflippable(e))
          continue;
        // Each side of a constraint is treated like a boundary: a triangle whose angle opposite
        // the edge nears pi is about to degenerate, and no flip can help it.
        // The margin catches the edges at which the line search stopped (just below the angle).
        const int h = tri.halfedge(e), t = tri.opposite(h);
        const FT threshold = split_angle * FT(0.999);
        const FT angle_h = tri.corner_angle(tri.face(h), (h % 3 + 2) % 3);
        const FT angle_t = t >= 0 ? tri.corner_angle(tri.face(t), (t % 3 + 2) % 3) : FT(0);
        if(angle_h > threshold || angle_t > threshold)
        {
          // The altitude's foot from the larger corner, kept off the ends (no tiny edges).
          const FT foot = angle_h >= angle_t ? altitude_foot(h) : FT(1) - altitude_foot(t);
          todo.emplace_back(e, (std::min)(FT(49) / FT(50), (std::max)(FT(1) / FT(50), foot)));
        }
      }
      if(todo.empty())
        break;
      const std::size_t splits_before = result.number_of_splits;
      for(const auto& split : todo)
        if(tri.split_edge(split.first, split.second) >= 0)
        {
          ++result.number_of_splits;
          target.push_back(FT(0));
          result.conformal_factors.push_back(FT(0));
        }
      // A split refused by rounding (a sliver too thin to split) would be tried forever.
      if(result.number_of_splits == splits_before)
        break;
      result.number_of_flips += tri.make_delaunay();
    }
    update_angle_sums();
    result.seconds_flips += seconds(t0);
  };

  if(flips)
    restore_delaunay();

  // The gauge vertex's row and column are dropped: H is singular along constants.
  const int gauge = 0;
  auto reduced = [gauge](int v) { return v < gauge ? v : v - 1; };
  Solver solver;
  bool pattern_known = false;
  std::size_t changes_at_analysis = 0;
  int analyzed_size = -1, factorized_size = -1;
  // Conjugate gradients on H x = b preconditioned by the current factorization; false if the
  // relative residual does not reach ~1e-4 sqrt(eps) within a few iterations.
  auto preconditioned_cg = [&solver](const Matrix& A, const Vector& b, Vector& x) {
    using std::sqrt;
    const int max_cg = 8;
    const FT bnorm = b.norm();
    x = solver.solve(b);
    if(solver.info() != Eigen::Success || !(bnorm > FT(0)))
      return false;
    const FT goal = FT(1e-4) * sqrt(std::numeric_limits<FT>::epsilon()) * bnorm;
    Vector r = b - A * x;
    if(r.norm() <= goal)
      return true;
    Vector z = solver.solve(r);
    Vector p = z;
    FT rz = r.dot(z);
    for(int k = 0; k < max_cg; ++k)
    {
      const Vector Ap = A * p;
      const FT pAp = p.dot(Ap);
      if(!(pAp > FT(0)))
        return false;
      const FT alpha = rz / pAp;
      x += alpha * p;
      r -= alpha * Ap;
      if(r.norm() <= goal)
        return true;
      z = solver.solve(r);
      const FT rz_next = r.dot(z);
      p = z + (rz_next / rz) * p;
      rz = rz_next;
    }
    return false;
  };
  std::vector<FT> g, g_trial, d, l;
  std::vector<double> zero, trial_u;
  std::vector<Eigen::Triplet<FT>> triplets;
  FT error;
  {
    const Clock::time_point t0 = Clock::now();
    error = residual(g);
    result.seconds_assembly += seconds(t0);
  }
  // --- path following for the line search -------------------------------------------------------
  // base[e]: length of e at t = 0 of the current Newton step; the length at t is
  // base[e] exp(t (d_i + d_j)). Flipped edges get the base that gives their length at the flip.
  // The path is explored on `work`, a copy of `tri` without correspondence record; the flips of
  // an accepted step are then replayed on `tri` (a failed exploration leaves `tri` untouched).
  Intrinsic_triangulation<FT> work;
  std::vector<std::pair<int, FT>> path_flips; // (edge, t) in the order they were done on `work`
  std::vector<FT> base;
  std::vector<unsigned> version;
  auto length_at = [&](int e, const FT& t) {
    const int h = work.halfedge(e);
    return base[e] * exp(t * (d[work.source(h)] + d[work.target(h)]));
  };
  // Sum of the cotangents opposite e at t; false if a triangle of e is not valid at t.
  auto delaunay_value = [&](int e, const FT& t, FT& value) {
    value = FT(0);
    const int h = work.halfedge(e);
    for(int g_side : {h, work.opposite(h)})
    {
      const int f = work.face(g_side);
      std::array<FT, 3> tan_half;
      if(!rf::half_angle_tangents(std::array<FT, 3>{{length_at(work.edge(f, 1), t), length_at(work.edge(f, 2), t),
                                                    length_at(work.edge(f, 0), t)}}, tan_half))
        return false;
      value += rf::cot_from_half_tangent(tan_half[(g_side % 3 + 2) % 3]);
    }
    return true;
  };
  // Whether the angles opposite a boundary or unflippable edge e stay at most `block_angle` at t
  // (and its triangles are valid): no flip can save such a triangle, so the path stops there
  // and the edge is split after the step.
  const FT block_angle = split_angle < pi ? split_angle : FT(999) * pi / FT(1000);
  const FT flip_tolerance = FT(1024) * std::numeric_limits<FT>::epsilon();
  auto constraint_ok = [&](int e, const FT& t) {
    const int h = work.halfedge(e);
    for(int g_side : {h, work.opposite(h)})
    {
      if(g_side < 0)
        continue;
      const int f = work.face(g_side);
      std::array<FT, 3> tan_half;
      if(!rf::half_angle_tangents(std::array<FT, 3>{{length_at(work.edge(f, 1), t), length_at(work.edge(f, 2), t),
                                                    length_at(work.edge(f, 0), t)}}, tan_half))
        return false;
      if(rf::angle_from_half_tangent(tan_half[(g_side % 3 + 2) % 3]) > block_angle)
        return false;
    }
    return true;
  };
  // Moves the metric from t_from towards t_to, flipping every edge when it stops being Delaunay,
  // and stopping early where a triangle at a boundary or unflippable edge would degenerate.
  // Returns the parameter t reached; adds the flips to `count`.
  auto follow_path = [&](const FT& t_from, const FT& t_to, std::size_t& count) -> FT {
    // (tau of the event, last tau known to be safe, edge, version of the edge when scheduled)
    typedef std::tuple<FT, FT, int, unsigned> Event;
    std::priority_queue<Event, std::vector<Event>, std::greater<Event>> events;
    version.assign(work.number_of_edges(), 0u);
    auto time_of = [&](const FT& tau) { return t_from + tau * (t_to - t_from); };
    // Earliest tau in [lo, 1] where the predicate fails, by bisection; none if it holds at 1.
    auto schedule = [&](int e, const FT& lo) {
      const bool constraint = work.is_border_edge(e) || work.is_unflippable(e);
      auto holds = [&](const FT& tau) {
        if(constraint)
          return constraint_ok(e, time_of(tau));
        // The tolerance keeps a just flipped (cocircular) edge from flipping straight back.
        FT value;
        return delaunay_value(e, time_of(tau), value) && !(value < -flip_tolerance);
      };
      if(holds(FT(1)))
        return;
      if(!holds(lo))
      {
        events.push(Event(lo, lo, e, version[e]));
        return;
      }
      FT a = lo, b(1);
      for(int it = 0; it < 64 && b - a > FT(1e-15); ++it)
      {
        const FT m = (a + b) / FT(2);
        (holds(m) ? a : b) = m;
      }
      // a constraint stops the path where it still holds; a flip happens just past the root
      events.push(Event(constraint ? a : b, a, e, version[e]));
    };
    for(int e = 0; e < work.number_of_edges(); ++e)
      schedule(e, FT(0));
    FT reached_tau(1);
    std::size_t budget = 64 * static_cast<std::size_t>(work.number_of_edges()) + 1000; // guards against cycles
    while(!events.empty() && budget-- > 0)
    {
      const Event ev = events.top();
      events.pop();
      const int e = std::get<2>(ev);
      if(std::get<3>(ev) != version[e])
        continue;
      const FT tau = std::get<0>(ev), t = time_of(tau);
      if(work.is_border_edge(e) || work.is_unflippable(e))
      {
        reached_tau = tau;
        break;
      }
      int h = work.halfedge(e);
      const int quad[5] = {e, work.edge(work.next(h)), work.edge(work.prev(h)), work.edge(work.next(work.opposite(h))),
                           work.edge(work.prev(work.opposite(h)))};
      for(int q : quad)
        work.set_length(q, length_at(q, t));
      if(!work.flip(e))
      {
        // e.g. both sides of e in one face: the path cannot go on past the last safe point
        reached_tau = std::get<1>(ev);
        break;
      }
      ++count;
      path_flips.emplace_back(e, t);
      h = work.halfedge(e);
      base[e] = work.length(e) * exp(-t * (d[work.source(h)] + d[work.target(h)]));
      for(int q : quad)
      {
        ++version[q];
        schedule(q, tau);
      }
    }
    const FT reached = time_of(reached_tau);
    for(int e = 0; e < work.number_of_edges(); ++e)
      work.set_length(e, length_at(e, reached));
    return reached;
  };

  // The best state seen (lowest curvature error) is what a flow that stops above the tolerance
  // returns. Newton steps mostly lower the error, so the state is copied only when a step leaves
  // it for one that is not better; while no copy is held, the current state is the best.
  FT best_error = error;
  FT error_before_step = error;
  bool last_step_was_full = false;
  bool best_saved = false;
  Intrinsic_triangulation<FT> best_tri;
  std::vector<FT> best_factors, best_target;
  std::size_t best_flips = 0, best_splits = 0;
  auto restore_best = [&]() {
    if(!best_saved || !(best_error < error))
      return false;
    tri = std::move(best_tri);
    result.conformal_factors.swap(best_factors);
    target.swap(best_target);
    result.number_of_flips = best_flips;
    result.number_of_splits = best_splits;
    error = best_error;
    result.max_curvature_error = error;
    best_saved = false;
    return true;
  };

  for(;;)
  {
    if(!best_saved || error < best_error)
    {
      best_error = error;
      best_saved = false;
      result.best_iteration = result.iterations;
    }
    result.max_curvature_error = error;
    if(callback)
      callback(result.iterations, static_cast<double>(error));
    if(error < tolerance)
    {
      result.converged = true;
      result.message = "converged";
      break;
    }
    // Newton's error falls quadratically until it meets the rounding of the angle sums; a full
    // step that no longer halves it means that floor is reached (around 1e-10 on a large CAD
    // disc, where dozens more iterations change nothing).
    if(last_step_was_full && error < FT(100) * tolerance && !(error < FT(0.5) * error_before_step))
    {
      restore_best();
      result.converged = true;
      result.at_rounding_floor = true;
      std::ostringstream message;
      message << "converged to the rounding floor: the curvature error " << static_cast<double>(error)
              << " is within 100 times the tolerance and a full Newton step no longer lowers it";
      result.message = message.str();
      break;
    }
    if(result.iterations >= max_iterations)
    {
      result.message = "maximum number of iterations reached";
      break;
    }
    if(time_limit.exceeded())
    {
      restore_best();
      time_limit.check("after " + std::to_string(result.iterations) + " Newton iterations (curvature error "
                       + std::to_string(static_cast<double>(error)) + ")");
    }
    ++result.iterations;
    const int nv = tri.number_of_vertices();
    error_before_step = error;

    // Hessian (cotangent matrix), assembled per face so that repeated vertices are handled.
    Clock::time_point t0 = Clock::now();
    triplets.clear();
    triplets.reserve(12 * static_cast<std::size_t>(tri.number_of_faces()));
    for(int f = 0; f < tri.number_of_faces(); ++f)
    {
      std::array<FT, 3> t;
      rf::half_angle_tangents(std::array<FT, 3>{{tri.length(tri.edge(f, 1)), tri.length(tri.edge(f, 2)),
                                                 tri.length(tri.edge(f, 0))}}, t);
      for(int c = 0; c < 3; ++c)
      {
        // side c joins corners c and c+1; it is opposite corner c+2
        const int a = tri.vertex(f, c), b = tri.vertex(f, (c + 1) % 3);
        if(a == b)
          continue;
        const FT w = rf::cot_from_half_tangent(t[(c + 2) % 3]);
        if(a != gauge) triplets.emplace_back(reduced(a), reduced(a), w);
        if(b != gauge) triplets.emplace_back(reduced(b), reduced(b), w);
        if(a != gauge && b != gauge)
        {
          triplets.emplace_back(reduced(a), reduced(b), -w);
          triplets.emplace_back(reduced(b), reduced(a), -w);
        }
      }
    }
    Matrix H(nv - 1, nv - 1);
    H.setFromTriplets(triplets.begin(), triplets.end());
    Vector rhs(nv - 1);
    for(int v = 0; v < nv; ++v)
      if(v != gauge)
        rhs[reduced(v)] = -g[v];
    result.seconds_assembly += seconds(t0);

    // The factorization of an earlier Hessian of the same size is first tried as a
    // preconditioner of conjugate gradients: near convergence the Hessian changes little and a
    // few triangular solves replace a factorization (the dominant cost on large meshes).
    Vector x;
    bool solved = false;
    if(factorized_size == nv)
    {
      t0 = Clock::now();
      solved = preconditioned_cg(H, rhs, x);
      result.seconds_solve += seconds(t0);
    }
    if(!solved)
    {
      t0 = Clock::now();
      if(!pattern_known || changes_at_analysis != tri.number_of_connectivity_changes() || analyzed_size != nv)
      {
        solver.analyzePattern(H);
        pattern_known = true;
        changes_at_analysis = tri.number_of_connectivity_changes();
        analyzed_size = nv;
      }
      solver.factorize(H);
      ++result.number_of_factorizations;
      result.seconds_factorization += seconds(t0);
      if(solver.info() != Eigen::Success)
        throw Error(Error_code::LINEAR_SOLVER_FAILED, "discrete_ricci_flow: the factorization of the Hessian failed.");
      factorized_size = nv;
      t0 = Clock::now();
      x = solver.solve(rhs);
      result.seconds_solve += seconds(t0);
      if(solver.info() != Eigen::Success)
        throw Error(Error_code::LINEAR_SOLVER_FAILED, "discrete_ricci_flow: the solve with the Hessian failed.");
    }
    d.assign(nv, FT(0));
    for(int v = 0; v < nv; ++v)
      if(v != gauge)
        d[v] = x[reduced(v)];

    // Line search along u(t) = u + t d. By default on the fixed triangulation (flips after the
    // step). With exact_conformal_path, the metric at t is the discrete conformal metric of
    // Gu-Luo-Sun-Wu: the triangulation follows the path and an edge is flipped at the moment it
    // stops being Delaunay, when its quadrilateral is cyclic and the Euclidean flip coincides
    // with the Ptolemy flip. That result does not depend on the path taken, and each flip still
    // keeps the metric (so the correspondence stays a composition of exact planar identities).
    t0 = Clock::now();
    const std::vector<FT> l0 = tri.edge_lengths();
    zero.assign(nv, 0.);
    trial_u.resize(nv);
    const double e0 = rf::ricci_energy(tri, l0, target_angle_sum, zero);
    double slope = 0; // directional derivative of the energy: g . d < 0
    FT gnorm2(0);
    for(int v = 0; v < nv; ++v)
    {
      slope += static_cast<double>(g[v] * d[v]);
      gnorm2 += g[v] * g[v];
    }
    l.resize(l0.size());
    FT step(1), t_now(0), previous(-1), accepted_step(0);
    bool accepted = false, on_path = flips && exact_path;
    std::size_t explored_flips = 0;
    if(on_path)
    {
      work = tri.without_history();
      base = l0;
      path_flips.clear();
    }
    for(int trial = 0; trial < 60 && !accepted; ++trial, step /= FT(2))
    {
      if(on_path)
      {
        // A stop short of the step (a constraint about to degenerate, an impossible flip)
        // makes that the trial.
        t_now = follow_path(t_now, step, explored_flips);
        step = t_now;
        if(!(step > FT(0)) || step == previous || !work.is_valid())
        {
          // Blocked or stuck: for this iteration, step on the fixed triangulation and flip
          // afterwards instead (paper Alg. 4; the metric then depends on the step taken).
          on_path = false;
          step = FT(2);
          continue;
        }
        previous = step;
      }
      else
      {
        for(int e = 0; e < tri.number_of_edges(); ++e)
        {
          const int h = tri.halfedge(e);
          l[e] = l0[e] * exp(step * (d[tri.source(h)] + d[tri.target(h)]));
        }
        tri.set_edge_lengths(l);
      }
      const Intrinsic_triangulation<FT>& current = on_path ? work : tri;
      if(!current.is_valid())
        continue;
      for(int v = 0; v < nv; ++v)
        trial_u[v] = static_cast<double>(step * d[v]);
      const double e1 = rf::ricci_energy(current, current.edge_lengths(), target_angle_sum, trial_u);
      const bool armijo = e1 <= e0 + 1e-4 * static_cast<double>(step) * slope;
      const FT trial_error = residual_on(current, g_trial);
      FT trial_norm2(0);
      for(int v = 0; v < nv; ++v)
        trial_norm2 += g_trial[v] * g_trial[v];
      // Near convergence e1 - e0 is below the rounding of the energy; the residual decides.
      const bool rounding = std::abs(slope) < 1e-12 * (1. + std::abs(e0));
      if(armijo || (rounding && trial_norm2 < gnorm2))
      {
        if(!best_saved && !(trial_error < best_error))
        {
          // Leaving the best state for one that is not better: keep it to come back to.
          best_tri = tri;
          if(!on_path)
            best_tri.set_edge_lengths(l0);
          best_factors = result.conformal_factors;
          best_target = target;
          best_flips = result.number_of_flips;
          best_splits = result.number_of_splits;
          best_saved = true;
        }
        accepted = true;
        accepted_step = step;
        g.swap(g_trial);
        error = trial_error;
        for(int v = 0; v < nv; ++v)
          result.conformal_factors[v] += step * d[v];
      }
    }
    if(accepted && on_path)
    {
      // Replay the explored flips on `tri` (same lengths at the same moments: same results),
      // recording them for the correspondence.
      std::vector<FT>& replay_base = l;
      replay_base = l0;
      auto replay_length = [&](int e, const FT& t) {
        const int h = tri.halfedge(e);
        return replay_base[e] * exp(t * (d[tri.source(h)] + d[tri.target(h)]));
      };
      for(const std::pair<int, FT>& pf : path_flips)
      {
        const int e = pf.first, h = tri.halfedge(e);
        const int quad[5] = {e, tri.edge(tri.next(h)), tri.edge(tri.prev(h)), tri.edge(tri.next(tri.opposite(h))),
                             tri.edge(tri.prev(tri.opposite(h)))};
        for(int q : quad)
          tri.set_length(q, replay_length(q, pf.second));
        if(!tri.flip(e))
        {
          continue;
        }
        ++result.number_of_flips;
        const int g_new = tri.halfedge(e);
        replay_base[e] = tri.length(e) * exp(-pf.second * (d[tri.source(g_new)] + d[tri.target(g_new)]));
      }
      for(int e = 0; e < tri.number_of_edges(); ++e)
        tri.set_length(e, replay_length(e, accepted_step));
    }
    if(!accepted)
      tri.set_edge_lengths(l0);
    result.seconds_line_search += seconds(t0);
    if(!accepted)
    {
      result.message = "line search failed: no step along the Newton direction keeps the triangles valid and decreases the energy";
      break;
    }
    last_step_was_full = accepted_step == FT(1);
    if(flips)
    {
      const std::size_t before = tri.number_of_vertices();
      restore_delaunay();
      if(static_cast<std::size_t>(tri.number_of_vertices()) != before)
      {
        // New vertices: the residual changes (Euclidean flips alone keep it).
        const Clock::time_point t1 = Clock::now();
        error = residual(g);
        result.seconds_assembly += seconds(t1);
        last_step_was_full = false;
      }
    }
  }
  if(result.converged)
    result.status = Error_code::SUCCESS;
  else if(restore_best())
    result.message += "; the state of iteration " + std::to_string(result.best_iteration)
                      + ", with the lowest curvature error, is returned";
  result.seconds_total = seconds(start);
  return result;
}

} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_DISCRETE_RICCI_FLOW_H
