// Remeshes a surface twice with an edge length that varies over it (`CGAL::remesh_conformal()`,
// user manual section "Sizing"), each time into a separate output mesh:
//   (a) adaptive to curvature, `maximum_chord_error()`: shorter edges where the surface bends;
//   (b) a user field, `sizing_field()`: short edges near a corner of the bounding box, longer
//       with the distance from it.
// Sizes are in 3D units; the target edge length is the largest either may ask for.
//
// Usage: remesh_with_sizing [input_mesh [output_chord_error.off [output_sizing_field.off]]]
// (default input: data/perforated_plate.off, shipped with the examples). Exit code 1 on failure.

#include <CGAL/Conformal_remeshing/IO/read_mesh.h>
#include <CGAL/Conformal_remeshing/mesh_quality.h>
#include <CGAL/remesh_conformal.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#ifndef CONFORMAL_REMESHING_EXAMPLE_DATA // set by CMake to the source directory's data/
#define CONFORMAL_REMESHING_EXAMPLE_DATA "data"
#endif

typedef CGAL::Epick K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace CR = CGAL::Conformal_remeshing;
namespace PMP = CGAL::Polygon_mesh_processing;

// The mean edge length of the faces for which `in_region(face)` holds, over the target length.
template <typename Region>
double relative_edge_length(const Mesh& mesh, double target, const Region& in_region)
{
  double sum = 0.;
  std::size_t n = 0;
  for(Mesh::Face_index f : mesh.faces())
    if(in_region(f))
      for(Mesh::Halfedge_index h : mesh.halfedges_around_face(mesh.halfedge(f)))
      {
        sum += PMP::edge_length(h, mesh);
        ++n;
      }
  return n > 0 ? sum / double(n) / target : std::nan("");
}

template <typename Region1, typename Region2>
void print(const std::string& name, const Mesh& mesh, double target, const std::string& where1,
           const Region1& region1, const std::string& where2, const Region2& region2)
{
  std::cout << name << ": " << mesh.number_of_vertices() << " vertices, minimum angle "
            << CR::mesh_quality(mesh).minimum_angle.min << " deg; mean edge length / target: "
            << relative_edge_length(mesh, target, region1) << " " << where1 << ", "
            << relative_edge_length(mesh, target, region2) << " " << where2 << "\n";
}

int main(int argc, char** argv)
{
  const std::string input = argc > 1 ? argv[1] : CONFORMAL_REMESHING_EXAMPLE_DATA "/perforated_plate.off";
  const std::string output_a = argc > 2 ? argv[2] : "remeshed_chord_error.off";
  const std::string output_b = argc > 3 ? argv[3] : "remeshed_sizing_field.off";
  Mesh mesh, by_curvature, by_field;
  try
  {
    const CR::Mesh_check_report checks = CR::read_and_check_mesh(input, mesh);
    if(!checks.is_valid())
    {
      std::cerr << "Error: '" << input << "' cannot be remeshed: " << checks.summary() << "\n";
      return 1;
    }
    const CGAL::Bbox_3 box = PMP::bbox(mesh);
    const K::Point_3 corner(box.xmin(), box.ymin(), box.zmin());
    const double diagonal = std::sqrt(CGAL::squared_distance(corner, K::Point_3(box.xmax(), box.ymax(), box.zmax())));
    // Coarser than the default 1%, so that the finer parts stand out (and the example runs fast).
    const double target = 0.02 * diagonal;

    // (a) Chords may leave the surface by at most 1e-4 of the diagonal: edges near sqrt(8 E R)
    // where the radius of curvature is R (hole walls, fillets), never longer than the target.
    CR::remesh_conformal(mesh, by_curvature,
                         CR::parameters::maximum_chord_error(1e-4 * diagonal, CR::parameters::target_edge_length(target)));

    // (b) 1/8 of the target at the corner, growing linearly to the target at half the diagonal.
    // The library would raise sizes below 1/16 of the target and lower those above it anyway;
    // clamping here keeps the field meaningful on its own.
    const auto field = [&](const K::Point_3& p) {
      const double t = std::sqrt(CGAL::squared_distance(p, corner)) / (0.5 * diagonal);
      return target * (0.125 + 0.875 * (std::min)(1., t));
    };
    CR::remesh_conformal(mesh, by_field, CR::parameters::sizing_field(field, CR::parameters::target_edge_length(target)));

    // (a)'s output bends at a face whose normal turns by 0.5 to 30 degrees across one of its
    // edges (sharper turns are features, which the chord error leaves alone).
    const Mesh& a = by_curvature;
    std::vector<bool> curved(a.number_of_faces(), false);
    for(Mesh::Halfedge_index h : a.halfedges())
      if(!a.is_border(h) && !a.is_border(a.opposite(h)))
      {
        const double turn = CGAL::approximate_angle(PMP::compute_face_normal(a.face(h), a), PMP::compute_face_normal(a.face(a.opposite(h)), a));
        curved[a.face(h)] = curved[a.face(h)] || (turn > 0.5 && turn < 30.);
      }
    std::cout.precision(3);
    print("chord error", a, target, "on curved parts", [&](Mesh::Face_index f) { return bool(curved[f]); },
          "on flat parts", [&](Mesh::Face_index f) { return !curved[f]; });

    const auto distance_to_corner = [&](Mesh::Face_index f) {
      return std::sqrt(CGAL::squared_distance(by_field.point(by_field.target(by_field.halfedge(f))), corner));
    };
    print("sizing field", by_field, target, "near the corner", [&](Mesh::Face_index f) { return distance_to_corner(f) < 0.15 * diagonal; },
          "far from it", [&](Mesh::Face_index f) { return distance_to_corner(f) > 0.6 * diagonal; });
  }
  catch(const CR::Error& e) // unreadable file, or a surface that cannot be remeshed: the message says why
  {
    std::cerr << "Error: " << e.what() << "\n";
    return 1;
  }
  for(const auto& out : {std::make_pair(output_a, &by_curvature), std::make_pair(output_b, &by_field)})
    if(!CGAL::IO::write_polygon_mesh(out.first, *out.second, CGAL::parameters::stream_precision(17)))
    {
      std::cerr << "Error: cannot write '" << out.first << "'.\n";
      return 1;
    }
  std::cout << "wrote " << output_a << " and " << output_b << "\n";
  return 0;
}
