// Remeshes a surface with named parameters of both kinds, asks for the two optional outputs of
// `CGAL::remesh_conformal()` and checks the result with `verify_remesh()`:
//  - the package's parameters (`CGAL::Conformal_remeshing::parameters`, each taking the ones to
//    chain as its second argument) followed by CGAL's own `maximum_running_time`, chained as a
//    member as CGAL's parameters are;
//  - `vertex_locations`: the input face and barycentric coordinates of every output vertex,
//    which `verify_remesh()` then checks with exact predicates together with the topology, the
//    distance to the input and self-intersections;
//  - `statistics`: the timings and counters of the stages;
//  - `maximum_surface_distance`: a bound, here a tenth of the target edge length, on the distance
//    between the output and the input both ways; where the output strays farther, the surface
//    is meshed again there with shorter edges, and the report says how far it still is.
// It then measures the triangles below 25 degrees with `angles_at_sharp_corners()`, apart from
// those that a corner of the input narrower than that forces.
//
// Usage: remesh_and_verify [input_mesh [output.off]] (default input: data/perforated_plate.off).
// Exit code 0 when the output is verified, 1 when the input cannot be remeshed or the output
// fails a check, 3 when the time limit of 60 s is exceeded.

#include <CGAL/Conformal_remeshing/IO/read_mesh.h>
#include <CGAL/Conformal_remeshing/angles_at_sharp_corners.h>
#include <CGAL/Conformal_remeshing/verify_remesh.h>
#include <CGAL/remesh_conformal.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <cmath>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

#ifndef CONFORMAL_REMESHING_EXAMPLE_DATA // set by CMake to the source directory's data/
#define CONFORMAL_REMESHING_EXAMPLE_DATA "data"
#endif

typedef CGAL::Epick K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace CR = CGAL::Conformal_remeshing;

int main(int argc, char** argv)
{
  const std::string input_file = argc > 1 ? argv[1] : CONFORMAL_REMESHING_EXAMPLE_DATA "/perforated_plate.off";
  const std::string output_file = argc > 2 ? argv[2] : "remeshed.off";
  Mesh input, output;
  std::vector<CR::Surface_location> locations;
  CR::Remeshing_statistics statistics;
  try
  {
    const CR::Mesh_check_report checks = CR::read_and_check_mesh(input_file, input);
    if(!checks.is_valid())
    {
      std::cerr << "Error: '" << input_file << "' cannot be remeshed: " << checks.summary() << "\n";
      return 1;
    }
    const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(input);
    const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin())
                                      + CGAL::square(box.zmax() - box.zmin()));
    const double target = 0.02 * diagonal;
    const CR::Remeshing_report report = CR::remesh_conformal(
      input, output,
      CR::parameters::target_edge_length(
        target, CR::parameters::maximum_surface_distance(
                  0.1 * target, CR::parameters::vertex_locations(std::ref(locations), CR::parameters::statistics(std::ref(statistics)))))
        .maximum_running_time(60.)); // CGAL's parameters chain as members
    std::cout << "remeshed into " << report.output_vertices << " vertices and " << report.output_faces << " faces, "
              << report.number_of_patches << " patches; target edge length " << report.target_edge_length << "\n"
              << "stages: segmentation " << statistics.seconds_segmentation << " s, flattening " << statistics.seconds_flattening
              << " s, meshing " << statistics.seconds_meshing_stage << " s, gluing " << statistics.seconds_gluing << " s\n"
              << "surface distance: at most " << report.largest_surface_distance << " found (bound "
              << report.surface_distance_bound << ", " << report.surface_distance_refinements << " rounds of meshing again near "
              << report.places_beyond_surface_distance << " places); still beyond it: "
              << report.output_faces_beyond_surface_distance + report.input_vertices_beyond_surface_distance
                   + report.input_edges_beyond_surface_distance + report.input_faces_beyond_surface_distance
              << " elements\n";
  }
  catch(const CR::Error& e)
  {
    std::cerr << "Error: " << e.what() << "\n";
    return e.code() == CR::Error_code::TIME_LIMIT_EXCEEDED ? 3 : 1;
  }

  const CR::Remesh_verification verification =
    CR::verify_remesh(input, output, CR::parameters::vertex_locations(std::cref(locations)));
  std::cout << "verification: " << verification.summary() << "\n";
  if(!verification.is_valid())
    return 1;
  const CR::Sharp_corner_angles small_angles = CR::angles_at_sharp_corners(output, input, 25.);
  std::cout << "triangles below 25 degrees: " << small_angles.triangles_below << " of " << small_angles.triangles << ", "
            << small_angles.triangles_below_at_sharp_corners << " of them at the input's " << small_angles.sharp_corners
            << " corners sharper than that\n";
  if(!CGAL::IO::write_polygon_mesh(output_file, output, CGAL::parameters::stream_precision(17)))
  {
    std::cerr << "Error: cannot write '" << output_file << "'\n";
    return 1;
  }
  std::cout << "wrote " << output_file << "\n";
  return 0;
}
