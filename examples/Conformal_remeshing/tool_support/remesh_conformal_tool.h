// The command-line tool remesh_conformal as a function (`remesh_conformal_main()`), shared by
// remesh_conformal.cpp, whose comment gives its synopsis, and the MPI tool remesh_conformal_mpi.cpp,
// which differs only in where the patch jobs run.

#ifndef CONFORMAL_REMESHING_TOOLS_REMESH_CONFORMAL_TOOL_H
#define CONFORMAL_REMESHING_TOOLS_REMESH_CONFORMAL_TOOL_H

#include "atomic_file.h"
#include "deviation_map.h"
#include "flattening_pictures.h"
#include "quality_plot_svg.h"
#include "report_json.h"

#include <CGAL/Conformal_remeshing/IO/read_mesh.h>
#include <CGAL/Conformal_remeshing/flatten_poly_annuli.h>
#include <CGAL/Conformal_remeshing/mesh_quality.h>
#include <CGAL/remesh_conformal.h>
#include <CGAL/Conformal_remeshing/internal/process_memory.h>
#include <CGAL/Conformal_remeshing/internal/remeshing/patch_job.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <functional>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <limits>
#include <new>
#include <sstream>
#include <string>
#include <vector>

namespace Conformal_remeshing_tools {
namespace remesh_conformal_tool {

namespace CR = CGAL::Conformal_remeshing;
namespace tools = Conformal_remeshing_tools;
typedef CGAL::Epick K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

inline const char* const usage =
  "usage: remesh_conformal IN OUT [--target-edge-length L | --relative-edge-length R] [--min-angle DEG]\n"
  "                        [--features-angle DEG] [--crease-angle DEG] [--patches FILE] [--cut-plane a,b,c,d]...\n"
  "                        [--save-patches DIR] [--sequential] [--report FILE.json] [--plots DIR] [--quiet]\n"
  "                        [--time-limit SECONDS] [--optimization-rounds N] [--lloyd-iterations N] [--chord-error E]\n"
  "                        [--no-frontal] [--no-repair] [--deviation-map PREFIX] [--batch-faces N]\n"
  "                        [--no-fidelity] [--surface-distance D | --relative-surface-distance R]\n"
  "  IN, OUT                 mesh files (.off .obj .ply .stl); OUT is written atomically\n"
  "  --target-edge-length L  target edge length in the input's units\n"
  "  --relative-edge-length R  target edge length as a fraction of the bounding-box diagonal (default 0.01)\n"
  "  --min-angle DEG         smallest angle the optimization on the surface keeps (default 28;\n"
  "                          the planar Delaunay refinement uses at most 20.7)\n"
  "  --features-angle DEG    edges with a dihedral angle above DEG are sharp features (default 60, and none if a\n"
  "                          patch cannot be flattened with them; given, they are kept or the tool fails; 0: none)\n"
  "  --crease-angle DEG      creases above DEG (and not above --features-angle) are features too where they are a CAD\n"
  "                          part's edges: chains at least 5 target lengths long with no parallel crease within one\n"
  "                          (default 40; 0: none)\n"
  "  --patches FILE          user patches: one integer patch id per face of IN, in face order\n"
  "  --cut-plane a,b,c,d     cut the surface by the plane ax+by+cz+d=0 first (repeatable)\n"
  "  --save-patches DIR      DIR/patch_N.off and DIR/patch_N_flattening.svg for every patch meshed (DIR is created)\n"
  "  --sequential            one patch at a time (default: in parallel when built with TBB)\n"
  "  --report FILE.json      stage times, segmentation and flattening, quality of input and output, fidelity\n"
  "  --plots DIR             DIR/quality.svg: angle and skewness histograms, input and output (DIR is created)\n"
  "  --deviation-map PREFIX  PREFIX_output.{ply,png} and PREFIX_input.{ply,png}: each face coloured by its largest\n"
  "                          distance to the other surface (blue 0 to red at a quarter of the target length), and\n"
  "                          the histograms of those distances in the output and in --report\n"
  "  --quiet                 no progress messages\n"
  "  --time-limit SECONDS    give up (exit code 3, no output written) if reading and remeshing take longer\n"
  "  --optimization-rounds N rounds of flips and smoothing judged on the surface after the refinement (default 5, 0: none)\n"
  "  --lloyd-iterations N    at most N iterations of CGAL's Lloyd smoothing in the plane before them (default 0: none)\n"
  "  --no-frontal            place the planar points by Delaunay refinement alone, with one Laplacian pass (by\n"
  "                          default frontal insertion places them in rows of nearly equilateral triangles first)\n"
  "  --chord-error E         shorter edges where the surface bends, so that chords deviate from it by at most E\n"
  "                          (input units; down to 1/16 of the target length; default 0: uniform)\n"
  "  --surface-distance D    mesh again with shorter edges (half the target there, halved again where it still is, down\n"
  "                          to 1/16) where the output and the input stand farther than D apart (input units), either\n"
  "                          way: cut creases, rounded small features, chords across bends; what is still farther is\n"
  "                          reported (0: none)\n"
  "  --relative-surface-distance R  the same, D = R times the target edge length (default 0.25)\n"
  "  --no-repair             refuse polygons, inconsistent orientation, isolated vertices, cracks, non-manifold\n"
  "                          edges and vertices and degenerate faces (by default polygons are triangulated, faces\n"
  "                          oriented, isolated vertices removed, borders along the same points stitched,\n"
  "                          non-manifold edges and vertices cut apart and zero-area faces removed first)\n"
  "  --batch-faces N         an input of more than N faces and several components is remeshed a batch of whole\n"
  "                          components of at most N faces at a time, to bound the memory (default 2000000; 0: in\n"
  "                          one piece)\n"
  "  --no-fidelity           skip the Hausdorff distances to and from the input (they sample every face of both:\n"
  "                          on a car of 15M faces they take longer than the remeshing); the quality and the\n"
  "                          self-intersection check stay\n"
  "Any orientable triangle mesh: closed or open, any genus, several components; vertices at the same point stay\n"
  "distinct.\n"
  "exit code: 0 success, 1 the input cannot be remeshed, 2 the tool could not run, 3 time limit exceeded\n";

struct Options
{
  std::string input, output, report, plots, patches, save_patches, deviation_map;
  double target = 0., relative = 0.01, min_angle = 28., features_angle = 60., crease_angle = 40.;
  double time_limit = std::numeric_limits<double>::infinity();
  double chord_error = 0., surface_distance = -1., relative_surface_distance = 0.25; // surface_distance < 0: not given
  int optimization_rounds = 5, lloyd_iterations = 0;
  double batch_faces = 2000000.;
  std::vector<K::Plane_3> planes;
  bool quiet = false, sequential = false, repair = true, frontal = true, fidelity = true;
  bool features_angle_given = false; // then no fallback without features (CR::parameters::features_fallback)
};

// A message for standard error: the library's errors name their function, which is the tool's
// name too, and are not prefixed twice.
using CGAL::Conformal_remeshing::internal::peak_resident_megabytes;

// The message of an error, prefixed with the tool's name once; std::bad_alloc says what it is.
inline std::string tool_message(const std::string& what)
{
  const std::string prefix = "remesh_conformal: ";
  if(what == std::bad_alloc().what())
    return prefix + "out of memory (" + std::to_string(std::lround(peak_resident_megabytes())) + " MB resident at the most)";
  return what.compare(0, prefix.size(), prefix) == 0 ? what : prefix + what;
}

// A point of the report as "(x, y, z)", with the stream's default precision.
inline std::string point_text(const std::array<double, 3>& p)
{
  std::ostringstream text;
  text << "(" << p[0] << ", " << p[1] << ", " << p[2] << ")";
  return text.str();
}

// A point of the report as a JSON array [x, y, z], written where `json` stands.
inline tools::Json_writer& json_point(tools::Json_writer& json, const std::array<double, 3>& p)
{
  json.begin_array();
  for(double c : p)
    json.value(c);
  return json.end_array();
}

inline bool parse_plane(const std::string& text, std::vector<K::Plane_3>& planes)
{
  std::istringstream in(text);
  double c[4];
  char comma = ',';
  for(int i = 0; i < 4; ++i)
    if(!(in >> c[i]) || (i < 3 && (!(in >> comma) || comma != ',')))
      return false;
  if(!in.eof() && in.peek() != EOF)
    return false;
  if(c[0] == 0. && c[1] == 0. && c[2] == 0.)
    return false;
  planes.emplace_back(c[0], c[1], c[2], c[3]);
  return true;
}

inline bool parse(int argc, char** argv, Options& o)
{
  for(int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    auto number = [&](double& target) {
      if(i + 1 >= argc)
        return false;
      try
      {
        std::size_t used = 0;
        target = std::stod(argv[++i], &used);
        return used == std::string(argv[i]).size();
      }
      catch(const std::exception&)
      {
        return false;
      }
    };
    auto count = [&](int& target) { // a whole number from 0 to 100
      double value = 0.;
      if(!number(value) || !(value >= 0. && value <= 100. && value == std::floor(value)))
        return false;
      target = int(value);
      return true;
    };
    bool ok = true;
    if(arg == "--target-edge-length")
      ok = number(o.target) && o.target > 0.;
    else if(arg == "--relative-edge-length")
      ok = number(o.relative) && o.relative > 0.;
    else if(arg == "--min-angle")
      ok = number(o.min_angle);
    else if(arg == "--features-angle")
      ok = o.features_angle_given = number(o.features_angle);
    else if(arg == "--crease-angle")
      ok = number(o.crease_angle) && o.crease_angle >= 0.;
    else if(arg == "--patches" && i + 1 < argc)
      o.patches = argv[++i];
    else if(arg == "--cut-plane" && i + 1 < argc)
      ok = parse_plane(argv[++i], o.planes);
    else if(arg == "--save-patches" && i + 1 < argc)
      o.save_patches = argv[++i];
    else if(arg == "--sequential")
      o.sequential = true;
    else if(arg == "--report" && i + 1 < argc)
      o.report = argv[++i];
    else if(arg == "--plots" && i + 1 < argc)
      o.plots = argv[++i];
    else if(arg == "--deviation-map" && i + 1 < argc)
      o.deviation_map = argv[++i];
    else if(arg == "--quiet")
      o.quiet = true;
    else if(arg == "--no-repair")
      o.repair = false;
    else if(arg == "--no-fidelity")
      o.fidelity = false;
    else if(arg == "--no-frontal")
      o.frontal = false;
    else if(arg == "--time-limit")
      ok = number(o.time_limit) && o.time_limit > 0.;
    else if(arg == "--optimization-rounds")
      ok = count(o.optimization_rounds);
    else if(arg == "--lloyd-iterations")
      ok = count(o.lloyd_iterations);
    else if(arg == "--batch-faces")
      ok = number(o.batch_faces) && o.batch_faces >= 0. && o.batch_faces == std::floor(o.batch_faces) && o.batch_faces < 1e18;
    else if(arg == "--chord-error")
      ok = number(o.chord_error) && o.chord_error >= 0.;
    else if(arg == "--surface-distance")
      ok = number(o.surface_distance) && o.surface_distance >= 0. && std::isfinite(o.surface_distance);
    else if(arg == "--relative-surface-distance")
      ok = number(o.relative_surface_distance) && o.relative_surface_distance >= 0. && std::isfinite(o.relative_surface_distance);
    else if(!arg.empty() && arg[0] != '-' && o.input.empty())
      o.input = arg;
    else if(!arg.empty() && arg[0] != '-' && o.output.empty())
      o.output = arg;
    else
      ok = false;
    if(!ok)
    {
      std::cerr << "remesh_conformal: bad argument '" << arg << "'\n" << usage;
      return false;
    }
  }
  if(o.input.empty() || o.output.empty())
  {
    std::cerr << "remesh_conformal: needs IN and OUT\n" << usage;
    return false;
  }
  return true;
}

} // namespace remesh_conformal_tool

namespace remesh_conformal_tool {

// The tool's work; `remesh_conformal_main()` turns what escapes it into a message.
inline int run(int argc, char** argv, const CGAL::Conformal_remeshing::internal::remeshing::Patch_job_runner& runner)
{
  const auto start = std::chrono::steady_clock::now();
  for(int i = 1; i < argc; ++i)
    if(std::string(argv[i]) == "--help" || std::string(argv[i]) == "-h")
    {
      std::cout << usage;
      return 0;
    }
  Options o;
  if(!parse(argc, argv, o))
    return 2;
  auto progress = [&](const std::string& message) {
    if(!o.quiet)
      std::cerr << "remesh_conformal: " << message << std::endl;
  };
  // --time-limit counts from the start; the library stops with TIME_LIMIT_EXCEEDED past it.
  auto remaining_time = [&]() {
    return (std::max)(0., o.time_limit - std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  };
  auto out_of_time = [&](const std::string& why) {
    std::cerr << "remesh_conformal: the time limit of " << o.time_limit << " s (--time-limit) was exceeded; no output written ("
              << why << ")\n";
    return 3;
  };

  // Output directories exist before the long work, or the run stops here.
  try
  {
    for(const std::string& directory : {o.save_patches, o.plots})
      if(!directory.empty())
        tools::prepare_output_directory(directory);
  }
  catch(const std::exception& e)
  {
    std::cerr << tool_message(e.what()) << "\n";
    return 2;
  }

  Mesh input;
  CR::Input_repair_report repaired;
  try
  {
    progress("reading " + o.input);
    const CR::Mesh_check_report checks
      = CR::read_and_check_mesh(o.input, input, o.repair ? CR::Input_repairs::all() : CR::Input_repairs(), repaired);
    if(repaired.any())
      progress("repaired the input: " + repaired.summary());
    // Refused here, before any work, as the library would refuse it.
    const CR::Mesh_check_report left = checks.refused_by_remeshing(o.repair);
    if(!left.is_valid())
    {
      std::cerr << "remesh_conformal: invalid input '" << o.input << "': " << left.summary()
                << (repaired.any() ? " (after the repairs: " + repaired.summary() + ")" : std::string()) << "\n";
      return 1;
    }
  }
  catch(const std::exception& e)
  {
    std::cerr << tool_message(e.what()) << "\n";
    return 2;
  }
  if(!(remaining_time() > 0.))
    return out_of_time("stopped after reading the input");

  // User patches: one id per face, all read before anything runs.
  auto patch_of = input.add_property_map<Mesh::Face_index, std::size_t>("f:user_patch", 0).first;
  if(!o.patches.empty())
  {
    std::ifstream in(o.patches);
    std::vector<long> ids;
    long id = 0;
    while(in >> id)
      ids.push_back(id);
    // One id per face of the file: a triangulated polygon's triangles take its id.
    if(!in.eof() || ids.size() != repaired.file_faces
       || std::any_of(ids.begin(), ids.end(), [](long i) { return i < 0; }))
    {
      std::cerr << "remesh_conformal: cannot read '" << o.patches << "': expected " << repaired.file_faces
                << " non-negative integer patch ids (one per face), found " << ids.size()
                << (in.eof() ? "" : " before a non-integer") << "\n";
      return 2;
    }
    for(Mesh::Face_index f : input.faces())
      patch_of[f] = std::size_t(ids[repaired.file_face[f.idx()]]);
  }
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(input);
  const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin())
                                    + CGAL::square(box.zmax() - box.zmin()));
  const double target = o.target > 0. ? o.target : o.relative * diagonal;
  const double surface_distance = o.surface_distance >= 0. ? o.surface_distance : o.relative_surface_distance * target;
  const auto np = CR::parameters::maximum_surface_distance(surface_distance, CR::parameters::frontal_insertion(o.frontal, CR::parameters::maximum_chord_error(o.chord_error, CR::parameters::optimization_rounds(o.optimization_rounds, CR::parameters::lloyd_iterations(o.lloyd_iterations, CR::parameters::target_edge_length(
    target, CR::parameters::minimum_angle(
              o.min_angle, CR::parameters::crease_angle(o.crease_angle, CR::parameters::features_angle(
                             o.features_angle, CR::parameters::cut_planes(
                                                 o.planes, CR::parameters::features_fallback(
                                                             !o.features_angle_given, CR::parameters::progress(progress, CGAL::parameters::face_patch_map(patch_of)))))))))))));

  Mesh output;
  CR::Remeshing_report report;
  CR::Remeshing_statistics statistics;
  try
  {
    progress("remeshing " + std::to_string(input.number_of_faces()) + " faces");
    // --save-patches: the patches that the meshing stage meshes, numbered across batches. Without
    // it, no visitor (an empty function), so that the library keeps only what the meshing reads
    // of each patch as soon as it is flattened.
    std::size_t saved_patches = 0;
    std::function<void(const CR::Extracted_patch&, const CR::Conformal_flattening&)> save_patch;
    if(!o.save_patches.empty())
      save_patch = [&](const CR::Extracted_patch& patch, const CR::Conformal_flattening& flattening) {
        if(saved_patches == 0)
          progress("saving the patches to " + o.save_patches);
        const std::string name = o.save_patches + "/patch_" + std::to_string(saved_patches++);
        tools::write_file_atomically_at(name + ".off", [&](const std::string& temporary) {
          return CGAL::IO::write_polygon_mesh(temporary, patch.mesh, CGAL::parameters::stream_precision(17));
        });
        tools::write_file_atomically(name + "_flattening.svg", tools::welded_domain_svg(flattening));
      };
    const auto limited = CR::parameters::flattened_patch_visitor(save_patch, CR::parameters::patch_job_runner(runner, CR::parameters::repair_input(
      o.repair, CR::parameters::statistics(std::ref(statistics), CR::parameters::batch_faces(
                                             std::size_t(o.batch_faces), CR::parameters::maximum_running_time(remaining_time(), np))))));
    report = o.sequential ? CR::remesh_conformal<CGAL::Sequential_tag>(input, output, limited)
                          : CR::remesh_conformal<CGAL::Parallel_if_available_tag>(input, output, limited);
  }
  catch(const CR::Error& e)
  {
    if(e.code() == CR::Error_code::TIME_LIMIT_EXCEEDED)
      return out_of_time(e.what());
    std::cerr << tool_message(e.what()) << "\n";
    return 1;
  }
  catch(const std::exception& e) // a patch that --save-patches could not write
  {
    std::cerr << tool_message(e.what()) << "\n";
    return 2;
  }
  // What the remeshing took, before the measures (which on a large input can take longer).
  const double seconds_remeshed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double peak_mb_remeshed = peak_resident_megabytes();
  progress(o.fidelity ? "measuring quality and fidelity" : "measuring quality");
  const CR::Mesh_quality_report before = CR::mesh_quality(input), after = CR::mesh_quality(output);
  const CR::Sharp_corner_angles small_angles =
    CR::angles_at_sharp_corners(output, input, 25., CR::parameters::features_angle(o.features_angle));
  CR::Reference_comparison fidelity;
  if(o.fidelity)
    fidelity = CR::compare_to_reference(output, input);
  else
    fidelity.self_intersects = CR::internal::has_crossing_faces<CGAL::Parallel_if_available_tag>(output);
  CR::Face_deviations deviations;
  if(!o.deviation_map.empty())
  {
    progress("measuring the distance of every face to the other surface");
    deviations = CR::face_deviations(output, input);
  }

  try
  {
    tools::write_file_atomically_at(o.output, [&](const std::string& temporary) {
      return CGAL::IO::write_polygon_mesh(temporary, output, CGAL::parameters::stream_precision(17));
    });
    if(!o.report.empty())
    {
      tools::Json_writer json;
      json.begin_object().field("input", o.input).field("output", o.output).field("target_edge_length", report.target_edge_length);
      // The options the output depends on, to rerun it (the sequential or parallel run gives the same).
      json.key("parameters").begin_object().field("min_angle", o.min_angle).field("features_angle", o.features_angle).field("crease_angle", o.crease_angle)
          .field("optimization_rounds", o.optimization_rounds).field("lloyd_iterations", o.lloyd_iterations)
          .field("chord_error", o.chord_error).field("surface_distance", report.surface_distance_bound).field("cut_planes", o.planes.size()).field("patches", o.patches)
          .field("repair", o.repair).field("frontal_insertion", o.frontal).field("batch_faces", std::size_t(o.batch_faces)).end_object();
      json.key("input_repairs").begin_object().field("triangulated_polygons", repaired.triangulated_polygons)
          .field("triangles_from_polygons", repaired.triangles_from_polygons).field("reoriented_faces", repaired.reoriented_faces)
          .field("removed_isolated_vertices", repaired.removed_isolated_vertices)
          .field("stitched_vertices", repaired.stitched_vertices).field("split_non_manifold_vertices", repaired.split_vertices
                                                                                           + report.input.split_non_manifold_vertices)
          .field("removed_degenerate_faces", report.input.removed_degenerate_faces)
          .field("coincident_vertices", report.input.coincident_vertices)
          .field("coincident_example", report.input.coincident_example)
          .field("non_manifold_example", report.input.non_manifold_example)
          .field("degenerate_example", report.input.degenerate_example)
          .field("input_crosses_itself", report.input_crosses_itself).end_object();
      json.key("seconds").begin_object().field("segmentation", statistics.seconds_segmentation)
          .field("flattening", statistics.seconds_flattening).field("meshing_and_pull_back", statistics.seconds_meshing_stage)
          .field("gluing", statistics.seconds_gluing).field("proximity", statistics.seconds_proximity)
          .field("surface_distance", statistics.seconds_surface_distance)
          .field("ricci_flow_thread_seconds", statistics.seconds_ricci_flow)
          .field("planar_meshing_thread_seconds", statistics.seconds_planar_meshing)
          .field("optimization_thread_seconds", statistics.seconds_optimization)
          .field("pull_back_thread_seconds", statistics.seconds_pull_back);
      // The flattening's steps summed over the patches (see Flattening_report), in thread seconds;
      // the flow's are the statistics' own sum.
      double welding = 0., refinement = 0., flips = 0., factorization = 0., solve = 0., line_search = 0., layout = 0.,
             check = 0.;
      for(const CR::Flattening_report& r : statistics.patches)
      {
        welding += r.seconds_welding, refinement += r.seconds_refinement;
        flips += r.seconds_flips, factorization += r.seconds_factorization, solve += r.seconds_solve;
        line_search += r.seconds_line_search, layout += r.seconds_layout, check += r.seconds_check;
      }
      json.key("flattening_step_thread_seconds").begin_object().field("welding", welding).field("refinement", refinement)
          .field("flow", statistics.seconds_ricci_flow).field("flow_flips", flips).field("flow_factorization", factorization)
          .field("flow_solve", solve).field("flow_line_search", line_search).field("layout", layout)
          .field("embedding_check", check).end_object();
      json.key("meshing_phase_thread_seconds").begin_object();
      CR::Meshing_phase_seconds::for_each_phase(
        [&](const char* name, double CR::Meshing_phase_seconds::*phase) { json.field(name, statistics.meshing_phases.*phase); });
      json.end_object().end_object();
      json.key("segmentation").begin_object().field("patches", report.number_of_patches)
          .field("features_dropped", report.features_dropped).field("features_fallback_reason", report.features_fallback_reason)
          .field("plane_cuts", report.plane_cuts).field("patch_bisections", report.patch_bisections)
          .field("feature_edges", report.feature_edges).field("dangling_feature_edges", report.dangling_feature_edges)
          .field("narrow_strip_feature_edges", report.narrow_strip_feature_edges)
          .field("boundary_curves", statistics.boundary_curves).field("refined_boundary_curves", report.refined_boundary_curves)
          .field("split_diagonals", report.split_diagonals).field("component_batches", report.component_batches)
          .field("merged_batches", report.merged_batches).end_object();
      // Where sheets of the input come within a target length of each other (measured with a
      // chord error; smallest_gap null: nowhere or not measured).
      json.key("proximity").begin_object().field("measured", !std::isnan(report.smallest_gap))
          .field("smallest_gap", report.smallest_gap);
      json.key("smallest_gap_point").begin_array();
      for(double c : report.smallest_gap_point)
        json.value(std::isfinite(report.smallest_gap) ? c : std::numeric_limits<double>::quiet_NaN());
      json.end_array().field("gap_bounded_vertices", report.gap_bounded_vertices).end_object();
      // The surface-distance bound and what its check found on the output (0 and none: no bound).
      json.key("surface_distance").begin_object().field("bound", report.surface_distance_bound)
          .field("refinements", report.surface_distance_refinements).field("places", report.places_beyond_surface_distance)
          .field("rounds_dropped", report.surface_distance_rounds_dropped)
          .field("largest", report.largest_surface_distance);
      json_point(json.key("largest_point"), report.largest_surface_distance_point)
          .field("output_faces_beyond", report.output_faces_beyond_surface_distance)
          .field("input_vertices_beyond", report.input_vertices_beyond_surface_distance)
          .field("input_edges_beyond", report.input_edges_beyond_surface_distance)
          .field("input_faces_beyond", report.input_faces_beyond_surface_distance);
      // Where the output still strays (at most Remeshing_report::max_reported_places of them).
      json.key("places_still_beyond").begin_array();
      for(const std::array<double, 3>& place : report.places_still_beyond_surface_distance)
        json_point(json, place);
      json.end_array().end_object();
      json.key("frontal_insertion").begin_object().field("dropped", report.frontal_dropped)
          .field("fallback_reason", report.frontal_fallback_reason).end_object();
      json.key("flattening").begin_object().field("max_iterations", statistics.max_newton_iterations)
          .field("max_curvature_error", statistics.max_curvature_error).field("flips", statistics.flips)
          .field("retriangulated_faces", statistics.retriangulated_faces).field("max_scale_ratio", statistics.max_scale_ratio).end_object();
      json.field("boundary_samples", statistics.boundary_samples).field("clamped_vertices", statistics.clamped_vertices)
          .field("optimization_flips", statistics.optimization_flips).field("optimization_splits", statistics.optimization_splits)
          .field("optimization_chord_splits", statistics.optimization_chord_splits)
          .field("optimization_collapses", statistics.optimization_collapses).field("flips_after_gluing", statistics.flips_after_gluing)
          .field("collapses_after_gluing", statistics.collapses_after_gluing)
          .field("moves_after_gluing", statistics.moves_after_gluing)
          .field("patch_jobs_run", statistics.patch_jobs_run).field("patch_jobs_kept", statistics.patch_jobs_kept)
          .field("self_intersection_refinements", report.self_intersection_refinements);
      // Each patch job's seconds, for a scheduler over processes (the car benchmark replays them).
      json.key("patch_job_seconds").begin_array();
      for(double seconds : statistics.patch_job_seconds)
        json.value(seconds);
      json.end_array();
      json.field("peak_resident_mb", peak_resident_megabytes());
      // From the start of the tool to the output remeshed, before the measures and the writing.
      json.field("seconds_until_remeshed", seconds_remeshed).field("peak_resident_mb_until_remeshed", peak_mb_remeshed);
      json.key("peak_resident_mb_after").begin_object().field("segmentation", statistics.peak_resident_mb_segmentation)
          .field("flattening", statistics.peak_resident_mb_flattening).field("meshing", statistics.peak_resident_mb_meshing)
          .field("gluing", statistics.peak_resident_mb_gluing).end_object();
      json.key("input_quality");
      tools::write_json(json, before);
      json.key("output_quality");
      tools::write_json(json, after);
      json.key("output_angles_at_sharp_input_corners");
      tools::write_json(json, small_angles);
      json.field("output_self_intersects", fidelity.self_intersects);
      json.key("fidelity");
      if(o.fidelity)
        tools::write_json(json, fidelity);
      else
        json.value(std::numeric_limits<double>::quiet_NaN()); // null: not measured
      if(!o.deviation_map.empty())
      {
        // Largest distance per face, in target lengths, and its histogram.
        json.key("deviation").begin_object().key("output_faces_to_input");
        tools::write_deviation_json(json, deviations.of_mesh_faces, report.target_edge_length);
        json.key("input_faces_to_output");
        tools::write_deviation_json(json, deviations.of_reference_faces, report.target_edge_length);
        json.end_object();
      }
      json.end_object();
      tools::write_file_atomically(o.report, json.str());
    }
    if(!o.deviation_map.empty())
      tools::write_deviation_maps(o.deviation_map, output, input, deviations, report.target_edge_length);
    if(!o.plots.empty())
      tools::write_file_atomically(o.plots + "/quality.svg",
                                   tools::quality_histograms_svg({{"input: " + o.input, before}, {"remeshed: " + o.output, after}},
                                                                 "Mesh quality before and after conformal remeshing"));
  }
  catch(const std::exception& e)
  {
    std::cerr << tool_message(e.what()) << "\n";
    return 2;
  }

  const auto hausdorff_text = [](const CR::Reference_comparison& f) {
    std::ostringstream text;
    text << f.relative_distance_to_reference << " / " << f.relative_distance_from_reference << " x diagonal";
    return text.str();
  };
  std::cout << o.output << ": " << output.number_of_vertices() << " vertices, " << output.number_of_faces()
            << " faces (target edge length " << report.target_edge_length << ")\n"
            << "  minimum angle " << after.minimum_angle.min << " deg (input " << before.minimum_angle.min << "), "
            << 100. * after.share_with_minimum_angle_below(25.) << "% of triangles below 25 deg ("
            << 100. * small_angles.share_below_away_from_sharp_corners() << "% away from "
            << small_angles.sharp_corners << " input corners sharper than that), mean skewness "
            << after.skewness.mean << " (input " << before.skewness.mean << ")\n"
            << "  Hausdorff distance to / from the input: "
            << (o.fidelity ? hausdorff_text(fidelity) : std::string("not measured (--no-fidelity)"))
            << "; self-intersections: "
            << (fidelity.self_intersects ? (report.input_crosses_itself ? "YES (the input crosses itself too)" : "YES") : "none")
            << "\n"
            << "  " << report.number_of_patches << " patches (" << report.plane_cuts << " plane cuts, "
            << report.feature_edges << " feature edges" << (report.features_dropped ? ", dropped: no flattening with them" : "")
            << (report.narrow_strip_feature_edges > 0
                  ? ", " + std::to_string(report.narrow_strip_feature_edges) + " sharp edges of narrow strips left out"
                  : std::string())
            << "); seconds: segmentation " << statistics.seconds_segmentation
            << ", flattening " << statistics.seconds_flattening << ", meshing and pull-back " << statistics.seconds_meshing_stage
            << ", gluing " << statistics.seconds_gluing << "\n";
  if(!o.deviation_map.empty())
    std::cout << "  distance of the output's faces to the input, in target lengths: "
              << tools::deviation_histogram_line(deviations.of_mesh_faces, report.target_edge_length)
              << "\n  distance of the input's faces to the output: "
              << tools::deviation_histogram_line(deviations.of_reference_faces, report.target_edge_length) << "\n";
  if(report.surface_distance_bound > 0.)
    std::cout << "  surface distance bound " << report.surface_distance_bound << ": " << report.surface_distance_refinements
              << " rounds of meshing again near " << report.places_beyond_surface_distance << " places"
              << (report.surface_distance_rounds_dropped > 0
                    ? " (" + std::to_string(report.surface_distance_rounds_dropped) + " more dropped: their output intersected itself or was no closer)"
                    : std::string())
              << "; largest distance found " << report.largest_surface_distance << " at " << point_text(report.largest_surface_distance_point)
              << ", still beyond the bound: " << report.output_faces_beyond_surface_distance
              << " output faces, " << report.input_vertices_beyond_surface_distance << " input vertices, "
              << report.input_edges_beyond_surface_distance << " input edges, " << report.input_faces_beyond_surface_distance
              << " input faces"
              << (report.places_still_beyond_surface_distance.empty()
                    ? std::string()
                    : " (e.g. near " + point_text(report.places_still_beyond_surface_distance.front()) + "; --report lists "
                        + std::to_string(report.places_still_beyond_surface_distance.size()) + " places)")
              << "\n";
  if(std::isfinite(report.smallest_gap))
    std::cout << "  sheets of the input " << report.smallest_gap << " apart at " << point_text(report.smallest_gap_point)
              << "; the gaps shortened the target at "
              << report.gap_bounded_vertices << " input vertices\n";
  return 0;
}

} // namespace remesh_conformal_tool

/// The tool remesh_conformal on the command line `argc`, `argv`; returns its exit code. The
/// patch jobs run in this process's threads, or by `runner` when it is set (remesh_conformal_mpi).
/// Running out of memory anywhere is exit code 2 with a message, nothing written.
inline int remesh_conformal_main(int argc, char** argv,
                                 const CGAL::Conformal_remeshing::internal::remeshing::Patch_job_runner& runner = {})
{
  try
  {
    return remesh_conformal_tool::run(argc, argv, runner);
  }
  catch(const std::exception& e)
  {
    std::cerr << remesh_conformal_tool::tool_message(e.what()) << "; no output written\n";
  }
  return 2;
}

} // namespace Conformal_remeshing_tools

#endif // CONFORMAL_REMESHING_TOOLS_REMESH_CONFORMAL_TOOL_H
