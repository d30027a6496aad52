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
#include <CGAL/Conformal_remeshing/internal/ricci_flow/conformal_path.h>
#include <CGAL/Conformal_remeshing/internal/ricci_flow/lobachevsky.h>
#include <CGAL/Conformal_remeshing/internal/ricci_flow/triangle_geometry.h>
#include <CGAL/Conformal_remeshing/internal/time_limit.h>

#include <CGAL/Named_function_parameters.h>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <boost/math/constants/constants.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
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

// The Ricci energy of the fixed triangulation `tri` (convex in the conformal factors; its
// gradient is K - K̄, its Hessian the cotangent matrix). Up to a constant:
//   E = sum_faces sum_corners [ (theta - pi/2) log l_opposite + Lob(theta) ] + sum_v Theta_v u_v
// with Theta_v the target angle sum. It is evaluated in double: it only decides whether a step
// is accepted, and near convergence the gradient test takes over.
//
// The sum over the faces at the lengths of `tri`, and from the same half-angle tangents the
// angle sum at every vertex (in FT): a line search's trial needs both, and the tangents, their
// arctangents and the checks of the triangle inequality are the larger part of either.
// Returns false if a face violates the triangle inequality. With FT other than double the
// energy's terms are those of the lengths rounded to double, and the energy is infinite if
// those violate it.
template <typename FT>
bool face_energy_and_angle_sums(const Intrinsic_triangulation<FT>& tri, double& face_energy,
                                std::vector<FT>& angle_sums)
{
  const double half_pi = 1.5707963267948966;
  face_energy = 0;
  angle_sums.assign(tri.number_of_vertices(), FT(0));
  std::array<FT, 3> opposite, t;
  std::array<double, 3> len, t_double;
  bool energy_defined = true;
  for(int f = 0; f < tri.number_of_faces(); ++f)
  {
    const std::array<FT, 3> sides = tri.face_lengths(f); // side c joins corners c and c + 1
    for(int c = 0; c < 3; ++c)
      opposite[c] = sides[(c + 1) % 3];
    if(!half_angle_tangents(opposite, t))
      return false;
    if constexpr(std::is_same<FT, double>::value)
    {
      len = opposite;
      t_double = t;
    }
    else
    {
      for(int c = 0; c < 3; ++c)
        len[c] = static_cast<double>(opposite[c]);
      if(!half_angle_tangents(len, t_double))
        energy_defined = false;
    }
    for(int c = 0; c < 3; ++c)
    {
      const FT theta = angle_from_half_tangent(t[c]);
      angle_sums[tri.vertex(f, c)] += theta;
      double theta_double;
      if constexpr(std::is_same<FT, double>::value)
        theta_double = theta;
      else
        theta_double = 2. * std::atan(t_double[c]);
      if(energy_defined)
        face_energy += (theta_double - half_pi) * std::log(len[c]) + lobachevsky(theta_double);
    }
  }
  if(!energy_defined)
    face_energy = std::numeric_limits<double>::infinity();
  return true;
}

// The Ricci energy from the sum over the faces and the conformal factors `u` of the vertices.
inline double ricci_energy(double face_energy, const std::vector<double>& target_angle_sum, const std::vector<double>& u)
{
  double e = face_energy;
  for(std::size_t v = 0; v < u.size(); ++v)
    e += target_angle_sum[v] * u[v];
  return e;
}

// The Ricci energy of `tri` at its lengths; infinite if a face violates the triangle inequality.
template <typename FT>
double ricci_energy(const Intrinsic_triangulation<FT>& tri, const std::vector<double>& target_angle_sum,
                    const std::vector<double>& u)
{
  double face_energy;
  std::vector<FT> angle_sums;
  if(!face_energy_and_angle_sums(tri, face_energy, angle_sums))
    return std::numeric_limits<double>::infinity();
  return ricci_energy(face_energy, target_angle_sum, u);
}

// The named parameters of `discrete_ricci_flow()` (see there), read once with their defaults;
// the time limit counts from their reading.
template <typename FT>
struct Flow_parameters
{
  template <typename NamedParameters>
  explicit Flow_parameters(const NamedParameters& np)
    : max_iterations(CGAL::parameters::choose_parameter(
          CGAL::parameters::get_parameter(np, CGAL::internal_np::number_of_iterations), 50)),
      tolerance(CGAL::parameters::choose_parameter(
          CGAL::parameters::get_parameter(np, internal_np::curvature_tolerance), FT(1e-10))),
      flips(CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np::use_edge_flips), true)),
      exact_path(CGAL::parameters::choose_parameter(
          CGAL::parameters::get_parameter(np, internal_np::exact_conformal_path), false)),
      split_angle(CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np::edge_split_angle),
                                                     FT(9) * boost::math::constants::pi<FT>() / FT(10))),
      callback(CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::callback),
                                                  std::function<void(int, double)>())),
      time_limit(Time_limit::from(np, "discrete_ricci_flow"))
  {}

  int max_iterations;
  FT tolerance;
  bool flips;      // flips and splits keep the triangulation Delaunay
  bool exact_path; // path-following line search
  FT split_angle;
  std::function<void(int, double)> callback;
  Time_limit time_limit;
};

// Checks what `discrete_ricci_flow()` is given, before anything is changed: the number of
// targets, their sum (Gauss-Bonnet) and the input metric.
template <typename FT>
void check_flow_input(const Intrinsic_triangulation<FT>& tri, const std::vector<FT>& target_curvature)
{
  using std::abs;
  const FT pi = boost::math::constants::pi<FT>();
  if(static_cast<int>(target_curvature.size()) != tri.number_of_vertices())
    throw Error(Error_code::INVALID_INPUT, "discrete_ricci_flow: expected " + std::to_string(tri.number_of_vertices()) +
                                               " target curvatures, got " + std::to_string(target_curvature.size()) + ".");
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
  if(!tri.is_valid())
    throw Error(Error_code::DEGENERATE_METRIC, "discrete_ricci_flow: the input metric violates the triangle inequality.");
}

// One run of `discrete_ricci_flow()` on `tri`: the state of the Newton iterations, with one
// member function per step. `start()` makes the input Delaunay and computes its curvature error,
// `iterate()` runs the Newton iterations until one of the stop conditions, and `finish()`
// returns the result. `Solver` is the Eigen sparse solver of the Newton systems.
template <typename FT, typename Solver>
class Flow_run
{
  typedef Eigen::SparseMatrix<FT> Matrix;
  typedef Eigen::Matrix<FT, Eigen::Dynamic, 1> Vector;
  typedef std::chrono::steady_clock Clock;

public:
  Flow_run(Intrinsic_triangulation<FT>& tri, const std::vector<FT>& target_curvature,
           const Flow_parameters<FT>& parameters)
    : tri_(tri), parameters_(parameters), pi_(boost::math::constants::pi<FT>()), target_(result_.target_curvatures),
      max_splits_(4 * static_cast<std::size_t>(tri.number_of_vertices()) + 1000), path_(parameters.split_angle, pi_)
  {
    result_.target_curvatures = target_curvature;
    result_.conformal_factors.assign(tri_.number_of_vertices(), FT(0));
    update_angle_sums();
  }

  Flow_run(const Flow_run&) = delete;
  Flow_run& operator=(const Flow_run&) = delete;

  // The input made Delaunay (when flips are on) and its curvature error: the state before the
  // first iteration, which is the best one so far.
  void start()
  {
    if(parameters_.flips)
      restore_delaunay();
    const Clock::time_point t0 = Clock::now();
    error_ = residual(g_);
    result_.seconds_assembly += seconds_since(t0);
    best_error_ = error_;
    error_before_step_ = error_;
  }

  // The Newton iterations: a direction, a line search along it and the Delaunay property
  // restored, until the flow converges or stops (see `stops()`).
  void iterate()
  {
    for(;;)
    {
      note_best_state();
      result_.max_curvature_error = error_;
      if(parameters_.callback)
        parameters_.callback(result_.iterations, static_cast<double>(error_));
      if(stops())
        break;
      ++result_.iterations;
      const int nv = tri_.number_of_vertices();
      error_before_step_ = error_;
      newton_direction(nv);
      FT accepted_step(0);
      if(!line_search(nv, accepted_step))
      {
        result_.message = "line search failed: no step along the Newton direction keeps the triangles valid and decreases the energy";
        break;
      }
      last_step_was_full_ = accepted_step == FT(1);
      if(parameters_.flips)
        restore_delaunay_after_step();
    }
  }

  // The report: a flow that did not converge returns the best state it reached. `start` is the
  // time of the call.
  Ricci_flow_result<FT> finish(Clock::time_point start)
  {
    if(result_.converged)
      result_.status = Error_code::SUCCESS;
    else if(restore_best())
      result_.message += "; the state of iteration " + std::to_string(result_.best_iteration)
                         + ", with the lowest curvature error, is returned";
    result_.seconds_total = seconds_since(start);
    return std::move(result_);
  }

private:
  static double seconds_since(Clock::time_point a) { return std::chrono::duration<double>(Clock::now() - a).count(); }

  // --- curvatures -------------------------------------------------------------------------------

  // The target angle sum per vertex, in double for the energy: pi at the boundary, 2 pi inside,
  // minus the target curvature.
  void update_angle_sums()
  {
    target_angle_sum_.resize(target_.size());
    for(std::size_t v = 0; v < target_.size(); ++v)
      target_angle_sum_[v] = static_cast<double>((tri_.is_border_vertex(int(v)) ? pi_ : FT(2) * pi_) - target_[v]);
  }

  // g = K - K̄ of the triangulation T from its angle sums; returns max |g|
  FT residual_on(const Intrinsic_triangulation<FT>& T, const std::vector<FT>& angle_sums, std::vector<FT>& g) const
  {
    using std::abs;
    g.resize(angle_sums.size());
    FT m(0);
    for(std::size_t v = 0; v < angle_sums.size(); ++v)
    {
      const FT curvature = (T.is_border_vertex(int(v)) ? pi_ : FT(2) * pi_) - angle_sums[v];
      g[v] = curvature - target_[v];
      if(abs(g[v]) > m)
        m = abs(g[v]);
    }
    return m;
  }

  FT residual(std::vector<FT>& g) const { return residual_on(tri_, tri_.angle_sums(), g); }

  // --- Delaunay restoration: flips and edge splits ------------------------------------------------

  // Flip to Delaunay; split boundary / unflippable edges whose opposite angles are too large.
  void restore_delaunay()
  {
    const Clock::time_point t0 = Clock::now();
    result_.number_of_flips += tri_.make_delaunay();
    // Each round of splits is followed by flips; the time limit is also checked between rounds
    // (the caller's Newton loop then stops with TIME_LIMIT_EXCEEDED). A split at the altitude's
    // foot cures its corner, so a few rounds suffice; more mean splits feeding each other across
    // a constraint in a collapsing metric (thousands of rounds, with lengths shrinking towards
    // 1e-26), which the Newton loop then reports as not converging.
    const FT& split_angle = parameters_.split_angle;
    const Time_limit& time_limit = parameters_.time_limit;
    for(int round = 0; round < 16 && split_angle < pi_ && result_.number_of_splits < max_splits_ && !time_limit.exceeded(); ++round)
    {
      const std::vector<std::pair<int, FT> > todo = edges_to_split();
      if(todo.empty())
        break;
      const std::size_t splits_before = result_.number_of_splits;
      for(const auto& split : todo)
        if(tri_.split_edge(split.first, split.second) >= 0)
        {
          ++result_.number_of_splits;
          target_.push_back(FT(0));
          result_.conformal_factors.push_back(FT(0));
        }
      // A split refused by rounding (a sliver too thin to split) would be tried forever.
      if(result_.number_of_splits == splits_before)
        break;
      result_.number_of_flips += tri_.make_delaunay();
    }
    update_angle_sums();
    result_.seconds_flips += seconds_since(t0);
  }

  // The boundary and unflippable edges to split: each edge, with where to split it (fraction
  // from its halfedge's source).
  std::vector<std::pair<int, FT> > edges_to_split() const
  {
    std::vector<std::pair<int, FT> > todo;
    for(int e = 0; e < tri_.number_of_edges(); ++e)
    {
      if(!tri_.is_border_edge(e) && !tri_.is_unflippable(e))
        continue;
      // Each side of a constraint is treated like a boundary: a triangle whose angle opposite
      // the edge nears pi is about to degenerate, and no flip can help it.
      // The margin catches the edges at which the line search stopped (just below the angle).
      const int h = tri_.halfedge(e), t = tri_.opposite(h);
      const FT threshold = parameters_.split_angle * FT(0.999);
      const FT angle_h = tri_.corner_angle(tri_.face(h), (h % 3 + 2) % 3);
      const FT angle_t = t >= 0 ? tri_.corner_angle(tri_.face(t), (t % 3 + 2) % 3) : FT(0);
      if(angle_h > threshold || angle_t > threshold)
      {
        // The altitude's foot from the larger corner, kept off the ends (no tiny edges).
        const FT foot = angle_h >= angle_t ? altitude_foot(h) : FT(1) - altitude_foot(t);
        todo.emplace_back(e, (std::min)(FT(49) / FT(50), (std::max)(FT(1) / FT(50), foot)));
      }
    }
    return todo;
  }

  // Where the altitude from the corner opposite halfedge `h` meets it, as a fraction from its source.
  FT altitude_foot(int h) const
  {
    const FT l = tri_.length(tri_.edge(h)), to_source = tri_.length(tri_.edge(tri_.prev(h))),
             to_target = tri_.length(tri_.edge(tri_.next(h)));
    return (l * l + to_source * to_source - to_target * to_target) / (FT(2) * l * l);
  }

  // After an accepted step: the Delaunay property restored, and the residual computed again if
  // splits added vertices.
  void restore_delaunay_after_step()
  {
    const std::size_t before = tri_.number_of_vertices(), flips_before = result_.number_of_flips;
    restore_delaunay();
    if(result_.number_of_flips != flips_before || static_cast<std::size_t>(tri_.number_of_vertices()) != before)
      face_energy_known_ = false;
    if(static_cast<std::size_t>(tri_.number_of_vertices()) != before)
    {
      // New vertices: the residual changes (Euclidean flips alone keep it).
      const Clock::time_point t1 = Clock::now();
      error_ = residual(g_);
      result_.seconds_assembly += seconds_since(t1);
      last_step_was_full_ = false;
    }
  }

  // --- stop checks and the best state -------------------------------------------------------------

  // Before each iteration: the current state is the best one when no copy of a better one is
  // held, or when it is better than that copy (which is then dropped).
  void note_best_state()
  {
    if(!best_saved_ || error_ < best_error_)
    {
      best_error_ = error_;
      best_saved_ = false;
      result_.best_iteration = result_.iterations;
    }
  }

  // Whether the flow stops before the next iteration (`result_.message` says why): converged, at
  // the rounding floor or out of iterations. When the time limit has passed, the best state is
  // restored and TIME_LIMIT_EXCEEDED thrown.
  bool stops()
  {
    if(error_ < parameters_.tolerance)
    {
      result_.converged = true;
      result_.message = "converged";
      return true;
    }
    // Newton's error falls quadratically until it meets the rounding of the angle sums; a full
    // step that no longer halves it means that floor is reached (around 1e-10 on a large CAD
    // disc, where dozens more iterations change nothing).
    if(last_step_was_full_ && error_ < FT(100) * parameters_.tolerance && !(error_ < FT(0.5) * error_before_step_))
    {
      restore_best();
      result_.converged = true;
      result_.at_rounding_floor = true;
      std::ostringstream message;
      message << "converged to the rounding floor: the curvature error " << static_cast<double>(error_)
              << " is within 100 times the tolerance and a full Newton step no longer lowers it";
      result_.message = message.str();
      return true;
    }
    if(result_.iterations >= parameters_.max_iterations)
    {
      result_.message = "maximum number of iterations reached";
      return true;
    }
    if(parameters_.time_limit.exceeded())
    {
      restore_best();
      parameters_.time_limit.check("after " + std::to_string(result_.iterations) + " Newton iterations (curvature error "
                                   + std::to_string(static_cast<double>(error_)) + ")");
    }
    return false;
  }

  // Back to the saved best state, if one is held and better than the current state.
  bool restore_best()
  {
    if(!best_saved_ || !(best_error_ < error_))
      return false;
    tri_ = std::move(best_tri_);
    result_.conformal_factors.swap(best_factors_);
    target_.swap(best_target_);
    result_.number_of_flips = best_flips_;
    result_.number_of_splits = best_splits_;
    error_ = best_error_;
    result_.max_curvature_error = error_;
    best_saved_ = false;
    return true;
  }

  // --- the Newton step ----------------------------------------------------------------------------

  // The gauge vertex's row and column are dropped: H is singular along constants.
  static constexpr int gauge = 0;
  static int reduced(int v) { return v < gauge ? v : v - 1; }

  // The Newton direction d_ of the current state (`nv` vertices): H d = K̄ - K, with the conformal
  // factor of the gauge vertex fixed.
  void newton_direction(int nv)
  {
    const Clock::time_point t0 = Clock::now();
    Matrix H(nv - 1, nv - 1);
    {
      const std::vector<Eigen::Triplet<FT> > triplets = hessian_triplets(nv);
      H.setFromTriplets(triplets.begin(), triplets.end());
    } // the triplets are freed before the factorization
    Vector rhs(nv - 1);
    for(int v = 0; v < nv; ++v)
      if(v != gauge)
        rhs[reduced(v)] = -g_[v];
    result_.seconds_assembly += seconds_since(t0);

    const Vector x = solve(H, rhs, nv);
    d_.assign(nv, FT(0));
    for(int v = 0; v < nv; ++v)
      if(v != gauge)
        d_[v] = x[reduced(v)];
  }

  // The Hessian (cotangent matrix) as triplets, assembled per face so that repeated vertices are
  // handled. Eigen's setFromTriplets() sums the triplets of one entry in their order; the
  // diagonal is summed here in that same order and given as one triplet per vertex, which halves
  // the triplets (the largest transient of a flow on a large patch) and leaves the matrix as it
  // would be with one triplet per corner and side.
  std::vector<Eigen::Triplet<FT> > hessian_triplets(int nv) const
  {
    std::vector<FT> diagonal(nv, FT(0));
    std::vector<char> has_diagonal(nv, 0);
    const auto add_to_diagonal = [&](int v, const FT& w) {
      if(v == gauge)
        return;
      diagonal[v] = has_diagonal[v] ? diagonal[v] + w : w;
      has_diagonal[v] = 1;
    };
    std::vector<Eigen::Triplet<FT> > triplets;
    triplets.reserve(6 * static_cast<std::size_t>(tri_.number_of_faces()) + static_cast<std::size_t>(nv));
    for(int f = 0; f < tri_.number_of_faces(); ++f)
    {
      std::array<FT, 3> t;
      half_angle_tangents(std::array<FT, 3>{{tri_.length(tri_.edge(f, 1)), tri_.length(tri_.edge(f, 2)),
                                             tri_.length(tri_.edge(f, 0))}}, t);
      for(int c = 0; c < 3; ++c)
      {
        // side c joins corners c and c+1; it is opposite corner c+2
        const int a = tri_.vertex(f, c), b = tri_.vertex(f, (c + 1) % 3);
        if(a == b)
          continue;
        const FT w = cot_from_half_tangent(t[(c + 2) % 3]);
        add_to_diagonal(a, w);
        add_to_diagonal(b, w);
        if(a != gauge && b != gauge)
        {
          triplets.emplace_back(reduced(a), reduced(b), -w);
          triplets.emplace_back(reduced(b), reduced(a), -w);
        }
      }
    }
    for(int v = 0; v < nv; ++v)
      if(has_diagonal[v])
        triplets.emplace_back(reduced(v), reduced(v), diagonal[v]);
    return triplets;
  }

  // The solution of H x = rhs (H of size nv - 1). The factorization of an earlier Hessian of the
  // same size is first tried as a preconditioner of conjugate gradients: near convergence the
  // Hessian changes little and a few triangular solves replace a factorization (the dominant
  // cost on large meshes).
  Vector solve(const Matrix& H, const Vector& rhs, int nv)
  {
    Vector x;
    bool solved = false;
    Clock::time_point t0;
    if(factorized_size_ == nv)
    {
      t0 = Clock::now();
      solved = preconditioned_cg(H, rhs, x);
      result_.seconds_solve += seconds_since(t0);
    }
    if(!solved)
    {
      t0 = Clock::now();
      if(!pattern_known_ || changes_at_analysis_ != tri_.number_of_connectivity_changes() || analyzed_size_ != nv)
      {
        solver_.analyzePattern(H);
        pattern_known_ = true;
        changes_at_analysis_ = tri_.number_of_connectivity_changes();
        analyzed_size_ = nv;
      }
      solver_.factorize(H);
      ++result_.number_of_factorizations;
      result_.seconds_factorization += seconds_since(t0);
      if(solver_.info() != Eigen::Success)
        throw Error(Error_code::LINEAR_SOLVER_FAILED, "discrete_ricci_flow: the factorization of the Hessian failed.");
      factorized_size_ = nv;
      t0 = Clock::now();
      x = solver_.solve(rhs);
      result_.seconds_solve += seconds_since(t0);
      if(solver_.info() != Eigen::Success)
        throw Error(Error_code::LINEAR_SOLVER_FAILED, "discrete_ricci_flow: the solve with the Hessian failed.");
    }
    return x;
  }

  // Conjugate gradients on H x = b preconditioned by the current factorization; false if the
  // relative residual does not reach ~1e-4 sqrt(eps) within a few iterations.
  bool preconditioned_cg(const Matrix& A, const Vector& b, Vector& x) const
  {
    using std::sqrt;
    const int max_cg = 8;
    const FT bnorm = b.norm();
    x = solver_.solve(b);
    if(solver_.info() != Eigen::Success || !(bnorm > FT(0)))
      return false;
    const FT goal = FT(1e-4) * sqrt(std::numeric_limits<FT>::epsilon()) * bnorm;
    Vector r = b - A * x;
    if(r.norm() <= goal)
      return true;
    Vector z = solver_.solve(r);
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
      z = solver_.solve(r);
      const FT rz_next = r.dot(z);
      p = z + (rz_next / rz) * p;
      rz = rz_next;
    }
    return false;
  }

  // --- the line search ----------------------------------------------------------------------------

  // Line search along u(t) = u + t d. By default on the fixed triangulation (flips after the
  // step). With exact_conformal_path, the metric at t is the discrete conformal metric of
  // Gu-Luo-Sun-Wu: the triangulation follows the path and an edge is flipped at the moment it
  // stops being Delaunay, when its quadrilateral is cyclic and the Euclidean flip coincides
  // with the Ptolemy flip. That result does not depend on the path taken, and each flip still
  // keeps the metric (so the correspondence stays a composition of exact planar identities).
  // Returns whether a step was accepted (its length in `accepted_step`); if none was, `tri_` is
  // left in the metric it had.
  bool line_search(int nv, FT& accepted_step)
  {
    const Clock::time_point t0 = Clock::now();
    const std::vector<FT> l0 = tri_.edge_lengths();
    zero_.assign(nv, 0.);
    trial_u_.resize(nv);
    // The energy at the start is that of the last accepted trial when no flip or split has
    // changed the triangulation since.
    const double e0 = face_energy_known_ ? ricci_energy(face_energy_, target_angle_sum_, zero_)
                                         : ricci_energy(tri_, target_angle_sum_, zero_);
    face_energy_known_ = false;
    double slope = 0; // directional derivative of the energy: g . d < 0
    FT gnorm2(0);
    for(int v = 0; v < nv; ++v)
    {
      slope += static_cast<double>(g_[v] * d_[v]);
      gnorm2 += g_[v] * g_[v];
    }
    l_.resize(l0.size());
    FT step(1), t_now(0), previous(-1);
    bool accepted = false, on_path = parameters_.flips && parameters_.exact_path;
    std::size_t explored_flips = 0;
    if(on_path)
      path_.start(tri_, l0, d_);
    for(int trial = 0; trial < 60 && !accepted; ++trial, step /= FT(2))
    {
      if(on_path)
      {
        // A stop short of the step (a constraint about to degenerate, an impossible flip)
        // makes that the trial.
        t_now = path_.follow(t_now, step, explored_flips);
        step = t_now;
        if(!(step > FT(0)) || step == previous || !path_.triangulation().is_valid())
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
        set_trial_lengths(l0, step);
      const Intrinsic_triangulation<FT>& current = on_path ? path_.triangulation() : tri_;
      double face_energy;
      if(!face_energy_and_angle_sums(current, face_energy, trial_angle_sums_))
        continue; // a face violates the triangle inequality
      FT trial_error;
      if(is_acceptable(current, nv, step, face_energy, e0, slope, gnorm2, trial_error))
      {
        accept_step(nv, step, trial_error, l0, on_path);
        accepted = true;
        accepted_step = step;
        // On the path, `tri_` gets the step by a replay of the flips, not these very lengths.
        face_energy_known_ = !on_path;
        face_energy_ = face_energy;
      }
    }
    // Replay the explored flips on `tri_`; `l_` is free again and holds the replay's bases.
    if(accepted && on_path)
      path_.replay(tri_, l0, accepted_step, l_, result_.number_of_flips);
    if(!accepted)
      tri_.set_edge_lengths(l0);
    result_.seconds_line_search += seconds_since(t0);
    return accepted;
  }

  // The metric of the fixed triangulation at `step` along d from the lengths `l0`.
  void set_trial_lengths(const std::vector<FT>& l0, const FT& step)
  {
    using std::exp;
    for(int e = 0; e < tri_.number_of_edges(); ++e)
    {
      const int h = tri_.halfedge(e);
      l_[e] = l0[e] * exp(step * (d_[tri_.source(h)] + d_[tri_.target(h)]));
    }
    tri_.set_edge_lengths(l_);
  }

  // Whether the trial metric `current`, at `step` along d, is accepted: the Armijo test on the
  // energy (`e0` at the start, `slope` its directional derivative; `face_energy` and
  // `trial_angle_sums_` are those of the trial), or near convergence a lower residual norm than
  // `gnorm2`. The trial's residual goes to `g_trial_`, its max to `trial_error`.
  bool is_acceptable(const Intrinsic_triangulation<FT>& current, int nv, const FT& step, double face_energy,
                     double e0, double slope, const FT& gnorm2, FT& trial_error)
  {
    for(int v = 0; v < nv; ++v)
      trial_u_[v] = static_cast<double>(step * d_[v]);
    const double e1 = ricci_energy(face_energy, target_angle_sum_, trial_u_);
    const bool armijo = e1 <= e0 + 1e-4 * static_cast<double>(step) * slope;
    trial_error = residual_on(current, trial_angle_sums_, g_trial_);
    FT trial_norm2(0);
    for(int v = 0; v < nv; ++v)
      trial_norm2 += g_trial_[v] * g_trial_[v];
    // Near convergence e1 - e0 is below the rounding of the energy; the residual decides.
    const bool rounding = std::abs(slope) < 1e-12 * (1. + std::abs(e0));
    return armijo || (rounding && trial_norm2 < gnorm2);
  }

  // The accepted trial becomes the current state: its residual and error, the conformal factors
  // moved by `step` along d. `l0` is the metric before the step, `on_path` whether the trial
  // was on the path (`tri_` then still holds `l0`).
  void accept_step(int nv, const FT& step, const FT& trial_error, const std::vector<FT>& l0, bool on_path)
  {
    if(!best_saved_ && !(trial_error < best_error_))
    {
      // Leaving the best state for one that is not better: keep it to come back to.
      best_tri_ = tri_;
      if(!on_path)
        best_tri_.set_edge_lengths(l0);
      best_factors_ = result_.conformal_factors;
      best_target_ = target_;
      best_flips_ = result_.number_of_flips;
      best_splits_ = result_.number_of_splits;
      best_saved_ = true;
    }
    g_.swap(g_trial_);
    error_ = trial_error;
    for(int v = 0; v < nv; ++v)
      result_.conformal_factors[v] += step * d_[v];
  }

  // --- state --------------------------------------------------------------------------------------

  Intrinsic_triangulation<FT>& tri_;
  const Flow_parameters<FT>& parameters_;
  const FT pi_;
  Ricci_flow_result<FT> result_;
  std::vector<FT>& target_; // result_.target_curvatures: those of all vertices, including the added ones
  std::vector<double> target_angle_sum_;
  const std::size_t max_splits_; // over the whole run

  // the Newton systems
  Solver solver_;
  bool pattern_known_ = false;
  std::size_t changes_at_analysis_ = 0;
  int analyzed_size_ = -1, factorized_size_ = -1;
  std::vector<FT> g_, g_trial_, d_, l_; // residual K - K̄, that of a trial, Newton direction, trial lengths
  std::vector<double> zero_, trial_u_;
  std::vector<FT> trial_angle_sums_;
  double face_energy_ = 0; // the Ricci energy's sum over the faces of `tri_`, when known
  bool face_energy_known_ = false;
  FT error_;
  Conformal_path<FT> path_; // the line search with exact_conformal_path

  // The best state seen (lowest curvature error) is what a flow that stops above the tolerance
  // returns. Newton steps mostly lower the error, so the state is copied only when a step leaves
  // it for one that is not better; while no copy is held, the current state is the best.
  FT best_error_;
  FT error_before_step_;
  bool last_step_was_full_ = false;
  bool best_saved_ = false;
  Intrinsic_triangulation<FT> best_tri_;
  std::vector<FT> best_factors_, best_target_;
  std::size_t best_flips_ = 0, best_splits_ = 0;
};

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
  namespace rf = internal::ricci_flow;
  typedef Eigen::SparseMatrix<FT> Matrix;
  typedef typename CGAL::internal_np::Lookup_named_param_def<CGAL::internal_np::sparse_linear_solver_t, NamedParameters,
                                                             Eigen::SimplicialLDLT<Matrix>>::type Solver_param;
  typedef typename rf::Unwrap<Solver_param>::type Solver;
  const std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();

  const rf::Flow_parameters<FT> parameters(np);
  rf::check_flow_input(tri, target_curvature);

  rf::Flow_run<FT, Solver> run(tri, target_curvature, parameters);
  run.start();
  run.iterate();
  return run.finish(start);
}

} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_DISCRETE_RICCI_FLOW_H
