// render_mesh: draws a triangle mesh into a PNG picture, offscreen, with the package's small
// software rasterizer (tool_support/mesh_rendering.h): flat-shaded triangles, their edges as dark
// lines, seen along a fixed direction. The same command line on an input and on its remeshing
// gives two pictures of the same view, for comparing their triangles. With --also, more meshes
// (the patches of a segmentation, say) are drawn into the same picture, each in its own colour.
//
// Exit codes: 0 success, 1 the input is not a triangle mesh, 2 the tool could not run.

#include "atomic_file.h"
#include "mesh_rendering.h"

#include <CGAL/Conformal_remeshing/IO/read_mesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <iostream>
#include <sstream>
#include <string>

namespace CR = CGAL::Conformal_remeshing;
namespace tools = Conformal_remeshing_tools;
typedef CGAL::Epick K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

namespace {

const char* usage =
  "usage: render_mesh IN OUT.png [--size WxH] [--view x,y,z] [--up x,y,z] [--zoom Z] [--focus x,y,z]\n"
  "                   [--edge-width PIXELS] [--highlight-angle DEG] [--also MESH]...\n"
  "  IN                   a triangle mesh (.off .obj .ply .stl)\n"
  "  OUT.png              the picture (written atomically)\n"
  "  --size WxH           picture size in pixels (default 600x450)\n"
  "  --view x,y,z         direction from the eye into the scene (default -0.6,-1,-0.9)\n"
  "  --up x,y,z           direction shown upwards (default 0,0,1)\n"
  "  --zoom Z             magnification; 1 shows the whole mesh (default 1)\n"
  "  --focus x,y,z        point at the centre of the picture (default the centre of the mesh)\n"
  "  --edge-width PIXELS  width of the edges drawn (default 1.2; 0: no edges)\n"
  "  --highlight-angle DEG  triangles with an angle below DEG in red (default 0: none)\n"
  "  --also MESH          one more triangle mesh in the same picture, in the next colour (repeatable)\n"
  "exit code: 0 success, 1 the input is not a triangle mesh, 2 the tool could not run\n";

bool parse_vector(const std::string& text, tools::Vector_3d& v)
{
  std::istringstream in(text);
  char comma = ',';
  for(int i = 0; i < 3; ++i)
    if(!(in >> v[i]) || (i < 2 && (!(in >> comma) || comma != ',')))
      return false;
  return in.peek() == EOF;
}

bool parse_size(const std::string& text, int& width, int& height)
{
  std::istringstream in(text);
  char x = 'x';
  return (in >> width >> x >> height) && x == 'x' && in.peek() == EOF && width > 0 && height > 0 && width <= 8192 &&
         height <= 8192;
}

bool parse_number(const std::string& text, double& value)
{
  std::istringstream in(text);
  return (in >> value) && in.peek() == EOF && value >= 0.;
}

// Reads the options; returns false on a bad command line.
bool parse(int argc, char** argv, std::vector<std::string>& inputs, std::string& output, tools::Mesh_rendering_options& o)
{
  for(int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    const bool has_value = i + 1 < argc;
    bool ok = true;
    if(arg == "--size" && has_value)
      ok = parse_size(argv[++i], o.width, o.height);
    else if(arg == "--view" && has_value)
      ok = parse_vector(argv[++i], o.view_direction);
    else if(arg == "--up" && has_value)
      ok = parse_vector(argv[++i], o.up);
    else if(arg == "--zoom" && has_value)
      ok = parse_number(argv[++i], o.zoom) && o.zoom > 0.;
    else if(arg == "--focus" && has_value)
      ok = o.has_focus = parse_vector(argv[++i], o.focus);
    else if(arg == "--edge-width" && has_value)
      ok = parse_number(argv[++i], o.edge_width);
    else if(arg == "--highlight-angle" && has_value)
      ok = parse_number(argv[++i], o.highlight_angle);
    else if(arg == "--also" && has_value)
      inputs.push_back(argv[++i]);
    else if(!arg.empty() && arg[0] != '-' && inputs.empty())
      inputs.push_back(arg);
    else if(!arg.empty() && arg[0] != '-' && output.empty())
      output = arg;
    else
      ok = false;
    if(!ok)
    {
      std::cerr << "render_mesh: bad argument '" << arg << "'\n" << usage;
      return false;
    }
  }
  if(inputs.empty() || output.empty())
  {
    std::cerr << "render_mesh: needs IN and OUT.png\n" << usage;
    return false;
  }
  return true;
}

// Appends the triangles of a mesh file to the scene, in `colour`; returns an exit code.
int add_mesh(const std::string& input, tools::Colour colour, std::vector<tools::Vector_3d>& points,
             std::vector<std::array<std::size_t, 3> >& triangles, std::vector<tools::Colour>& colours)
{
  Mesh mesh;
  try
  {
    const CR::Mesh_check_report checks = CR::read_and_check_mesh(input, mesh);
    if(!checks.topology_available || !CGAL::is_triangle_mesh(mesh))
    {
      std::cerr << "render_mesh: '" << input << "' is not a triangle mesh: " << checks.summary() << "\n";
      return 1;
    }
  }
  catch(const std::exception& e)
  {
    std::cerr << "render_mesh: " << e.what() << "\n";
    return 2;
  }
  const std::size_t first = points.size();
  points.resize(first + mesh.number_of_vertices());
  for(auto v : mesh.vertices())
    points[first + v.idx()] = {{mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z()}};
  for(auto f : mesh.faces())
  {
    const auto h = mesh.halfedge(f);
    triangles.push_back({{first + mesh.source(h).idx(), first + mesh.target(h).idx(), first + mesh.target(mesh.next(h)).idx()}});
    colours.push_back(colour);
  }
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  if(argc > 1 && (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h"))
  {
    std::cout << usage;
    return 0;
  }
  std::vector<std::string> inputs;
  std::string output;
  tools::Mesh_rendering_options options;
  if(!parse(argc, argv, inputs, output, options))
    return 2;

  std::vector<tools::Vector_3d> points;
  std::vector<std::array<std::size_t, 3> > triangles;
  std::vector<tools::Colour> colours;
  for(std::size_t i = 0; i < inputs.size(); ++i)
    if(const int code = add_mesh(inputs[i], i == 0 ? options.face : tools::part_colour(i), points, triangles, colours))
      return code;
  try
  {
    const tools::Rgb_image picture = tools::render_mesh(points, triangles, options, &colours);
    tools::write_file_atomically(output, [&](std::ostream& out) { return tools::write_png(out, picture); });
  }
  catch(const std::exception& e)
  {
    std::cerr << "render_mesh: " << e.what() << "\n";
    return 2;
  }
  std::cout << "render_mesh: " << triangles.size() << " triangles drawn into " << output << "\n";
  return 0;
}
