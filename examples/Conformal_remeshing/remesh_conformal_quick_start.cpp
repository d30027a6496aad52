// Quick start: reads a surface mesh, checks it, remeshes it by conformal flattening and compares
// the quality before and after.
//
// Usage: remesh_conformal_quick_start [input_mesh [output.off]]
// (default input: data/perforated_plate.off, a CAD-like plate of genus 7).

#include <CGAL/Conformal_remeshing/IO/read_mesh.h>
#include <CGAL/Conformal_remeshing/mesh_quality.h>
#include <CGAL/remesh_conformal.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <iostream>
#include <string>

#ifndef CONFORMAL_REMESHING_EXAMPLE_DATA // set by CMake to the source directory's data/
#define CONFORMAL_REMESHING_EXAMPLE_DATA "data"
#endif

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace CR = CGAL::Conformal_remeshing;

int main(int argc, char** argv)
{
  const std::string input_file = argc > 1 ? argv[1] : CONFORMAL_REMESHING_EXAMPLE_DATA "/perforated_plate.off";
  const std::string output_file = argc > 2 ? argv[2] : "remeshed.off";

  Mesh mesh;
  const CR::Mesh_check_report checks = CR::read_and_check_mesh(input_file, mesh); // throws if unreadable
  if(!checks.is_valid())
  {
    std::cerr << "cannot remesh '" << input_file << "': " << checks.summary() << "\n";
    return 1;
  }
  const CR::Mesh_quality_report before = CR::mesh_quality(mesh);

  // In place, with edges of 2% of the bounding-box diagonal; throws CR::Error on failure.
  const CR::Remeshing_report report = CGAL::remesh_conformal(mesh, CR::parameters::relative_target_edge_length(0.02));

  const CR::Mesh_quality_report after = CR::mesh_quality(mesh);
  std::cout << report.number_of_patches << " patches, " << mesh.number_of_vertices() << " vertices\n"
            << "smallest angle: " << before.minimum_angle.min << " -> " << after.minimum_angle.min << " degrees\n"
            << "mean skewness:  " << before.skewness.mean << " -> " << after.skewness.mean << "\n";
  return CGAL::IO::write_polygon_mesh(output_file, mesh, CGAL::parameters::stream_precision(17)) ? 0 : 1;
}
