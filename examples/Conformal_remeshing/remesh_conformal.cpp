// remesh_conformal: remeshes a surface by conformal flattening (CGAL::remesh_conformal()).
//
//   remesh_conformal IN OUT [--target-edge-length L | --relative-edge-length R] [--min-angle DEG]
//                    [--report FILE.json] [--plots DIR] [--quiet]
//
// Progress goes to standard error; OUT is written completely or not at all. Exit codes: 0
// success, 1 the input cannot be remeshed (defects, unsupported topology, failed flattening),
// 2 the tool could not run (bad arguments, unreadable input, unwritable output).

#include "atomic_file.h"
#include "quality_plot_svg.h"
#include "report_json.h"

#include <CGAL/Conformal_remeshing/IO/read_mesh.h>
#include <CGAL/Conformal_remeshing/mesh_quality.h>
#include <CGAL/remesh_conformal.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Surface_mesh.h>

#include <chrono>
#include <iostream>
#include <string>

namespace CR = CGAL::Conformal_remeshing;
namespace tools = Conformal_remeshing_tools;
typedef CGAL::Epick K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

namespace {

const char* usage =
  "usage: remesh_conformal IN OUT [--target-edge-length L | --relative-edge-length R] [--min-angle DEG]\n"
  "                        [--report FILE.json] [--plots DIR] [--quiet]\n"
  "  IN, OUT                 mesh files (.off .obj .ply .stl); OUT is written atomically\n"
  "  --target-edge-length L  target edge length in the input's units\n"
  "  --relative-edge-length R  target edge length as a fraction of the bounding-box diagonal (default 0.01)\n"
  "  --min-angle DEG         minimum angle of the planar Delaunay refinement (default 28)\n"
  "  --report FILE.json      stage times, flattening report, quality of input and output, fidelity\n"
  "  --plots DIR             DIR/quality.svg: angle and skewness histograms, input and output\n"
  "  --quiet                 no progress messages\n"
  "Today the input must be a genus-0 patch with at least one boundary loop.\n"
  "exit code: 0 success, 1 the input cannot be remeshed, 2 the tool could not run\n";

struct Options
{
  std::string input, output, report, plots;
  double target = 0., relative = 0.01, min_angle = 28.;
  bool quiet = false;
};

bool parse(int argc, char** argv, Options& o)
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
    bool ok = true;
    if(arg == "--target-edge-length")
      ok = number(o.target) && o.target > 0.;
    else if(arg == "--relative-edge-length")
      ok = number(o.relative) && o.relative > 0.;
    else if(arg == "--min-angle")
      ok = number(o.min_angle);
    else if(arg == "--report" && i + 1 < argc)
      o.report = argv[++i];
    else if(arg == "--plots" && i + 1 < argc)
      o.plots = argv[++i];
    else if(arg == "--quiet")
      o.quiet = true;
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

} // namespace

int main(int argc, char** argv)
{
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

  Mesh input;
  try
  {
    progress("reading " + o.input);
    const CR::Mesh_check_report checks = CR::read_and_check_mesh(o.input, input);
    if(!checks.is_valid())
    {
      std::cerr << "remesh_conformal: invalid input '" << o.input << "': " << checks.summary() << "\n";
      return 1;
    }
  }
  catch(const std::exception& e)
  {
    std::cerr << "remesh_conformal: " << e.what() << "\n";
    return 2;
  }

  Mesh output;
  CR::Remeshing_report report;
  try
  {
    progress("flattening and remeshing " + std::to_string(input.number_of_faces()) + " faces");
    report = o.target > 0. ? CR::remesh_conformal(input, output, CR::parameters::target_edge_length(o.target, CR::parameters::minimum_angle(o.min_angle)))
                           : CR::remesh_conformal(input, output, CR::parameters::relative_target_edge_length(o.relative, CR::parameters::minimum_angle(o.min_angle)));
  }
  catch(const CR::Error& e)
  {
    std::cerr << "remesh_conformal: " << e.what() << "\n";
    return 1;
  }
  progress("measuring quality and fidelity");
  const CR::Mesh_quality_report before = CR::mesh_quality(input), after = CR::mesh_quality(output);
  const CR::Reference_comparison fidelity = CR::compare_to_reference(output, input);

  try
  {
    tools::write_file_atomically_at(o.output, [&](const std::string& temporary) {
      return CGAL::IO::write_polygon_mesh(temporary, output, CGAL::parameters::stream_precision(17));
    });
    if(!o.report.empty())
    {
      tools::Json_writer json;
      json.begin_object().field("input", o.input).field("output", o.output).field("target_edge_length", report.target_edge_length);
      json.key("seconds").begin_object().field("checks_and_flattening", report.seconds_checks_and_flattening)
          .field("ricci_flow", report.flattening.seconds_flow).field("planar_meshing", report.seconds_planar_meshing)
          .field("pull_back", report.seconds_pull_back).end_object();
      json.key("flattening").begin_object().field("iterations", report.flattening.iterations)
          .field("curvature_error", report.flattening.curvature_error).field("flips", report.flattening.flips)
          .field("min_scale", report.flattening.min_scale).field("max_scale", report.flattening.max_scale)
          .field("embedding", report.flattening.embedding.summary()).end_object();
      json.field("boundary_samples", report.boundary_samples).field("clamped_vertices", report.clamped_vertices);
      json.key("input_quality");
      tools::write_json(json, before);
      json.key("output_quality");
      tools::write_json(json, after);
      json.key("fidelity");
      tools::write_json(json, fidelity);
      json.end_object();
      tools::write_file_atomically(o.report, json.str());
    }
    if(!o.plots.empty())
      tools::write_file_atomically(o.plots + "/quality.svg",
                                   tools::quality_histograms_svg({{"input: " + o.input, before}, {"remeshed: " + o.output, after}},
                                                                 "Mesh quality before and after conformal remeshing"));
  }
  catch(const std::exception& e)
  {
    std::cerr << "remesh_conformal: " << e.what() << "\n";
    return 2;
  }

  std::cout << o.output << ": " << output.number_of_vertices() << " vertices, " << output.number_of_faces()
            << " faces (target edge length " << report.target_edge_length << ")\n"
            << "  minimum angle " << after.minimum_angle.min << " deg (input " << before.minimum_angle.min << "), "
            << 100. * after.share_with_minimum_angle_below(25.) << "% of triangles below 25 deg, mean skewness "
            << after.skewness.mean << " (input " << before.skewness.mean << ")\n"
            << "  Hausdorff distance to / from the input: " << fidelity.relative_distance_to_reference << " / "
            << fidelity.relative_distance_from_reference << " x diagonal; self-intersections: "
            << (fidelity.self_intersects ? "YES" : "none") << "\n"
            << "  seconds: flattening " << report.seconds_checks_and_flattening << ", planar meshing "
            << report.seconds_planar_meshing << ", pull-back " << report.seconds_pull_back << "\n";
  return 0;
}
