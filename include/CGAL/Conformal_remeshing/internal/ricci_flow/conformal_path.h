// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The path followed by the line search of `discrete_ricci_flow()` with `exact_conformal_path`:
// along u(t) = u + t d the metric at t is the discrete conformal metric of Gu-Luo-Sun-Wu, so the
// triangulation follows the path and an edge is flipped at the moment it stops being Delaunay.

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_RICCI_FLOW_CONFORMAL_PATH_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_RICCI_FLOW_CONFORMAL_PATH_H

#include <CGAL/Conformal_remeshing/Intrinsic_triangulation.h>
#include <CGAL/Conformal_remeshing/internal/ricci_flow/triangle_geometry.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <queue>
#include <tuple>
#include <utility>
#include <vector>


namespace CGAL {
namespace Conformal_remeshing {
namespace internal {
namespace ricci_flow {

// Path following for the line search of one Newton step along the direction `d`.
// base[e]: length of e at t = 0 of the current Newton step; the length at t is
// base[e] exp(t (d_i + d_j)). Flipped edges get the base that gives their length at the flip.
// The path is explored on `work`, a copy of `tri` without correspondence record; the flips of
// an accepted step are then replayed on `tri` (a failed exploration leaves `tri` untouched).
template <typename FT>
class Conformal_path
{
public:
  // `split_angle` is the flow's edge split angle: the angle opposite a boundary or unflippable
  // edge at which the path stops (a little below pi when splitting is disabled).
  Conformal_path(const FT& split_angle, const FT& pi)
    : block_angle_(split_angle < pi ? split_angle : FT(999) * pi / FT(1000)),
      flip_tolerance_(FT(1024) * std::numeric_limits<FT>::epsilon())
  {}

  // Starts the exploration of a step from the metric `l0` of `tri` along `d` (which must stay
  // alive and unchanged until the step is replayed or abandoned).
  void start(const Intrinsic_triangulation<FT>& tri, const std::vector<FT>& l0, const std::vector<FT>& d)
  {
    work_ = tri.without_history();
    base_ = l0;
    path_flips_.clear();
    d_ = &d;
  }

  // The explored triangulation, in the metric of the parameter last reached.
  const Intrinsic_triangulation<FT>& triangulation() const { return work_; }

  // Moves the metric from t_from towards t_to, flipping every edge when it stops being Delaunay,
  // and stopping early where a triangle at a boundary or unflippable edge would degenerate.
  // Returns the parameter t reached; adds the flips to `count`.
  FT follow(const FT& t_from, const FT& t_to, std::size_t& count)
  {
    using std::exp;
    const std::vector<FT>& d = *d_;
    // (tau of the event, last tau known to be safe, edge, version of the edge when scheduled)
    typedef std::tuple<FT, FT, int, unsigned> Event;
    std::priority_queue<Event, std::vector<Event>, std::greater<Event>> events;
    version_.assign(work_.number_of_edges(), 0u);
    auto time_of = [&](const FT& tau) { return t_from + tau * (t_to - t_from); };
    // Earliest tau in [lo, 1] where the predicate fails, by bisection; none if it holds at 1.
    auto schedule = [&](int e, const FT& lo) {
      const bool constraint = work_.is_border_edge(e) || work_.is_unflippable(e);
      auto holds = [&](const FT& tau) {
        if(constraint)
          return constraint_ok(e, time_of(tau));
        // The tolerance keeps a just flipped (cocircular) edge from flipping straight back.
        FT value;
        return delaunay_value(e, time_of(tau), value) && !(value < -flip_tolerance_);
      };
      if(holds(FT(1)))
        return;
      if(!holds(lo))
      {
        events.push(Event(lo, lo, e, version_[e]));
        return;
      }
      FT a = lo, b(1);
      for(int it = 0; it < 64 && b - a > FT(1e-15); ++it)
      {
        const FT m = (a + b) / FT(2);
        (holds(m) ? a : b) = m;
      }
      // a constraint stops the path where it still holds; a flip happens just past the root
      events.push(Event(constraint ? a : b, a, e, version_[e]));
    };
    for(int e = 0; e < work_.number_of_edges(); ++e)
      schedule(e, FT(0));
    FT reached_tau(1);
    std::size_t budget = 64 * static_cast<std::size_t>(work_.number_of_edges()) + 1000; // guards against cycles
    while(!events.empty() && budget-- > 0)
    {
      const Event ev = events.top();
      events.pop();
      const int e = std::get<2>(ev);
      if(std::get<3>(ev) != version_[e])
        continue;
      const FT tau = std::get<0>(ev), t = time_of(tau);
      if(work_.is_border_edge(e) || work_.is_unflippable(e))
      {
        reached_tau = tau;
        break;
      }
      int h = work_.halfedge(e);
      const int quad[5] = {e, work_.edge(work_.next(h)), work_.edge(work_.prev(h)),
                           work_.edge(work_.next(work_.opposite(h))), work_.edge(work_.prev(work_.opposite(h)))};
      for(int q : quad)
        work_.set_length(q, length_at(q, t));
      if(!work_.flip(e))
      {
        // e.g. both sides of e in one face: the path cannot go on past the last safe point
        reached_tau = std::get<1>(ev);
        break;
      }
      ++count;
      path_flips_.emplace_back(e, t);
      h = work_.halfedge(e);
      base_[e] = work_.length(e) * exp(-t * (d[work_.source(h)] + d[work_.target(h)]));
      for(int q : quad)
      {
        ++version_[q];
        schedule(q, tau);
      }
    }
    const FT reached = time_of(reached_tau);
    for(int e = 0; e < work_.number_of_edges(); ++e)
      work_.set_length(e, length_at(e, reached));
    return reached;
  }

  // Replays the explored flips on `tri` (same lengths at the same moments: same results),
  // recording them for the correspondence, and sets the metric of `tri` to the one at
  // `accepted_step`. `l0` is the metric of `tri` when the exploration started; `replay_base`
  // is a buffer for the bases of the replayed edges; `number_of_flips` counts the flips done.
  void replay(Intrinsic_triangulation<FT>& tri, const std::vector<FT>& l0, const FT& accepted_step,
              std::vector<FT>& replay_base, std::size_t& number_of_flips) const
  {
    using std::exp;
    const std::vector<FT>& d = *d_;
    replay_base = l0;
    auto replay_length = [&](int e, const FT& t) {
      const int h = tri.halfedge(e);
      return replay_base[e] * exp(t * (d[tri.source(h)] + d[tri.target(h)]));
    };
    for(const std::pair<int, FT>& pf : path_flips_)
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
      ++number_of_flips;
      const int g_new = tri.halfedge(e);
      replay_base[e] = tri.length(e) * exp(-pf.second * (d[tri.source(g_new)] + d[tri.target(g_new)]));
    }
    for(int e = 0; e < tri.number_of_edges(); ++e)
      tri.set_length(e, replay_length(e, accepted_step));
  }

private:
  FT length_at(int e, const FT& t) const
  {
    using std::exp;
    const std::vector<FT>& d = *d_;
    const int h = work_.halfedge(e);
    return base_[e] * exp(t * (d[work_.source(h)] + d[work_.target(h)]));
  }

  // Sum of the cotangents opposite e at t; false if a triangle of e is not valid at t.
  bool delaunay_value(int e, const FT& t, FT& value) const
  {
    value = FT(0);
    const int h = work_.halfedge(e);
    for(int g_side : {h, work_.opposite(h)})
    {
      const int f = work_.face(g_side);
      std::array<FT, 3> tan_half;
      if(!half_angle_tangents(std::array<FT, 3>{{length_at(work_.edge(f, 1), t), length_at(work_.edge(f, 2), t),
                                                 length_at(work_.edge(f, 0), t)}}, tan_half))
        return false;
      value += cot_from_half_tangent(tan_half[(g_side % 3 + 2) % 3]);
    }
    return true;
  }

  // Whether the angles opposite a boundary or unflippable edge e stay at most the block angle at
  // t (and its triangles are valid): no flip can save such a triangle, so the path stops there
  // and the edge is split after the step.
  bool constraint_ok(int e, const FT& t) const
  {
    const int h = work_.halfedge(e);
    for(int g_side : {h, work_.opposite(h)})
    {
      if(g_side < 0)
        continue;
      const int f = work_.face(g_side);
      std::array<FT, 3> tan_half;
      if(!half_angle_tangents(std::array<FT, 3>{{length_at(work_.edge(f, 1), t), length_at(work_.edge(f, 2), t),
                                                 length_at(work_.edge(f, 0), t)}}, tan_half))
        return false;
      if(angle_from_half_tangent(tan_half[(g_side % 3 + 2) % 3]) > block_angle_)
        return false;
    }
    return true;
  }

  const FT block_angle_;
  const FT flip_tolerance_;
  Intrinsic_triangulation<FT> work_;
  std::vector<std::pair<int, FT>> path_flips_; // (edge, t) in the order they were done on `work`
  std::vector<FT> base_;
  std::vector<unsigned> version_;
  const std::vector<FT>* d_ = nullptr;
};

} // namespace ricci_flow
} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_RICCI_FLOW_CONFORMAL_PATH_H
