// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// cgal_conformal_remeshing: the Python front end of the package. It takes and returns NumPy
// vertex and face arrays (V: n x 3 coordinates, F: m x 3 vertex indices), builds a
// CGAL::Surface_mesh from them, calls the library's functions and turns their reports into
// dicts, one small converter per report struct. Nothing here remeshes: every decision is the
// library's.
//
// - Arrays are checked before the library sees them: shapes and dtypes here, then the library's
//   own soup checks (`check_polygon_soup()`) for indices out of range and non-finite
//   coordinates; either raises ValueError, the latter with the library's message.
// - The library's errors: `Error_code::INVALID_INPUT` raises ValueError, `TIME_LIMIT_EXCEEDED`
//   TimeoutError, every other code `RemeshingError` (a RuntimeError with a `code` attribute).
// - The library's work runs with the GIL released (`run_long_call()`). The progress and sizing
//   callbacks of `remesh()` take it back to call Python; an exception they raise stops the call
//   (through the library's `stop_requested` parameter) and is raised again, as it was, once the
//   call has unwound.
// - Ctrl-C: while the library works for a call made from the main thread, SIGINT only sets a
//   flag, which `remesh()` and `flatten()` pass to the library as `stop_requested`: they stop at
//   its next time-limit check (between stages, patches and Newton iterations). The signal is
//   then handed to Python, whose handler raises KeyboardInterrupt.

#include <CGAL/Conformal_remeshing/IO/read_mesh.h>
#include <CGAL/Conformal_remeshing/check_mesh.h>
#include <CGAL/Conformal_remeshing/conformal_flatten.h>
#include <CGAL/Conformal_remeshing/angles_at_sharp_corners.h>
#include <CGAL/Conformal_remeshing/mesh_quality.h>
#include <CGAL/Conformal_remeshing/verify_remesh.h>
#include <CGAL/remesh_conformal.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <initializer_list>
#include <limits>
#include <mutex>
#include <optional>
#include <tuple>
#include <string>
#include <utility>
#include <vector>

#include <signal.h> // sigaction

namespace py = pybind11;
namespace CR = CGAL::Conformal_remeshing;
typedef CGAL::Epick K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

namespace {

// --- arrays in ----------------------------------------------------------------------------------

// The vertices and faces of the arrays, as the library's soup functions take them.
struct Soup
{
  std::vector<K::Point_3> points;
  std::vector<std::vector<std::size_t> > polygons;
};

// `object` as a NumPy array of shape (rows, 3), with a dtype of one of `kinds` (NumPy's kind
// letters); `rows` names the number of rows in the message.
py::array checked_array(const py::handle& object, const std::string& name, const char* rows, const char* kinds,
                        const char* wanted)
{
  py::array a = py::module_::import("numpy").attr("asarray")(object);
  if(a.ndim() != 2 || a.shape(1) != 3)
  {
    std::string shape = "(";
    for(py::ssize_t i = 0; i < a.ndim(); ++i)
      shape += (i > 0 ? ", " : "") + std::to_string(a.shape(i));
    shape += a.ndim() == 1 ? ",)" : ")";
    throw py::value_error(name + " must be an array of shape (" + rows + ", 3), not " + shape);
  }
  const char kind = a.dtype().kind();
  if(std::string(kinds).find(kind) == std::string::npos)
    throw py::value_error(name + " must hold " + wanted + ", not " + std::string(py::str(a.dtype())));
  return a;
}

// The soup of V and F: V of floating-point or integer dtype, F of integer dtype. A negative
// index, and with `distinct_corners` a face that repeats a vertex, raise ValueError here: no
// soup holds them. Indices past the vertices are left for the library's checks.
Soup soup_of(const py::handle& V, const py::handle& F, const std::string& v_name, const std::string& f_name,
             bool distinct_corners)
{
  const py::array v = checked_array(V, v_name, "n", "fiu", "floating-point coordinates");
  const py::array f = checked_array(F, f_name, "m", "iu", "integer vertex indices");
  const auto coordinates = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(v);
  const auto indices = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(f);
  if(!coordinates || !indices)
    throw py::value_error(v_name + " and " + f_name + " must convert to float64 and int64 arrays");
  Soup soup;
  const auto x = coordinates.unchecked<2>();
  soup.points.reserve(std::size_t(x.shape(0)));
  for(py::ssize_t i = 0; i < x.shape(0); ++i)
    soup.points.emplace_back(x(i, 0), x(i, 1), x(i, 2));
  const bool unsigned_indices = f.dtype().kind() == 'u';
  const auto t = indices.unchecked<2>();
  soup.polygons.reserve(std::size_t(t.shape(0)));
  for(py::ssize_t i = 0; i < t.shape(0); ++i)
  {
    std::vector<std::size_t> polygon(3);
    for(int c = 0; c < 3; ++c)
    {
      // uint64 indices past int64's range wrap to negative values: out of range all the same.
      if(t(i, c) < 0)
        throw py::value_error(f_name + "[" + std::to_string(i) + ", " + std::to_string(c) + "] = "
                              + (unsigned_indices ? "a vertex index above 2^63" : std::to_string(t(i, c)))
                              + " is out of range: vertex indices are in [0, " + std::to_string(soup.points.size()) + ")");
      polygon[c] = std::size_t(t(i, c));
    }
    if(distinct_corners && (polygon[0] == polygon[1] || polygon[1] == polygon[2] || polygon[0] == polygon[2]))
      throw py::value_error(f_name + "[" + std::to_string(i) + "] = [" + std::to_string(polygon[0]) + ", "
                            + std::to_string(polygon[1]) + ", " + std::to_string(polygon[2])
                            + "] repeats a vertex: a triangle needs three distinct vertices");
    soup.polygons.push_back(std::move(polygon));
  }
  return soup;
}

// The checks of `checks` restricted to the defects in `kinds`.
CR::Mesh_check_report only(const CR::Mesh_check_report& checks, std::initializer_list<CR::Mesh_defect> kinds)
{
  CR::Mesh_check_report left = checks;
  left.defects.clear();
  for(const CR::Defect_summary& d : checks.defects)
    if(std::find(kinds.begin(), kinds.end(), d.defect) != kinds.end())
      left.defects.push_back(d);
  return left;
}

// Raises ValueError with the library's words when the soup has an index past its vertices or a
// non-finite coordinate: what no function can take.
void require_readable(const CR::Mesh_check_report& checks, const std::string& caller)
{
  const CR::Mesh_check_report bad = only(checks, {CR::Mesh_defect::INVALID_VERTEX_INDEX, CR::Mesh_defect::NON_FINITE_COORDINATES});
  if(!bad.is_valid())
    throw py::value_error(caller + ": invalid arrays: " + bad.summary());
}

// Whether a halfedge data structure can hold the soup (as `read_and_check_mesh()` decides).
bool is_buildable(const Soup& soup, const CR::Mesh_check_report& checks)
{
  return !soup.polygons.empty() && checks.count(CR::Mesh_defect::INVALID_VERTEX_INDEX) == 0
         && checks.count(CR::Mesh_defect::NON_MANIFOLD_VERTEX) == 0
         && CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(soup.polygons);
}

// The mesh of the soup, vertex i being row i of V and face j row j of F, as the tools build it.
Mesh mesh_of(const Soup& soup)
{
  Mesh mesh;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(soup.points, soup.polygons, mesh);
  return mesh;
}

// The mesh of V and F for the functions that need one: ValueError with the library's checks
// when the arrays cannot make one.
Mesh required_mesh(const py::handle& V, const py::handle& F, const std::string& caller, const std::string& v_name = "V",
                   const std::string& f_name = "F")
{
  const Soup soup = soup_of(V, F, v_name, f_name, true);
  const CR::Mesh_check_report checks = CR::check_polygon_soup<K>(soup.points, soup.polygons);
  require_readable(checks, caller);
  if(!is_buildable(soup, checks))
    throw py::value_error(caller + ": " + v_name + " and " + f_name + " are not a polygon mesh (" + checks.summary() + ")");
  return mesh_of(soup);
}

// --- arrays out ---------------------------------------------------------------------------------

template <typename T>
py::array_t<T> array_of(const std::vector<T>& values)
{
  py::array_t<T> a(py::ssize_t(values.size()));
  std::copy(values.begin(), values.end(), a.mutable_data());
  return a;
}

// V and F of a mesh, in the order of `vertices(mesh)` and `faces(mesh)`.
py::tuple arrays_of(const Mesh& mesh)
{
  std::vector<std::size_t> index(mesh.num_vertices(), 0); // num_vertices(): removed ones too
  py::array_t<double> V({py::ssize_t(mesh.number_of_vertices()), py::ssize_t(3)});
  auto v = V.mutable_unchecked<2>();
  py::ssize_t row = 0;
  for(Mesh::Vertex_index x : mesh.vertices())
  {
    index[x.idx()] = std::size_t(row);
    const K::Point_3& p = mesh.point(x);
    for(int c = 0; c < 3; ++c)
      v(row, c) = p[c];
    ++row;
  }
  py::array_t<std::int64_t> F({py::ssize_t(mesh.number_of_faces()), py::ssize_t(3)});
  auto f = F.mutable_unchecked<2>();
  row = 0;
  for(Mesh::Face_index face : mesh.faces())
  {
    int c = 0;
    for(Mesh::Vertex_index x : mesh.vertices_around_face(mesh.halfedge(face)))
      if(c < 3)
        f(row, c++) = std::int64_t(index[x.idx()]);
    ++row;
  }
  return py::make_tuple(V, F);
}

// --- reports out: one converter per struct of the library -------------------------------------

const char* code_name(CR::Error_code code)
{
  switch(code)
  {
    case CR::Error_code::SUCCESS: return "SUCCESS";
    case CR::Error_code::INVALID_INPUT: return "INVALID_INPUT";
    case CR::Error_code::FILE_NOT_READABLE: return "FILE_NOT_READABLE";
    case CR::Error_code::UNSUPPORTED_FORMAT: return "UNSUPPORTED_FORMAT";
    case CR::Error_code::GAUSS_BONNET_VIOLATED: return "GAUSS_BONNET_VIOLATED";
    case CR::Error_code::NOT_CONVERGED: return "NOT_CONVERGED";
    case CR::Error_code::LINEAR_SOLVER_FAILED: return "LINEAR_SOLVER_FAILED";
    case CR::Error_code::DEGENERATE_METRIC: return "DEGENERATE_METRIC";
    case CR::Error_code::NOT_AN_EMBEDDING: return "NOT_AN_EMBEDDING";
    case CR::Error_code::TIME_LIMIT_EXCEEDED: return "TIME_LIMIT_EXCEEDED";
  }
  return "UNKNOWN";
}

const char* defect_kind(CR::Mesh_defect d)
{
  switch(d)
  {
    case CR::Mesh_defect::EMPTY_MESH: return "EMPTY_MESH";
    case CR::Mesh_defect::INVALID_VERTEX_INDEX: return "INVALID_VERTEX_INDEX";
    case CR::Mesh_defect::NON_FINITE_COORDINATES: return "NON_FINITE_COORDINATES";
    case CR::Mesh_defect::NON_TRIANGLE_FACE: return "NON_TRIANGLE_FACE";
    case CR::Mesh_defect::DEGENERATE_FACE: return "DEGENERATE_FACE";
    case CR::Mesh_defect::DUPLICATED_VERTEX: return "DUPLICATED_VERTEX";
    case CR::Mesh_defect::ISOLATED_VERTEX: return "ISOLATED_VERTEX";
    case CR::Mesh_defect::NON_MANIFOLD_EDGE: return "NON_MANIFOLD_EDGE";
    case CR::Mesh_defect::NON_MANIFOLD_VERTEX: return "NON_MANIFOLD_VERTEX";
    case CR::Mesh_defect::INCONSISTENT_ORIENTATION: return "INCONSISTENT_ORIENTATION";
    case CR::Mesh_defect::NON_ORIENTABLE: return "NON_ORIENTABLE";
  }
  return "UNKNOWN";
}

py::dict to_dict(const CR::Component_topology& c)
{
  py::dict d;
  d["vertices"] = c.vertices;
  d["edges"] = c.edges;
  d["faces"] = c.faces;
  d["boundary_loops"] = c.boundary_loops;
  d["euler_characteristic"] = c.euler_characteristic;
  d["genus"] = c.genus;
  return d;
}

py::list to_list(const std::vector<CR::Component_topology>& components)
{
  py::list l;
  for(const CR::Component_topology& c : components)
    l.append(to_dict(c));
  return l;
}

py::dict to_dict(const CR::Mesh_check_report& r)
{
  py::dict d;
  d["valid"] = r.is_valid();
  d["manifold_surface"] = r.is_manifold_surface();
  d["summary"] = r.summary();
  d["number_of_vertices"] = r.number_of_vertices;
  d["number_of_faces"] = r.number_of_faces;
  py::list defects;
  for(const CR::Defect_summary& s : r.defects)
  {
    py::dict defect;
    defect["kind"] = defect_kind(s.defect);
    defect["name"] = CR::defect_name(s.defect, s.count);
    defect["count"] = s.count;
    defect["example"] = s.example;
    defects.append(defect);
  }
  d["defects"] = defects;
  d["topology_available"] = r.topology_available;
  d["components"] = to_list(r.components);
  if(r.topology_available)
  {
    d["total_genus"] = r.total_genus();
    d["total_boundary_loops"] = r.total_boundary_loops();
  }
  return d;
}

py::dict to_dict(const CR::Statistics& s)
{
  py::dict d;
  d["min"] = s.min;
  d["mean"] = s.mean;
  d["max"] = s.max;
  return d;
}

py::dict to_dict(const CR::Histogram& h)
{
  py::dict d;
  d["lower"] = h.lower;
  d["bin_width"] = h.bin_width;
  d["counts"] = array_of(h.counts);
  return d;
}

py::dict to_dict(const CR::Mesh_quality_report& q)
{
  py::dict d;
  d["number_of_vertices"] = q.number_of_vertices;
  d["number_of_edges"] = q.number_of_edges;
  d["number_of_faces"] = q.number_of_faces;
  d["minimum_angle"] = to_dict(q.minimum_angle);
  d["maximum_angle"] = to_dict(q.maximum_angle);
  py::dict below;
  for(std::size_t i = 0; i < q.angle_thresholds.size(); ++i)
    below[py::float_(q.angle_thresholds[i])] = q.share_below[i];
  d["share_with_minimum_angle_below"] = below;
  d["skewness"] = to_dict(q.skewness);
  d["aspect_ratio"] = to_dict(q.aspect_ratio);
  d["number_of_degenerate_faces"] = q.number_of_degenerate_faces;
  d["edge_length"] = to_dict(q.edge_length);
  d["median_edge_length"] = q.median_edge_length;
  d["valence_histogram"] = array_of(q.valence_histogram);
  d["angle_histogram"] = to_dict(q.angle_histogram);
  d["minimum_angle_histogram"] = to_dict(q.minimum_angle_histogram);
  d["skewness_histogram"] = to_dict(q.skewness_histogram);
  return d;
}

py::dict to_dict(const CR::Reference_comparison& c)
{
  py::dict d;
  d["reference_diagonal"] = c.reference_diagonal;
  d["relative_distance_to_reference"] = c.relative_distance_to_reference;
  d["relative_distance_from_reference"] = c.relative_distance_from_reference;
  d["relative_hausdorff_distance"] = c.relative_hausdorff_distance();
  d["area_ratio"] = c.area_ratio;
  d["self_intersects"] = c.self_intersects;
  d["farthest_point_to_reference"] = py::make_tuple(c.farthest_point_to_reference[0], c.farthest_point_to_reference[1],
                                                    c.farthest_point_to_reference[2]);
  d["farthest_point_from_reference"] = py::make_tuple(c.farthest_point_from_reference[0], c.farthest_point_from_reference[1],
                                                      c.farthest_point_from_reference[2]);
  return d;
}

py::dict to_dict(const CR::Planar_embedding_report& e)
{
  py::dict d;
  d["is_embedding"] = e.is_embedding();
  d["summary"] = e.summary();
  d["number_of_faces"] = e.number_of_faces;
  d["non_positive_faces"] = e.non_positive_faces;
  d["overlapping_face_pairs"] = e.overlapping_face_pairs;
  d["boundary_intersections"] = e.boundary_intersections;
  d["misplaced_holes"] = e.misplaced_holes;
  d["non_finite_points"] = e.non_finite_points;
  return d;
}

py::dict to_dict(const CR::Flattening_report& r)
{
  py::dict d;
  d["status"] = code_name(r.status);
  d["converged"] = r.converged;
  d["iterations"] = r.iterations;
  d["curvature_error"] = r.curvature_error;
  d["flips"] = r.flips;
  d["hole_fill_flips"] = r.hole_fill_flips;
  d["boundary_loops"] = r.boundary_loops;
  d["boundary_splits"] = r.boundary_splits;
  d["edge_splits"] = r.edge_splits;
  d["refined_edge_length"] = r.refined_edge_length;
  d["retriangulated_faces"] = r.retriangulated_faces;
  d["welded_vertices"] = r.welded_vertices;
  d["flat_sides_shortened"] = r.flat_sides_shortened;
  d["min_scale"] = r.min_scale;
  d["max_scale"] = r.max_scale;
  d["embedding"] = to_dict(r.embedding);
  d["folded_input_triangles_in_uv"] = r.folded_input_triangles_in_uv;
  d["seconds_welding"] = r.seconds_welding;
  d["seconds_flow"] = r.seconds_flow;
  d["seconds_layout"] = r.seconds_layout;
  d["seconds_check"] = r.seconds_check;
  d["seconds_refinement"] = r.seconds_refinement;
  d["flow_message"] = r.flow_message;
  d["seconds_flips"] = r.seconds_flips;
  d["seconds_factorization"] = r.seconds_factorization;
  d["seconds_solve"] = r.seconds_solve;
  d["seconds_line_search"] = r.seconds_line_search;
  return d;
}

py::dict to_dict(const CR::Input_preparation_report& r)
{
  py::dict d;
  d["repaired"] = r.repaired();
  d["summary"] = r.summary();
  d["coincident_vertices"] = r.coincident_vertices;
  d["split_non_manifold_vertices"] = r.split_non_manifold_vertices;
  d["removed_degenerate_faces"] = r.removed_degenerate_faces;
  d["coincident_example"] = r.coincident_example;
  d["non_manifold_example"] = r.non_manifold_example;
  d["degenerate_example"] = r.degenerate_example;
  return d;
}

// The soup repairs the tools make (`Input_repairs`); `file_face` is left out: the faces of F are
// triangles, never cut, so it is the identity.
py::dict to_dict(const CR::Input_repair_report& r)
{
  py::dict d;
  d["repaired"] = r.any();
  d["summary"] = r.summary();
  d["triangulated_polygons"] = r.triangulated_polygons;
  d["triangles_from_polygons"] = r.triangles_from_polygons;
  d["reoriented_faces"] = r.reoriented_faces;
  d["removed_isolated_vertices"] = r.removed_isolated_vertices;
  d["stitched_vertices"] = r.stitched_vertices;
  d["split_vertices"] = r.split_vertices;
  return d;
}

py::dict to_dict(const CR::Meshing_phase_seconds& m)
{
  py::dict d;
  CR::Meshing_phase_seconds::for_each_phase([&](const char* name, double CR::Meshing_phase_seconds::*phase) { d[name] = m.*phase; });
  return d;
}

py::dict to_dict(const CR::Remeshing_statistics& s)
{
  py::dict d;
  py::list patches;
  for(const CR::Flattening_report& r : s.patches)
    patches.append(to_dict(r));
  d["patches"] = patches;
  d["max_newton_iterations"] = s.max_newton_iterations;
  d["max_curvature_error"] = s.max_curvature_error;
  d["flips"] = s.flips;
  d["retriangulated_faces"] = s.retriangulated_faces;
  d["max_scale_ratio"] = s.max_scale_ratio;
  d["boundary_curves"] = s.boundary_curves;
  d["boundary_samples"] = s.boundary_samples;
  d["patch_jobs_run"] = s.patch_jobs_run;
  d["patch_jobs_kept"] = s.patch_jobs_kept;
  d["clamped_vertices"] = s.clamped_vertices;
  d["optimization_flips"] = s.optimization_flips;
  d["optimization_splits"] = s.optimization_splits;
  d["optimization_chord_splits"] = s.optimization_chord_splits;
  d["optimization_collapses"] = s.optimization_collapses;
  d["flips_after_gluing"] = s.flips_after_gluing;
  d["collapses_after_gluing"] = s.collapses_after_gluing;
  d["moves_after_gluing"] = s.moves_after_gluing;
  d["seconds_segmentation"] = s.seconds_segmentation;
  d["seconds_flattening"] = s.seconds_flattening;
  d["seconds_meshing_stage"] = s.seconds_meshing_stage;
  d["seconds_gluing"] = s.seconds_gluing;
  d["seconds_proximity"] = s.seconds_proximity;
  d["seconds_surface_distance"] = s.seconds_surface_distance;
  d["seconds_ricci_flow"] = s.seconds_ricci_flow;
  d["seconds_planar_meshing"] = s.seconds_planar_meshing;
  d["seconds_optimization"] = s.seconds_optimization;
  d["seconds_pull_back"] = s.seconds_pull_back;
  d["meshing_phases"] = to_dict(s.meshing_phases);
  return d;
}

py::dict to_dict(const CR::Remeshing_report& r)
{
  py::dict d;
  d["target_edge_length"] = r.target_edge_length;
  d["input"] = to_dict(r.input);
  d["input_crosses_itself"] = r.input_crosses_itself;
  d["number_of_patches"] = r.number_of_patches;
  d["plane_cuts"] = r.plane_cuts;
  d["patch_bisections"] = r.patch_bisections;
  d["feature_edges"] = r.feature_edges;
  d["dangling_feature_edges"] = r.dangling_feature_edges;
  d["narrow_strip_feature_edges"] = r.narrow_strip_feature_edges;
  d["features_dropped"] = r.features_dropped;
  d["features_fallback_reason"] = r.features_fallback_reason;
  d["frontal_dropped"] = r.frontal_dropped;
  d["frontal_fallback_reason"] = r.frontal_fallback_reason;
  d["smallest_gap"] = r.smallest_gap;
  d["smallest_gap_point"] = py::make_tuple(r.smallest_gap_point[0], r.smallest_gap_point[1], r.smallest_gap_point[2]);
  d["gap_bounded_vertices"] = r.gap_bounded_vertices;
  d["self_intersection_refinements"] = r.self_intersection_refinements;
  d["surface_distance_bound"] = r.surface_distance_bound;
  d["surface_distance_refinements"] = r.surface_distance_refinements;
  d["places_beyond_surface_distance"] = r.places_beyond_surface_distance;
  d["surface_distance_rounds_dropped"] = r.surface_distance_rounds_dropped;
  d["largest_surface_distance"] = r.largest_surface_distance;
  d["largest_surface_distance_point"] =
    py::make_tuple(r.largest_surface_distance_point[0], r.largest_surface_distance_point[1], r.largest_surface_distance_point[2]);
  py::list still_beyond;
  for(const std::array<double, 3>& p : r.places_still_beyond_surface_distance)
    still_beyond.append(py::make_tuple(p[0], p[1], p[2]));
  d["places_still_beyond_surface_distance"] = still_beyond;
  d["output_faces_beyond_surface_distance"] = r.output_faces_beyond_surface_distance;
  d["input_vertices_beyond_surface_distance"] = r.input_vertices_beyond_surface_distance;
  d["input_edges_beyond_surface_distance"] = r.input_edges_beyond_surface_distance;
  d["input_faces_beyond_surface_distance"] = r.input_faces_beyond_surface_distance;
  d["refined_boundary_curves"] = r.refined_boundary_curves;
  d["split_diagonals"] = r.split_diagonals;
  d["output_vertices"] = r.output_vertices;
  d["output_faces"] = r.output_faces;
  return d;
}

py::dict to_dict(const CR::Remesh_verification& v)
{
  py::dict d;
  d["valid"] = v.is_valid();
  d["summary"] = v.summary();
  d["output_vertices"] = v.output_vertices;
  d["output_faces"] = v.output_faces;
  d["output_checks"] = to_dict(v.output_checks);
  d["valid_triangle_mesh"] = v.valid_triangle_mesh;
  d["manifold"] = v.manifold;
  d["self_intersections_checked"] = v.self_intersections_checked;
  d["self_intersecting_face_pairs"] = v.self_intersecting_face_pairs;
  d["self_intersection_free"] = v.self_intersection_free;
  d["input_components"] = to_list(v.input_components);
  d["output_components"] = to_list(v.output_components);
  d["same_number_of_components"] = v.same_number_of_components;
  d["same_genera"] = v.same_genera;
  d["same_boundary_loops"] = v.same_boundary_loops;
  d["topology_kept"] = v.topology_kept;
  d["input_diagonal"] = v.input_diagonal;
  d["tolerance"] = v.tolerance;
  d["max_distance_to_input"] = v.max_distance_to_input;
  d["vertices_off_surface"] = v.vertices_off_surface;
  d["on_input_surface"] = v.on_input_surface;
  d["locations_checked"] = v.locations_checked;
  d["vertices_off_location"] = v.vertices_off_location;
  d["max_location_error"] = v.max_location_error;
  d["locations_match"] = v.locations_match;
  return d;
}

// --- errors -------------------------------------------------------------------------------------

// The tag of cgal_conformal_remeshing.RemeshingError, and the type, set at import.
struct Remeshing_error
{};
py::handle remeshing_error_type;

// Raises the Python exception of a library error (see the top of this file).
[[noreturn]] void raise_library_error(const CR::Error& e)
{
  if(e.code() == CR::Error_code::INVALID_INPUT)
    throw py::value_error(e.what());
  if(e.code() == CR::Error_code::TIME_LIMIT_EXCEEDED)
  {
    PyErr_SetString(PyExc_TimeoutError, e.what());
    throw py::error_already_set();
  }
  py::object error = py::reinterpret_borrow<py::object>(remeshing_error_type)(e.what());
  error.attr("code") = code_name(e.code());
  PyErr_SetObject(remeshing_error_type.ptr(), error.ptr());
  throw py::error_already_set();
}

// --- long calls: the GIL, the callbacks and Ctrl-C ----------------------------------------------

// Thrown by a callback whose Python code raised, to unwind the library; not derived from
// `CR::Error`, so that no fallback of the library takes it for a failure it can work around.
struct Callback_raised
{};

// What the callbacks of one call share: the first Python exception one of them raised, and
// whether the call must stop. The library polls `stop_requested()` from several threads.
class Call_state
{
public:
  bool stop_requested() const { return failed_.load() || interrupted().load(); }

  // Runs `f` (which calls Python) with the GIL held; a Python exception is kept and stops the call.
  template <typename F>
  auto call_python(const F& f) -> decltype(f())
  {
    if(failed_.load())
      throw Callback_raised();
    py::gil_scoped_acquire gil;
    try
    {
      return f();
    }
    catch(...)
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if(!failed_.load())
        failure_ = std::current_exception();
      failed_ = true;
    }
    throw Callback_raised();
  }

  // Raises the kept Python exception, if any (with the GIL held).
  void raise_callback_failure() const
  {
    if(failure_)
      std::rethrow_exception(failure_);
  }

  // Set by the SIGINT handler while a long call runs (see `Interrupt_guard`).
  static std::atomic<bool>& interrupted()
  {
    static std::atomic<bool> flag(false);
    return flag;
  }

private:
  std::atomic<bool> failed_{false};
  std::mutex mutex_;
  std::exception_ptr failure_;
};

void on_sigint(int) { Call_state::interrupted() = true; }

// For the duration of a long call from the main thread, while Python's own SIGINT handler is in
// place, SIGINT only sets `Call_state::interrupted()`. Nested calls (a callback that calls the
// module again) keep the outermost guard's handler.
class Interrupt_guard
{
public:
  Interrupt_guard()
  {
    static int depth = 0; // only changed with the GIL held
    depth_ = &depth;
    const py::module_ signal = py::module_::import("signal");
    const py::module_ threading = py::module_::import("threading");
    const bool main_thread = threading.attr("current_thread")().is(threading.attr("main_thread")());
    if(depth == 0 && main_thread && signal.attr("getsignal")(int(SIGINT)).is(signal.attr("default_int_handler")))
    {
      Call_state::interrupted() = false;
      struct sigaction action = {};
      action.sa_handler = on_sigint;
      sigemptyset(&action.sa_mask);
      action.sa_flags = SA_RESTART;
      installed_ = sigaction(SIGINT, &action, &previous_) == 0;
    }
    ++depth;
  }

  // Gives SIGINT back to Python; if one arrived, Python's handler raises KeyboardInterrupt.
  // Called with the GIL held, before anything else is raised.
  void hand_back()
  {
    if(done_)
      return;
    done_ = true;
    --*depth_;
    if(!installed_)
      return;
    sigaction(SIGINT, &previous_, nullptr);
    if(Call_state::interrupted().exchange(false))
    {
      PyErr_SetInterrupt();
      if(PyErr_CheckSignals() != 0)
        throw py::error_already_set();
    }
  }

  ~Interrupt_guard()
  {
    if(!done_)
    {
      done_ = true;
      --*depth_;
      if(installed_)
        sigaction(SIGINT, &previous_, nullptr);
    }
  }

private:
  int* depth_ = nullptr;
  bool installed_ = false;
  bool done_ = false;
  struct sigaction previous_ = {};
};

// Runs `work()` with the GIL released, then raises, in this order: KeyboardInterrupt if Ctrl-C
// was pressed, a callback's exception, the Python exception of a library error.
template <typename Work>
auto run_long_call(Call_state& state, const Work& work) -> decltype(work())
{
  Interrupt_guard guard;
  std::exception_ptr failure;
  std::optional<decltype(work())> result;
  {
    py::gil_scoped_release release;
    try
    {
      result.emplace(work());
    }
    catch(...)
    {
      failure = std::current_exception();
    }
  }
  guard.hand_back();
  state.raise_callback_failure();
  if(failure)
  {
    try
    {
      std::rethrow_exception(failure);
    }
    catch(const CR::Error& e)
    {
      raise_library_error(e);
    }
  }
  return std::move(*result);
}

double seconds_or_unlimited(const std::optional<double>& seconds)
{
  return seconds ? *seconds : std::numeric_limits<double>::infinity();
}

void require_callable(const py::object& f, const char* name)
{
  if(!f.is_none() && !PyCallable_Check(f.ptr()))
    throw py::type_error(std::string(name) + " must be callable or None");
}

// --- the functions ------------------------------------------------------------------------------

py::tuple remesh(const py::object& V, const py::object& F, std::optional<double> target_edge_length,
                 double relative_edge_length, double minimum_angle, double features_angle, double crease_angle,
                 bool features_fallback,
                 std::optional<double> chord_error, std::optional<double> surface_distance, const py::object& sizing,
                 std::optional<double> time_limit,
                 const py::object& progress, bool repair, int optimization_rounds, int lloyd_iterations,
                 bool frontal_insertion)
{
  require_callable(sizing, "sizing");
  require_callable(progress, "progress");
  // The arrays as the remesh_conformal tool takes a file: the soup repaired (unless `repair` is
  // off), checked, then built into a mesh; the library repairs the rest itself.
  Soup soup = soup_of(V, F, "V", "F", true);
  require_readable(CR::check_polygon_soup<K>(soup.points, soup.polygons), "remesh");
  CR::Input_repair_report repaired;
  // read_and_check_mesh()'s soup repairs, which it makes on what it reads from a file; only
  // their file-reading entry point is public.
  if(repair)
    CR::internal::repair_polygon_soup(soup.points, soup.polygons, CR::Input_repairs::all(), repaired);
  const CR::Mesh_check_report checks = CR::check_polygon_soup<K>(soup.points, soup.polygons);
  const CR::Mesh_check_report left = checks.refused_by_remeshing(repair);
  if(!left.is_valid() || !is_buildable(soup, checks))
    throw py::value_error("remesh: invalid input: " + (left.is_valid() ? checks.summary() : left.summary())
                          + (repaired.any() ? " (after the repairs: " + repaired.summary() + ")" : std::string()));
  const Mesh input = mesh_of(soup);

  // The target edge length as the tool and the library compute it from a relative one.
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(input);
  const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin())
                                    + CGAL::square(box.zmax() - box.zmin()));
  const double target = target_edge_length ? *target_edge_length : relative_edge_length * diagonal;

  Call_state state;
  std::function<void(const std::string&)> progress_callback = [](const std::string&) {};
  if(!progress.is_none())
    progress_callback = [&](const std::string& message) { state.call_python([&] { progress(message); }); };
  // The library asks for one point at a time: each call passes a 1 x 3 array.
  std::function<double(const K::Point_3&)> sizing_field;
  if(!sizing.is_none())
    sizing_field = [&](const K::Point_3& p) {
      return state.call_python([&] {
        py::array_t<double> point({py::ssize_t(1), py::ssize_t(3)});
        auto x = point.mutable_unchecked<2>();
        for(int c = 0; c < 3; ++c)
          x(0, c) = p[c];
        const py::object returned = sizing(point);
        const py::array_t<double> lengths = py::array_t<double, py::array::forcecast>::ensure(returned);
        if(!lengths || lengths.size() != 1)
          throw py::value_error("sizing must return one length per point: called on 1 point, it returned "
                                + std::string(py::repr(returned)));
        return *lengths.data();
      });
    };
  const std::function<bool()> stop = [&] { return state.stop_requested(); };

  namespace P = CR::parameters;
  const auto np = P::stop_requested(stop,
                  P::target_edge_length(target,
                  P::minimum_angle(minimum_angle,
                  P::features_angle(features_angle,
                  P::crease_angle(crease_angle,
                  P::features_fallback(features_fallback,
                  P::maximum_chord_error(chord_error ? *chord_error : 0.,
                  P::maximum_surface_distance(surface_distance ? *surface_distance
                                                               : CR::internal::remeshing::default_surface_distance * target,
                  P::sizing_field(sizing_field,
                  P::maximum_running_time(seconds_or_unlimited(time_limit),
                  P::progress(progress_callback,
                  P::repair_input(repair,
                  P::optimization_rounds(optimization_rounds,
                  P::lloyd_iterations(lloyd_iterations,
                  P::frontal_insertion(frontal_insertion)))))))))))))));
  struct Result
  {
    Mesh output;
    CR::Remeshing_report report;
    CR::Remeshing_statistics statistics;
  };
  Result result = run_long_call(state, [&] {
    Result r;
    r.report = CR::remesh_conformal(input, r.output, CR::parameters::statistics(std::ref(r.statistics), np));
    return r;
  });
  py::dict report = to_dict(result.report);
  report["input_repairs"] = to_dict(repaired);
  report["statistics"] = to_dict(result.statistics);
  const py::tuple arrays = arrays_of(result.output);
  return py::make_tuple(arrays[0], arrays[1], report);
}

py::dict check(const py::object& V, const py::object& F)
{
  const Soup soup = soup_of(V, F, "V", "F", false);
  const CR::Mesh_check_report checks = CR::check_polygon_soup<K>(soup.points, soup.polygons);
  if(!is_buildable(soup, checks))
    return to_dict(checks);
  return to_dict(CR::check_mesh(mesh_of(soup)));
}

py::dict quality(const py::object& V, const py::object& F, const py::object& reference)
{
  const Mesh mesh = required_mesh(V, F, "quality");
  std::optional<Mesh> reference_mesh;
  if(!reference.is_none())
  {
    if(!py::isinstance<py::sequence>(reference) || py::len(reference) != 2)
      throw py::value_error("quality: reference must be a pair (V, F)");
    const py::sequence pair = reference.cast<py::sequence>();
    reference_mesh = required_mesh(pair[0], pair[1], "quality", "reference V", "reference F");
  }
  Call_state state;
  const auto measured = run_long_call(state, [&] {
    std::tuple<CR::Mesh_quality_report, std::optional<CR::Reference_comparison>, std::optional<CR::Sharp_corner_angles> > r;
    std::get<0>(r) = CR::mesh_quality(mesh);
    if(reference_mesh)
    {
      std::get<1>(r) = CR::compare_to_reference(mesh, *reference_mesh);
      std::get<2>(r) = CR::angles_at_sharp_corners(mesh, *reference_mesh);
    }
    return r;
  });
  py::dict d = to_dict(std::get<0>(measured));
  if(std::get<1>(measured))
    d["fidelity"] = to_dict(*std::get<1>(measured));
  if(const auto& a = std::get<2>(measured))
  {
    py::dict corners;
    corners["sharp_input_corners"] = a->sharp_corners;
    corners["triangles_below_25"] = a->triangles_below;
    corners["triangles_below_25_at_sharp_input_corners"] = a->triangles_below_at_sharp_corners;
    corners["share_below_25_away_from_sharp_input_corners"] = a->share_below_away_from_sharp_corners();
    d["angles_at_sharp_corners"] = corners;
  }
  return d;
}

py::tuple flatten(const py::object& V, const py::object& F, std::optional<double> time_limit)
{
  const Mesh mesh = required_mesh(V, F, "flatten");
  Call_state state;
  const std::function<bool()> stop = [&] { return state.stop_requested(); };
  const CR::Conformal_flattening result = run_long_call(state, [&] {
    return CR::conformal_flatten(
      mesh, CR::parameters::stop_requested(stop, CR::parameters::maximum_running_time(seconds_or_unlimited(time_limit))));
  });
  py::array_t<double> UV({py::ssize_t(result.uv.size()), py::ssize_t(2)});
  auto uv = UV.mutable_unchecked<2>();
  for(std::size_t i = 0; i < result.uv.size(); ++i)
  {
    uv(py::ssize_t(i), 0) = result.uv[i].x();
    uv(py::ssize_t(i), 1) = result.uv[i].y();
  }
  py::dict report = to_dict(result.report);
  report["conformal_factor"] = array_of(result.conformal_factor);
  return py::make_tuple(UV, report);
}

py::dict verify(const py::object& V_in, const py::object& F_in, const py::object& V_out, const py::object& F_out,
                double relative_tolerance)
{
  const Mesh input = required_mesh(V_in, F_in, "verify", "V_in", "F_in");
  const CR::Mesh_check_report input_checks = CR::check_mesh(input);
  if(!input_checks.topology_available)
    throw py::value_error("verify: V_in and F_in cannot serve as a reference: not a manifold polygon mesh ("
                          + input_checks.summary() + ")");
  // An output no halfedge structure can hold (but whose indices and coordinates can be read)
  // fails every check that needs one, as in the verify_remesh tool.
  const Soup output_soup = soup_of(V_out, F_out, "V_out", "F_out", false);
  const CR::Mesh_check_report output_checks = CR::check_polygon_soup<K>(output_soup.points, output_soup.polygons);
  require_readable(output_checks, "verify");
  if(!is_buildable(output_soup, output_checks))
  {
    CR::Remesh_verification v;
    v.output_checks = output_checks;
    v.output_vertices = output_checks.number_of_vertices;
    v.output_faces = output_checks.number_of_faces;
    v.input_components = input_checks.components;
    v.locations_match = true;
    return to_dict(v);
  }
  const Mesh output = mesh_of(output_soup);
  Call_state state;
  return to_dict(run_long_call(state, [&] {
    return CR::verify_remesh(input, output, CR::parameters::relative_distance_tolerance(relative_tolerance));
  }));
}

} // namespace

PYBIND11_MODULE(cgal_conformal_remeshing, m)
{
  m.doc() = R"doc(Conformal remeshing of triangle meshes given as NumPy arrays (CGAL Conformal Remeshing).

V is an n x 3 array of vertex coordinates (any float or integer dtype), F an m x 3 array of
vertex indices (any integer dtype), as pymeshlab, gpytoolbox and libigl use them. Returned
arrays are float64 and int64.

Errors: ValueError for bad input (shapes, dtypes, indices out of range, non-finite coordinates,
a mesh the library refuses, a parameter out of range), TimeoutError past a time limit,
RemeshingError (a RuntimeError with a `code` attribute naming the library's Error_code) for
the other failures. Ctrl-C stops remesh() and flatten() at the library's next time-limit check
and raises KeyboardInterrupt.)doc";

  static py::exception<Remeshing_error> error(m, "RemeshingError", PyExc_RuntimeError);
  remeshing_error_type = error;
  error.doc() = "A failure of the library other than invalid input or a time limit; `code` names its "
                "Error_code (e.g. 'NOT_AN_EMBEDDING').";

  m.def("remesh", &remesh, py::arg("V"), py::arg("F"), py::kw_only(), py::arg("target_edge_length") = py::none(),
        py::arg("relative_edge_length") = 0.01, py::arg("minimum_angle") = 28., py::arg("features_angle") = 60.,
        py::arg("crease_angle") = 40., py::arg("features_fallback") = true, py::arg("chord_error") = py::none(),
        py::arg("surface_distance") = py::none(), py::arg("sizing") = py::none(),
        py::arg("time_limit") = py::none(), py::arg("progress") = py::none(), py::arg("repair") = true,
        py::arg("optimization_rounds") = 5, py::arg("lloyd_iterations") = 0, py::arg("frontal_insertion") = true,
        R"doc(remesh(V, F, *, target_edge_length=None, relative_edge_length=0.01, minimum_angle=28.0,
       features_angle=60.0, crease_angle=40.0, features_fallback=True, chord_error=None,
       surface_distance=None, sizing=None,
       time_limit=None,
       progress=None, repair=True, optimization_rounds=5, lloyd_iterations=0,
       frontal_insertion=True) -> (V2, F2, report)

Remeshes the surface (V, F) by conformal flattening (CGAL::remesh_conformal()).

target_edge_length: in the units of V; default relative_edge_length times the bounding-box
    diagonal.
minimum_angle: degrees, in (0, 34].
features_angle: dihedral angle in degrees above which an edge is a sharp feature (0: none);
    with features_fallback, features are dropped when a patch cannot be flattened with them
    (report['features_dropped'] says so).
crease_angle: creases above this angle (and not above features_angle) are features too where
    they form chains at least 5 target lengths long, from sharp features to sharp features, with
    no parallel crease within one (a CAD part's edges, such as a chamfer's); 0: none.
chord_error: curvature-adaptive sizing: largest deviation of a chord from the surface.
surface_distance: a bound on the distance between the output and the input, both ways (units
    of V; default a quarter of the target edge length, 0: none): where they stand farther apart
    after gluing, the surface is meshed again there with shorter edges, in up to four rounds; report['surface_distance_refinements'] and the
    report's *_beyond_surface_distance counts say what was done and what is left.
sizing: a callable taking a k x 3 float64 array of points on the surface and returning k
    edge lengths; the library asks for one point at a time (k = 1). The target edge length
    stays the upper bound, and lengths below 1/16 of it count as 1/16.
time_limit: seconds; past it the call raises TimeoutError.
progress: a callable taking one str, called as each stage starts.
repair: repair the arrays first, as the remesh_conformal tool does (isolated vertices removed,
    faces oriented, borders along the same points stitched, non-manifold edges and vertices
    cut apart, degenerate faces removed); report['input_repairs'] and report['input'] say what.
optimization_rounds, lloyd_iterations, frontal_insertion: the library's parameters of the
    same names.

The callbacks run with the GIL held, the rest of the work without it. An exception raised
in a callback stops the call and is raised again by remesh().
report: the library's Remeshing_report as a dict, with 'input_repairs' and 'statistics'
(Remeshing_statistics: timings, counters and one flattening report per patch).)doc");

  m.def("check", &check, py::arg("V"), py::arg("F"),
        R"doc(check(V, F) -> dict

The library's input checks (check_polygon_soup(), check_mesh()): every defect with a count and
an example, and the topology of each component when the arrays make a manifold mesh. Indices
out of range and non-finite coordinates are reported here, not raised.)doc");

  m.def("quality", &quality, py::arg("V"), py::arg("F"), py::arg("reference") = py::none(),
        R"doc(quality(V, F, reference=None) -> dict

The quality measures of the triangle mesh (mesh_quality()): angles, equiangle skewness, aspect
ratio, edge lengths, valences and histograms. With reference=(V_ref, F_ref), also
'fidelity' (compare_to_reference()): Hausdorff distances both ways relative to the reference's
bounding-box diagonal, area ratio, self-intersection; and 'angles_at_sharp_corners'
(angles_at_sharp_corners()): the triangles below 25 degrees, how many of them have their smallest
angle at an input corner sharper than that, and the share of the others.)doc");

  m.def("flatten", &flatten, py::arg("V"), py::arg("F"), py::kw_only(), py::arg("time_limit") = py::none(),
        R"doc(flatten(V, F, *, time_limit=None) -> (UV, report)

Flattens a genus-0 patch with at least one boundary loop conformally and with no overlap
(conformal_flatten()). UV is n x 2, one row per row of V. report is the library's
Flattening_report, with 'conformal_factor' per vertex; report['status'] is 'SUCCESS', or
'NOT_CONVERGED' / 'NOT_AN_EMBEDDING' when the flattening failed.)doc");

  m.def("verify", &verify, py::arg("V_in"), py::arg("F_in"), py::arg("V_out"), py::arg("F_out"), py::kw_only(),
        py::arg("relative_tolerance") = 1e-9,
        R"doc(verify(V_in, F_in, V_out, F_out, *, relative_tolerance=1e-9) -> dict

Checks independently that (V_out, F_out) is a faithful remeshing of (V_in, F_in)
(verify_remesh()): a valid manifold triangle mesh, no self-intersection, the same topology,
every vertex within relative_tolerance times the input's diagonal of the input surface.
report['valid'] is true when every check holds.)doc");
}
