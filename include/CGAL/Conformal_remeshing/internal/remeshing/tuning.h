// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The remesher's fixed factors, each a multiple of the local target edge length h unless said
// otherwise. They were chosen by measuring the remeshing benchmark's models and CGAL's data
// meshes; the measurements are in benchmark/Conformal_remeshing/results/tuning_constants.md.

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_TUNING_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_TUNING_H

namespace CGAL {
namespace Conformal_remeshing {
namespace internal {
namespace remeshing {

// The planar refinement and the optimization bound the longest edge of a triangle by this
// factor times h, which puts the mean edge near h. A smaller bound (isotropic_remeshing()'s
// 4/3) raised the skewness of CAD plates, whose boundary samples stay h apart.
constexpr double longest_edge_factor = 1.4;

// After its first rounds, the optimization splits the inner edges longer than this and bounds
// the edges by it from then on: the refinement leaves clusters of nearly equilateral triangles
// with edges just under 1.4 h, which no flip or move improves and which stand farthest from a
// curved input. Lower factors leave too many split halves under 0.7 h.
constexpr double split_edge_factor = 1.26;

// It also splits the inner edges at least the second factor long whose chord's midpoint stands
// farther than the first factor from the surface point of its planar midpoint: edges across
// bends sharper than the target, where the output stood farthest from bent sheets and scans.
constexpr double off_surface_split_factor = 0.15, shortest_off_surface_split_factor = 0.9;

// And the inner edges at least the second factor long whose chord stands farther than the
// first factor off the surface: where the surface curves with a radius under about 3.4 h, the
// longest edges cut under it. From the first split on, no flip or move makes such a chord.
constexpr double tight_curve_split_factor = 0.045, shortest_tight_curve_split_factor = 1.05;

// After the splits, the optimization collapses the inner edges shorter than this times the
// size there: split halves, and the edges where a lattice grown in the plane meets the coarser
// mesh from the border.
constexpr double collapse_edge_factor = 0.7;

// After gluing, the edges at samples shorter than this times the size there are collapsed
// (collapses_after_gluing.h): two samples that close (the ends and middle of a short slit, the
// samples of two curves that pass close by) are where the glued output had its needles.
constexpr double sample_collapse_edge_factor = 0.25;

// The frontal insertion's target edge length in the plane, as a ratio to the refinement's size
// bound (`longest_edge_factor` h through the map's scale): 0.95 h on the surface. Rows of
// equilateral triangles at h itself cover the surface with fewer vertices than the refinement
// and stand farther from curved inputs; at this ratio both match the refinement's.
constexpr double frontal_target_ratio = 0.68;

// The planar refinement's shape bound, in degrees, is the smaller of the `minimum_angle`
// parameter and this, about the bound for which Delaunay refinement provably ends (CGAL's
// default, sin^2 = 1/8). The angles above it are the optimization on the surface's work: higher
// bounds in the plane fanned bad triangles around short chords and small input angles.
constexpr double planar_refinement_angle_bound = 20.7;

// Rows of seeds along features, borders and user patch borders before the refinement (see
// `equilateral_seeds()`): the first row over the boundary chords, the second over the first. A
// third row lowered the smallest angles without bringing the output closer to the input.
constexpr int seed_layers = 2;

// An input vertex whose tip the output would cut by more than this times h is kept as an
// output vertex (see kept_input_vertices.h): the tips of coarse smooth parts stand 0.03 h to
// 0.05 h over an output that does not keep them.
constexpr double kept_tip_tolerance = 0.03;

// Where a glued output intersects itself, those places are meshed again with edges of half the
// target there, then a quarter, up to this many rounds: the last reaches 1/16 of the target, the
// smallest size the size field gives (`bounded_size()`). (Tiny chamfered corners of CAD parts,
// a tenth of the target across, need that last round: CGAL's cheese.off.)
constexpr int max_self_intersection_refinements = 4;

// Where a glued output stands farther from the input than `maximum_surface_distance`, those
// places are meshed again with edges of half the target there, halved again where it still
// does, in at most this many rounds: halving the edges quarters a chord's sagitta and halves
// what a cut crease loses.
constexpr int max_surface_distance_refinements = 4;

// The default surface-distance bound, times the target edge length: a chord of a target length
// on a circle of radius h stands 0.13 h off it, so smooth parts meshed at their scale stay
// within it, while a small feature cut off or a crease rounded away shows.
constexpr double default_surface_distance = 0.25;

// A boundary curve of a patch whose chords do not glue is sampled twice as densely at most this
// many times; diagonals shared by two patches are split in at most this many rounds.
constexpr int max_curve_halvings = 6, max_diagonal_rounds = 4;

} // namespace remeshing
} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_TUNING_H
