// Deviation maps for the tools: a mesh written as PLY, and drawn as PNG, with each face coloured
// by its distance to the other surface (CR::face_deviations()), and the histogram of those distances in units of the
// target edge length, for the report.
//
// Colours run from blue (on the surface) through cyan, green and yellow to red, at a quarter of
// the target edge length and beyond: the distances a remesher at that length should keep well
// below, so that the faces that lost a feature stand out.

#ifndef CGAL_CONFORMAL_REMESHING_TOOLS_DEVIATION_MAP_H
#define CGAL_CONFORMAL_REMESHING_TOOLS_DEVIATION_MAP_H

#include "atomic_file.h"
#include "json_writer.h"
#include "mesh_rendering.h"

#include <CGAL/Conformal_remeshing/face_deviations.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

namespace Conformal_remeshing_tools {

// The distance, as a fraction of the target edge length, coloured red.
constexpr double deviation_shown_red = 0.25;

// The bins of the report's histograms, as fractions of the target edge length.
inline std::vector<double> deviation_bins() { return {0.01, 0.03, 0.1, 0.25, 0.5, 1.}; }

// The colour of `deviation` on the map's scale (0: blue, `red_at` and beyond: red).
inline std::array<int, 3> deviation_colour(double deviation, double red_at)
{
  const double t = red_at > 0. ? (std::min)(1., (std::max)(0., deviation / red_at)) : 1.;
  // Blue, cyan, green, yellow, red at 0, 1/4, 1/2, 3/4 and 1.
  static const double stops[5][3] = {{0., 0., 1.}, {0., 1., 1.}, {0., 1., 0.}, {1., 1., 0.}, {1., 0., 0.}};
  const double x = 4. * t;
  const int i = (std::min)(3, int(x));
  const double f = x - i;
  std::array<int, 3> rgb;
  for(int c = 0; c < 3; ++c)
    rgb[c] = int(std::lround(255. * ((1. - f) * stops[i][c] + f * stops[i + 1][c])));
  return rgb;
}

// `mesh` as ASCII PLY with the colour of `deviation[f]` on each face f (in the order of faces()),
// red at `red_at`, which MeshLab, ParaView and Blender show as they are.
template <typename Mesh>
bool write_deviation_ply(std::ostream& out, const Mesh& mesh, const std::vector<double>& deviation, double red_at)
{
  out.precision(17);
  out << "ply\nformat ascii 1.0\ncomment faces coloured by their distance to the other surface, red at " << red_at
      << "\nelement vertex " << mesh.number_of_vertices() << "\nproperty double x\nproperty double y\nproperty double z\n"
      << "element face " << mesh.number_of_faces() << "\nproperty list uchar int vertex_indices\n"
      << "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n";
  std::vector<std::size_t> index(mesh.number_of_vertices() + mesh.number_of_removed_vertices());
  std::size_t n = 0;
  for(auto v : mesh.vertices())
  {
    index[std::size_t(v)] = n++;
    out << mesh.point(v) << "\n";
  }
  std::size_t f = 0;
  for(auto face : mesh.faces())
  {
    out << "3";
    for(auto v : mesh.vertices_around_face(mesh.halfedge(face)))
      out << " " << index[std::size_t(v)];
    const std::array<int, 3> rgb = deviation_colour(deviation[f++], red_at);
    out << " " << rgb[0] << " " << rgb[1] << " " << rgb[2] << "\n";
  }
  return bool(out);
}

// Meshes of more faces are drawn without their edges, which would cover the picture.
constexpr std::size_t most_faces_drawn_with_edges = 6000;

// A picture of `mesh` (see mesh_rendering.h) with the colour of `deviation[f]` on each face f.
template <typename Mesh>
Rgb_image deviation_picture(const Mesh& mesh, const std::vector<double>& deviation, double red_at)
{
  std::vector<Vector_3d> points(mesh.number_of_vertices() + mesh.number_of_removed_vertices());
  for(auto v : mesh.vertices())
    points[std::size_t(v)] = {{CGAL::to_double(mesh.point(v).x()), CGAL::to_double(mesh.point(v).y()),
                               CGAL::to_double(mesh.point(v).z())}};
  std::vector<std::array<std::size_t, 3> > triangles;
  std::vector<Colour> colours;
  std::size_t f = 0;
  for(auto face : mesh.faces())
  {
    std::array<std::size_t, 3> t;
    int k = 0;
    for(auto v : mesh.vertices_around_face(mesh.halfedge(face)))
      t[k++] = std::size_t(v);
    triangles.push_back(t);
    const std::array<int, 3> rgb = deviation_colour(deviation[f++], red_at);
    colours.push_back({{std::uint8_t(rgb[0]), std::uint8_t(rgb[1]), std::uint8_t(rgb[2])}});
  }
  Mesh_rendering_options o;
  o.edge_width = triangles.size() <= most_faces_drawn_with_edges ? 0.8 : 0.;
  return render_mesh(points, triangles, o, &colours);
}

// PREFIX_output.ply and PREFIX_input.ply, the output and the input with each face coloured by
// its distance to the other, red at `deviation_shown_red` times `target`, and their pictures
// PREFIX_output.png and PREFIX_input.png.
template <typename Mesh>
void write_deviation_maps(const std::string& prefix, const Mesh& output, const Mesh& input,
                          const CGAL::Conformal_remeshing::Face_deviations& deviations, double target)
{
  const double red_at = deviation_shown_red * target;
  const struct
  {
    const char* name;
    const Mesh& mesh;
    const std::vector<double>& deviation;
  } maps[] = {{"_output", output, deviations.of_mesh_faces}, {"_input", input, deviations.of_reference_faces}};
  for(const auto& map : maps)
  {
    write_file_atomically(prefix + map.name + ".ply",
                          [&](std::ostream& out) { return write_deviation_ply(out, map.mesh, map.deviation, red_at); });
    const Rgb_image picture = deviation_picture(map.mesh, map.deviation, red_at);
    write_file_atomically(prefix + map.name + ".png", [&](std::ostream& out) { return write_png(out, picture); });
  }
}

inline std::vector<double> relative_to(const std::vector<double>& deviation, double target)
{
  std::vector<double> relative;
  for(double d : deviation)
    relative.push_back(d / target);
  return relative;
}

// The deviations over `target`, their largest and their histogram on `deviation_bins()`.
inline void write_deviation_json(Json_writer& json, const std::vector<double>& deviation, double target)
{
  const std::vector<double> relative = relative_to(deviation, target);
  const std::vector<double> bins = deviation_bins();
  json.begin_object().field("faces", relative.size())
      .field("largest", relative.empty() ? 0. : *std::max_element(relative.begin(), relative.end()))
      .array("bin_upper_bounds", bins).array("shares", CGAL::Conformal_remeshing::deviation_histogram(relative, bins)).end_object();
}

// One line of the histogram: "share% below 0.01, ...": how many faces lie how far, in target lengths.
inline std::string deviation_histogram_line(const std::vector<double>& deviation, double target)
{
  const std::vector<double> bins = deviation_bins();
  const std::vector<double> share = CGAL::Conformal_remeshing::deviation_histogram(relative_to(deviation, target), bins);
  std::ostringstream line;
  line.precision(3);
  for(std::size_t i = 0; i < share.size(); ++i)
  {
    line << (i > 0 ? ", " : "") << 100. * share[i] << "% ";
    if(i == 0)
      line << "< " << bins[0];
    else if(i < bins.size())
      line << bins[i - 1] << "-" << bins[i];
    else
      line << ">= " << bins.back();
  }
  return line.str();
}

} // namespace Conformal_remeshing_tools

#endif // CGAL_CONFORMAL_REMESHING_TOOLS_DEVIATION_MAP_H
