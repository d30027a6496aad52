// welding_parameters: how the annulus' inner radius delta affects the welded flattening, to
// choose its default on evidence. For each model and delta: Newton iterations, flips, seconds
// of the flow (median of 3 runs), the range of the map's local scale on the patch, and the
// result of the exact embedding check. Then the peer: CGAL's LSCM parameterizer on the same
// models, its time and its overlaps (exact predicates) beside the welded flattening's.
// Prints tables and writes JSON.
//
//   welding_parameters OUT.json [MESH ...]     (default models: generated ones only)

#include <CGAL/Conformal_remeshing/IO/read_mesh.h>
#include <CGAL/Conformal_remeshing/conformal_flatten.h>

#include "cad_like_models.h"
#include "test_surfaces.h"
#include "generated_patches.h"
#include "timing.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/LSCM_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <chrono>

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

namespace CR = CGAL::Conformal_remeshing;
namespace bm = CGAL::Conformal_remeshing::benchmarks;
typedef CGAL::Surface_mesh<CGAL::Epick::Point_3> Mesh;

int main(int argc, char** argv)
{
  if(argc < 2)
  {
    std::cerr << "usage: welding_parameters OUT.json [MESH ...]\n";
    return 2;
  }
  std::vector<std::pair<std::string, Mesh> > models = bm::generated_patches<Mesh>(false);
  for(int i = 2; i < argc; ++i)
  {
    Mesh mesh;
    try
    {
      if(!CR::read_and_check_mesh(argv[i], mesh).is_valid())
      {
        std::cerr << "welding_parameters: skipping invalid mesh " << argv[i] << "\n";
        continue;
      }
    }
    catch(const std::exception& e)
    {
      std::cerr << "welding_parameters: " << e.what() << "\n";
      return 2;
    }
    const std::string name = argv[i];
    models.emplace_back(name.substr(name.find_last_of('/') + 1), mesh);
  }

  std::ofstream json(argv[1]);
  json << "[\n";
  std::cout << std::left << std::setw(24) << "model" << std::right << std::setw(7) << "delta" << std::setw(7) << "iter"
            << std::setw(8) << "flips" << std::setw(10) << "flow s" << std::setw(12) << "min scale" << std::setw(12)
            << "max scale" << std::setw(10) << "ratio" << "  embedding\n";
  bool first = true;
  for(const auto& model : models)
    for(double delta : {0.2, 0.35, 0.5, 0.65, 0.8})
    {
      std::vector<double> seconds;
      CR::Conformal_flattening f;
      for(int run = 0; run < 3; ++run)
      {
        f = CR::conformal_flatten(model.second, CR::parameters::annulus_inner_radius(delta));
        seconds.push_back(f.report.seconds_flow);
      }
      std::sort(seconds.begin(), seconds.end());
      const CR::Flattening_report& r = f.report;
      std::cout << std::left << std::setw(24) << model.first << std::right << std::setw(7) << delta << std::setw(7)
                << r.iterations << std::setw(8) << r.flips << std::setw(10) << std::setprecision(3) << seconds[1]
                << std::setw(12) << r.min_scale << std::setw(12) << r.max_scale << std::setw(10) << r.max_scale / r.min_scale
                << "  " << r.embedding.summary() << "\n";
      json << (first ? "" : ",\n") << "  {\"model\": \"" << model.first << "\", \"delta\": " << delta
           << ", \"iterations\": " << r.iterations << ", \"flips\": " << r.flips << ", \"median_flow_seconds\": " << seconds[1]
           << ", \"min_scale\": " << r.min_scale << ", \"max_scale\": " << r.max_scale
           << ", \"embedding\": " << (r.embedding.is_embedding() ? "true" : "false") << "}";
      first = false;
    }
  json << "\n]\n";

  // The peer, in the same run: CGAL's LSCM against the welded flattening (default delta).
  namespace SMP = CGAL::Surface_mesh_parameterization;
  std::cout << "\n" << std::left << std::setw(24) << "model" << std::right << std::setw(11) << "welded s" << std::setw(11)
            << "LSCM s" << std::setw(9) << "ratio" << std::setw(22) << "welded overlaps" << std::setw(20) << "LSCM overlaps" << "\n";
  for(auto& model : models)
  {
    Mesh mesh = model.second;
    CR::Conformal_flattening f;
    const double welded_seconds = bm::median_seconds([&] { f = CR::conformal_flatten(mesh); });
    auto uv = mesh.add_property_map<Mesh::Vertex_index, CGAL::Epick::Point_2>("v:uv").first;
    const auto border = CGAL::Polygon_mesh_processing::longest_border(mesh).first;
    SMP::Error_code lscm_status = SMP::OK;
    const double lscm_seconds = bm::median_seconds([&] { lscm_status = SMP::parameterize(mesh, SMP::LSCM_parameterizer_3<Mesh>(), border, uv); });
    std::vector<std::array<std::size_t, 3> > triangles;
    for(const auto& t : f.triangles)
      triangles.push_back({{std::size_t(t[0]), std::size_t(t[1]), std::size_t(t[2])}});
    const CR::Planar_embedding_report welded = CR::check_planar_embedding(f.layout, triangles, {}, true);
    const CR::Planar_embedding_report lscm = CR::check_parameterization(mesh, uv, true);
    std::cout << std::left << std::setw(24) << model.first << std::right << std::setw(11) << std::setprecision(3)
              << welded_seconds << std::setw(11) << lscm_seconds << std::setw(9) << welded_seconds / lscm_seconds
              << std::setw(22) << welded.overlapping_face_pairs + welded.non_positive_faces << std::setw(20)
              << (lscm_status == SMP::OK ? std::to_string(lscm.overlapping_face_pairs + lscm.non_positive_faces) : std::string("failed"))
              << "\n";
  }
  std::cout << "(overlaps: overlapping triangle pairs plus folded triangles, exact predicates; ratio: welded / LSCM time)\n";
  return 0;
}
