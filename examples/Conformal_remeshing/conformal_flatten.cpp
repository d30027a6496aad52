// conformal_flatten: flattens a genus-0 patch with any number of boundary loops by conformal
// welding and writes pictures and data of the result:
//   PREFIX_welded.svg       the welded disc laid out flat (patch, hole fills, annulus)
//   PREFIX_checkerboard.svg the patch's planar domain with a checkerboard drawn in the plane
//   PREFIX.obj/.mtl + PREFIX_checker.png   the input mesh with uv and a checkerboard texture
//   PREFIX_textured.png     a software rendering of that textured mesh
//   PREFIX_report.json      what happened (iterations, curvature error, scale range, checks, CAD slivers opened)
//   PREFIX_unwelded.svg     with --unwelded: CGAL's LSCM parameterization of the same patch, without
//                           welding, its overlaps darker and its folded triangles red
//
// Exit codes: 0 success, 1 the input is not a valid patch or the flattening failed (not
// converged, or not an embedding), 2 the tool could not run.

#include "atomic_file.h"
#include "flattening_pictures.h"
#include "json_writer.h"
#include "report_json.h"

#include <CGAL/Conformal_remeshing/IO/read_mesh.h>
#include <CGAL/Conformal_remeshing/conformal_flatten.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/LSCM_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <Eigen/Eigenvalues>

#include <cstdlib>
#include <iostream>
#include <string>

namespace CR = CGAL::Conformal_remeshing;
namespace tools = Conformal_remeshing_tools;
typedef CGAL::Epick K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

namespace {

const char* usage =
  "usage: conformal_flatten IN OUT_PREFIX [--inner-radius DELTA] [--unwelded] [--picture-size PIXELS]\n"
  "  IN             a genus-0 triangle mesh with at least one boundary loop (.off .obj .ply .stl)\n"
  "  OUT_PREFIX     where to write PREFIX_welded.svg, PREFIX_checkerboard.svg, PREFIX.obj,\n"
  "                 PREFIX.mtl, PREFIX_checker.png, PREFIX_textured.png and PREFIX_report.json\n"
  "  --inner-radius the annulus' inner radius, in (0, 1) (default 0.3)\n"
  "  --unwelded     also write PREFIX_unwelded.svg: CGAL's LSCM parameterization without welding,\n"
  "                 its overlaps darker and its folded triangles red, and print its exact check\n"
  "  --picture-size the width and height of PREFIX_textured.png in pixels (default 900)\n"
  "exit code: 0 success, 1 invalid patch or failed flattening, 2 the tool could not run\n";

std::string json_report(const std::string& input, const CR::Conformal_flattening& f)
{
  const CR::Flattening_report& r = f.report;
  tools::Json_writer json;
  json.begin_object();
  json.field("input", input).field("status", CR::error_message(r.status)).field("converged", r.converged);
  json.field("iterations", r.iterations).field("curvature_error", r.curvature_error).field("flips", r.flips);
  json.field("boundary_loops", r.boundary_loops).field("holes", f.holes.size()).field("boundary_splits", r.boundary_splits);
  json.field("edge_splits", r.edge_splits).field("refined_edge_length", r.refined_edge_length)
      .field("flat_sides_shortened", r.flat_sides_shortened);
  json.field("welded_vertices", r.welded_vertices).field("min_scale", r.min_scale).field("max_scale", r.max_scale);
  json.key("embedding").begin_object().field("is_embedding", r.embedding.is_embedding())
      .field("summary", r.embedding.summary()).field("faces", r.embedding.number_of_faces)
      .field("non_positive_faces", r.embedding.non_positive_faces)
      .field("boundary_intersections", r.embedding.boundary_intersections)
      .field("misplaced_holes", r.embedding.misplaced_holes).end_object();
  json.field("folded_input_triangles_in_uv", r.folded_input_triangles_in_uv);
  json.key("seconds").begin_object().field("welding", r.seconds_welding).field("ricci_flow", r.seconds_flow)
      .field("layout", r.seconds_layout).field("embedding_check", r.seconds_check).end_object();
  json.end_object();
  return json.str();
}

// A view direction that shows a mostly flat part from the front, a little from the side.
std::array<double, 3> view_direction(const Mesh& mesh)
{
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for(auto v : mesh.vertices())
    mean += Eigen::Vector3d(mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z());
  mean /= double(mesh.number_of_vertices());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for(auto v : mesh.vertices())
  {
    const Eigen::Vector3d p = Eigen::Vector3d(mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z()) - mean;
    covariance += p * p.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(covariance);
  const Eigen::Vector3d d = eigen.eigenvectors().col(0) + 0.4 * eigen.eigenvectors().col(1);
  return {{d.x(), d.y(), d.z()}};
}

// The patch parameterized by CGAL's LSCM, without welding: writes its picture and prints what
// the exact embedding check finds. Returns false if LSCM fails.
bool write_unwelded_parameterization(const Mesh& input, const std::string& file)
{
  namespace SMP = CGAL::Surface_mesh_parameterization;
  Mesh mesh = input;
  auto uv = mesh.add_property_map<Mesh::Vertex_index, K::Point_2>("v:unwelded_uv").first;
  const auto border = CGAL::Polygon_mesh_processing::longest_border(mesh).first;
  if(SMP::parameterize(mesh, SMP::LSCM_parameterizer_3<Mesh>(), border, uv) != SMP::OK)
    return false;
  std::vector<K::Point_2> points(mesh.number_of_vertices());
  for(auto v : mesh.vertices())
    points[v.idx()] = uv[v];
  std::vector<std::array<std::size_t, 3> > triangles;
  for(auto f : mesh.faces())
  {
    const auto h = mesh.halfedge(f);
    triangles.push_back({{mesh.source(h).idx(), mesh.target(h).idx(), mesh.target(mesh.next(h)).idx()}});
  }
  std::vector<std::vector<std::size_t> > loops;
  std::vector<Mesh::Halfedge_index> borders;
  CGAL::Polygon_mesh_processing::extract_boundary_cycles(mesh, std::back_inserter(borders));
  for(auto h : borders)
  {
    loops.emplace_back();
    for(auto b : CGAL::halfedges_around_face(h, mesh))
      loops.back().push_back(mesh.target(b).idx());
  }
  std::cout << "  without welding (LSCM): " << CR::check_parameterization(mesh, uv, true).summary() << "\n";
  tools::write_file_atomically(file, tools::unwelded_parameterization_svg(points, triangles, loops));
  return true;
}

} // namespace

int main(int argc, char** argv)
{
  std::string input, prefix;
  double inner_radius = 0.3;
  bool unwelded = false;
  int picture_size = 900;
  for(int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if(arg == "--help" || arg == "-h")
    {
      std::cout << usage;
      return 0;
    }
    if(arg == "--inner-radius" && i + 1 < argc)
    {
      try
      {
        inner_radius = std::stod(argv[++i]);
      }
      catch(const std::exception&)
      {
        std::cerr << "conformal_flatten: --inner-radius needs a number\n" << usage;
        return 2;
      }
    }
    else if(arg == "--unwelded")
      unwelded = true;
    else if(arg == "--picture-size" && i + 1 < argc)
    {
      picture_size = std::atoi(argv[++i]);
      if(picture_size < 16 || picture_size > 8192)
      {
        std::cerr << "conformal_flatten: --picture-size needs a number of pixels in [16, 8192]\n" << usage;
        return 2;
      }
    }
    else if(!arg.empty() && arg[0] != '-' && input.empty())
      input = arg;
    else if(!arg.empty() && arg[0] != '-' && prefix.empty())
      prefix = arg;
    else
    {
      std::cerr << "conformal_flatten: bad argument '" << arg << "'\n" << usage;
      return 2;
    }
  }
  if(input.empty() || prefix.empty())
  {
    std::cerr << "conformal_flatten: needs IN and OUT_PREFIX\n" << usage;
    return 2;
  }

  Mesh mesh;
  try
  {
    const CR::Mesh_check_report checks = CR::read_and_check_mesh(input, mesh);
    if(!checks.is_valid())
    {
      std::cerr << "conformal_flatten: invalid input '" << input << "': " << checks.summary() << "\n";
      return 1;
    }
  }
  catch(const std::exception& e)
  {
    std::cerr << "conformal_flatten: " << e.what() << "\n";
    return 2;
  }

  CR::Conformal_flattening f;
  try
  {
    std::cerr << "conformal_flatten: " << input << ": " << mesh.number_of_vertices() << " vertices, "
              << mesh.number_of_faces() << " faces; welding and flattening...\n";
    f = CR::conformal_flatten(mesh, CR::parameters::annulus_inner_radius(inner_radius));
  }
  catch(const CR::Error& e)
  {
    std::cerr << "conformal_flatten: " << e.what() << "\n";
    return e.code() == CR::Error_code::INVALID_INPUT ? 1 : 2;
  }
  const CR::Flattening_report& r = f.report;
  std::cout << "status: " << CR::error_message(r.status) << "\n"
            << "  Ricci flow: " << r.iterations << " Newton iterations, curvature error " << r.curvature_error << ", "
            << r.flips << " flips, " << r.seconds_flow << " s\n"
            << "  domain: outer boundary of " << f.outer_boundary.size() << " vertices and " << f.holes.size() << " holes\n"
            << "  local scale of the map: " << r.min_scale << " to " << r.max_scale << "\n"
            << "  embedding (exact predicates): " << r.embedding.summary() << "\n";
  if(r.refined_edge_length > 0.)
    std::cout << "  flattened again with the flow's edges split to " << r.refined_edge_length
              << " (the flow on the input's edges folded a triangle)\n";

  try
  {
    tools::write_file_atomically(prefix + "_welded.svg", tools::welded_domain_svg(f));
    tools::write_file_atomically(prefix + "_checkerboard.svg", tools::checkerboard_svg(f));
    const std::string texture_name = prefix + "_checker.png";
    tools::write_file_atomically(texture_name, [](std::ostream& out) { return tools::write_png(out, tools::checker_texture()); });

    const std::vector<std::array<double, 2> > texture = tools::normalized_texture_coordinates(f.uv);
    const std::string base = prefix.substr(prefix.find_last_of('/') + 1);
    tools::write_file_atomically(prefix + ".mtl", "newmtl checker\nKa 1 1 1\nKd 1 1 1\nmap_Kd " + base + "_checker.png\n");
    tools::write_file_atomically(prefix + ".obj", [&](std::ostream& out) {
      out.precision(17);
      out << "# conformal flattening of " << input << "\nmtllib " << base << ".mtl\nusemtl checker\n";
      for(auto v : mesh.vertices())
        out << "v " << mesh.point(v) << "\n";
      for(auto v : mesh.vertices())
        out << "vt " << texture[v.idx()][0] << " " << texture[v.idx()][1] << "\n";
      for(auto face : mesh.faces())
      {
        out << "f";
        for(auto v : CGAL::vertices_around_face(mesh.halfedge(face), mesh))
          out << " " << v.idx() + 1 << "/" << v.idx() + 1;
        out << "\n";
      }
      return bool(out);
    });

    std::vector<std::array<double, 3> > points;
    for(auto v : mesh.vertices())
      points.push_back({{mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z()}});
    std::vector<std::array<std::size_t, 3> > triangles;
    for(auto face : mesh.faces())
    {
      const auto h = mesh.halfedge(face);
      triangles.push_back({{mesh.source(h).idx(), mesh.target(h).idx(), mesh.target(mesh.next(h)).idx()}});
    }
    const tools::Rgb_image picture = tools::render_textured(points, triangles, texture, view_direction(mesh), picture_size);
    tools::write_file_atomically(prefix + "_textured.png", [&](std::ostream& out) { return tools::write_png(out, picture); });
    tools::write_file_atomically(prefix + "_report.json", json_report(input, f));
    if(unwelded && !write_unwelded_parameterization(mesh, prefix + "_unwelded.svg"))
      std::cerr << "conformal_flatten: CGAL's LSCM parameterization failed; no " << prefix << "_unwelded.svg\n";
  }
  catch(const std::exception& e)
  {
    std::cerr << "conformal_flatten: " << e.what() << "\n";
    return 2;
  }
  std::cout << "written: " << prefix << "_welded.svg, _checkerboard.svg, .obj, .mtl, _checker.png, _textured.png, _report.json\n";

  if(r.status != CR::Error_code::SUCCESS)
  {
    std::cerr << "conformal_flatten: the flattening failed: " << CR::error_message(r.status) << " ("
              << r.embedding.summary() << ")\n";
    return 1;
  }
  return 0;
}
