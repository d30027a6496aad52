// Flattens a disc-topology triangle mesh with the dynamic discrete Ricci flow (paper Sec. 4.4:
// curvature 0 inside, 2 pi / n at each of the n boundary vertices) and writes the planar layout
// as an OBJ file with uv coordinates.
//
// Usage: ricci_flow input_mesh [output.obj]
//
// The OBJ has the input's 3D vertices (v), then the vertices the flow added by splitting
// boundary edges (their 3D points found through the correspondence with the input), their
// planar positions (vt, scaled to the unit box) and the faces of the final intrinsic Delaunay
// triangulation (f v/vt). Those faces are
// straight in the plane; the input's own faces are not (they map to curved polygons through
// the correspondence) and drawn straight in uv they could fold, which is why they are not used.

#include <CGAL/Conformal_remeshing/Error.h>
#include <CGAL/Conformal_remeshing/Intrinsic_triangulation.h>
#include <CGAL/Conformal_remeshing/discrete_ricci_flow.h>

#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Simple_cartesian<double> Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
namespace CR = CGAL::Conformal_remeshing;

static int usage(const char* program)
{
  std::cerr << "Usage: " << program << " input_mesh [output.obj]\n"
            << "  input_mesh: a triangle mesh of disc topology (OFF, OBJ, PLY, STL, ...)\n"
            << "  output.obj: the planar layout (default: ricci_flow_layout.obj)\n";
  return 2;
}

int main(int argc, char** argv)
{
  std::string input;
  if(argc >= 2)
    input = argv[1];
  else
  {
    const std::string fallback = CGAL::data_file_path("meshes/nefertiti.off");
    if(!std::ifstream(fallback))
      return usage(argv[0]);
    input = fallback;
  }
  const std::string output = argc >= 3 ? argv[2] : "ricci_flow_layout.obj";

  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(input, mesh) || mesh.is_empty())
  {
    std::cerr << "Error: cannot read a polygon mesh from '" << input << "'.\n";
    return 1;
  }
  if(!CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "Error: '" << input << "' is not a triangle mesh.\n";
    return 1;
  }
  std::vector<Mesh::Halfedge_index> border_cycles;
  CGAL::Polygon_mesh_processing::extract_boundary_cycles(mesh, std::back_inserter(border_cycles));
  const std::size_t components = CGAL::Polygon_mesh_processing::connected_components(
      mesh, mesh.add_property_map<Mesh::Face_index, std::size_t>("f:cc").first);
  const long chi = long(mesh.number_of_vertices()) - long(mesh.number_of_edges()) + long(mesh.number_of_faces());
  if(components != 1 || border_cycles.size() != 1 || chi != 1)
  {
    std::cerr << "Error: the mesh must be a topological disc (one component, one boundary, Euler characteristic 1); it has "
              << components << " component(s), " << border_cycles.size() << " boundary cycle(s), Euler characteristic "
              << chi << ".\n";
    return 1;
  }

  try
  {
    CR::Intrinsic_triangulation<double> tri(mesh);
    const std::vector<double> targets = CR::disc_flattening_targets(tri);
    auto result = CR::discrete_ricci_flow(tri, targets,
        CR::parameters::curvature_tolerance(1e-10, CGAL::parameters::callback([](int it, double err) {
          std::cout << "  iteration " << it << ": max |K_target - K| = " << err << "\n";
        })));
    std::cout << (result.converged ? "converged" : "NOT converged") << " after " << result.iterations
              << " Newton iterations, " << result.number_of_flips << " flips, " << result.number_of_splits
              << " edge splits, " << result.seconds_total << " s\n";
    if(!result.converged)
    {
      std::cerr << "Error: the Ricci flow did not converge (" << result.message << ").\n";
      return 1;
    }

    const std::vector<std::array<double, 2>> uv = tri.layout();
    double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
    for(const auto& p : uv)
      for(int d = 0; d < 2; ++d)
      {
        lo[d] = (std::min)(lo[d], p[d]);
        hi[d] = (std::max)(hi[d], p[d]);
      }
    const double scale = 1. / (std::max)(hi[0] - lo[0], hi[1] - lo[1]);

    std::ofstream out(output);
    if(!out)
    {
      std::cerr << "Error: cannot write '" << output << "'.\n";
      return 1;
    }
    out.precision(17);
    out << "# Ricci flow layout of " << input << "\n";
    for(Mesh::Vertex_index v : mesh.vertices())
      out << "v " << mesh.point(v) << "\n";
    // Vertices added by edge splits: their 3D point through the correspondence with the input.
    std::vector<std::array<Mesh::Vertex_index, 3>> input_face;
    for(Mesh::Face_index f : mesh.faces())
    {
      const Mesh::Halfedge_index h = mesh.halfedge(f);
      input_face.push_back({{mesh.source(h), mesh.target(h), mesh.target(mesh.next(h))}});
    }
    std::vector<std::pair<int, int>> corner_of(tri.number_of_vertices(), {-1, -1});
    for(int f = 0; f < tri.number_of_faces(); ++f)
      for(int c = 0; c < 3; ++c)
        corner_of[tri.vertex(f, c)] = {f, c};
    for(int v = static_cast<int>(mesh.number_of_vertices()); v < tri.number_of_vertices(); ++v)
    {
      CR::Intrinsic_triangulation<double>::Face_location at{corner_of[v].first, {{0., 0., 0.}}};
      at.coordinates[corner_of[v].second] = 1.;
      const auto in = tri.to_input(at);
      double p[3] = {0., 0., 0.};
      for(int c = 0; c < 3; ++c)
      {
        const Kernel::Point_3& q = mesh.point(input_face[in.face][c]);
        for(int d = 0; d < 3; ++d)
          p[d] += in.coordinates[c] * q[d];
      }
      out << "v " << p[0] << " " << p[1] << " " << p[2] << "\n";
    }
    for(const auto& p : uv)
      out << "vt " << (p[0] - lo[0]) * scale << " " << (p[1] - lo[1]) * scale << "\n";
    for(int f = 0; f < tri.number_of_faces(); ++f)
    {
      out << "f";
      for(int c = 0; c < 3; ++c)
        out << " " << tri.vertex(f, c) + 1 << "/" << tri.vertex(f, c) + 1;
      out << "\n";
    }
    if(!out)
    {
      std::cerr << "Error: writing '" << output << "' failed.\n";
      return 1;
    }
    std::cout << "wrote " << output << "\n";
  }
  catch(const CR::Error& e)
  {
    std::cerr << "Error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
