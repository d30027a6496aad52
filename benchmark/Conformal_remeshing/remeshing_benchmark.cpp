// remeshing_benchmark: remesh_conformal() against CGAL's isotropic_remeshing() at the same target
// edge length (1% of the bounding-box diagonal by default), in the same run, on generated patches
// and on any mesh files given. For each: times (median of 3 runs), output size, minimum angle,
// share of triangles below 25 degrees, mean equiangle skewness, share of edges within
// [0.7, 1.4] x target, Hausdorff distance both ways relative to the diagonal, self-intersection.
// Prints a table and writes JSON.
//
//   remeshing_benchmark OUT.json [--relative R] [MESH ...]

#include <CGAL/Conformal_remeshing/IO/read_mesh.h>
#include <CGAL/Conformal_remeshing/mesh_quality.h>
#include <CGAL/remesh_conformal.h>

#include "cad_like_models.h"
#include "test_surfaces.h"
#include "generated_patches.h"
#include "isotropic_peer.h"
#include "json_writer.h"
#include "timing.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

namespace CR = CGAL::Conformal_remeshing;
namespace bm = CGAL::Conformal_remeshing::benchmarks;
typedef CGAL::Epick K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

namespace {

struct Measure
{
  double seconds = 0.;
  std::size_t vertices = 0;
  double min_angle = 0., below_25 = 0., skewness = 0., edges_in_range = 0., hausdorff_to = 0., hausdorff_from = 0.;
  bool self_intersects = false;
};

Measure measure(const Mesh& input, const Mesh& output, double h, double seconds)
{
  Measure m;
  m.seconds = seconds;
  m.vertices = output.number_of_vertices();
  const CR::Mesh_quality_report q = CR::mesh_quality(output);
  m.min_angle = q.minimum_angle.min;
  m.below_25 = q.share_with_minimum_angle_below(25.);
  m.skewness = q.skewness.mean;
  m.edges_in_range = CR::share_of_edges_with_length_in(output, 0.7 * h, 1.4 * h);
  const CR::Reference_comparison c = CR::compare_to_reference(output, input);
  m.hausdorff_to = c.relative_distance_to_reference;
  m.hausdorff_from = c.relative_distance_from_reference;
  m.self_intersects = c.self_intersects;
  return m;
}

void print_row(const std::string& model, const std::string& method, const Measure& m)
{
  std::cout << std::left << std::setw(22) << model << std::setw(12) << method << std::right << std::setprecision(3)
            << std::setw(8) << m.seconds << std::setw(8) << m.vertices << std::setw(8) << m.min_angle << std::setw(8)
            << 100. * m.below_25 << std::setw(8) << m.skewness << std::setw(8) << 100. * m.edges_in_range << std::setw(10)
            << m.hausdorff_to << std::setw(10) << m.hausdorff_from << std::setw(6) << (m.self_intersects ? "yes" : "no") << "\n";
}

void write_json(std::ostream& out, const Measure& m)
{
  out << "{\"median_seconds\": " << m.seconds << ", \"vertices\": " << m.vertices << ", \"min_angle\": " << m.min_angle
      << ", \"share_below_25\": " << m.below_25 << ", \"mean_skewness\": " << m.skewness
      << ", \"edges_in_range\": " << m.edges_in_range << ", \"hausdorff_to_input\": " << m.hausdorff_to
      << ", \"hausdorff_from_input\": " << m.hausdorff_from << ", \"self_intersects\": " << (m.self_intersects ? "true" : "false") << "}";
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 2)
  {
    std::cerr << "usage: remeshing_benchmark OUT.json [--relative R] [MESH ...]\n";
    return 2;
  }
  double relative = 0.01;
  std::vector<std::pair<std::string, Mesh> > models = bm::generated_patches<Mesh>(true);
  for(int i = 2; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if(arg == "--relative" && i + 1 < argc)
    {
      relative = std::stod(argv[++i]);
      continue;
    }
    Mesh mesh;
    try
    {
      if(!CR::read_and_check_mesh(arg, mesh).is_valid())
      {
        std::cerr << "remeshing_benchmark: invalid mesh " << arg << "\n";
        return 1;
      }
    }
    catch(const std::exception& e)
    {
      std::cerr << "remeshing_benchmark: " << e.what() << "\n";
      return 2;
    }
    models.emplace_back(arg.substr(arg.find_last_of('/') + 1), mesh);
  }

  std::ofstream json(argv[1]);
  json << "[\n";
  std::cout << std::left << std::setw(22) << "model" << std::setw(12) << "method" << std::right << std::setw(8) << "sec"
            << std::setw(8) << "verts" << std::setw(8) << "minang" << std::setw(8) << "%<25" << std::setw(8) << "skew"
            << std::setw(8) << "%edges" << std::setw(10) << "H to" << std::setw(10) << "H from" << std::setw(6) << "self" << "\n";
  std::size_t failures = 0;
  for(std::size_t k = 0; k < models.size(); ++k)
  {
    const Mesh& input = models[k].second;
    Mesh ours;
    CR::Remeshing_report report;
    double ours_seconds = 0.;
    try
    {
      ours_seconds = bm::median_seconds([&] {
        report = CR::remesh_conformal(input, ours, CR::parameters::relative_target_edge_length(relative));
      });
    }
    catch(const CR::Error& e)
    {
      // A model the remesher refuses is a result too: recorded, and the run goes on.
      ++failures;
      std::cout << std::left << std::setw(22) << models[k].first << std::setw(12) << "conformal" << "FAILED: " << e.what() << "\n";
      Conformal_remeshing_tools::Json_writer record; // escapes the message
      record.begin_object().field("model", models[k].first).field("failed", std::string(e.what())).end_object();
      std::string text = record.str();
      text.pop_back(); // its final newline
      json << (k ? ",\n" : "") << "  " << text;
      continue;
    }
    const double h = report.target_edge_length;
    Mesh peer;
    const double peer_seconds = bm::median_seconds([&] {
      peer = input;
      bm::run_isotropic_peer(peer, h);
    });
    const Measure a = measure(input, ours, h, ours_seconds), b = measure(input, peer, h, peer_seconds);
    print_row(models[k].first, "conformal", a);
    print_row("", "isotropic", b);
    std::cout << std::left << std::setw(22) << "" << std::setw(12) << "ratio" << std::right << std::setw(8)
              << std::setprecision(3) << a.seconds / b.seconds << std::setw(8) << "" << std::setw(8) << a.min_angle / b.min_angle
              << std::setw(8) << "" << std::setw(8) << a.skewness / b.skewness << std::setw(8) << "" << std::setw(10)
              << a.hausdorff_to / b.hausdorff_to << std::setw(10) << a.hausdorff_from / b.hausdorff_from << "\n";
    json << (k ? ",\n" : "") << "  {\"model\": \"" << models[k].first << "\", \"target_edge_length\": " << h
         << ", \"patches\": " << report.number_of_patches << ", \"stage_seconds\": {\"segmentation\": "
         << report.seconds_segmentation << ", \"flattening\": " << report.seconds_flattening
         << ", \"meshing_and_pull_back\": " << report.seconds_meshing_stage << ", \"gluing\": " << report.seconds_gluing
         << ", \"planar_meshing_thread_seconds\": " << report.seconds_planar_meshing
         << ", \"optimization_thread_seconds\": " << report.seconds_optimization
         << ", \"pull_back_thread_seconds\": " << report.seconds_pull_back << "}, \"conformal\": ";
    write_json(json, a);
    json << ", \"isotropic\": ";
    write_json(json, b);
    json << "}";
  }
  json << "\n]\n";
  std::cout << "(sec: median of 3 runs; %edges: edges within [0.7, 1.4] x target; H: Hausdorff distance to and from "
               "the input over its diagonal; ratio: conformal / isotropic)\n";
  return failures == 0 ? 0 : 1;
}
