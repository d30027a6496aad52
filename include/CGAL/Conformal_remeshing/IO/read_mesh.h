// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Reading a mesh file through CGAL's IO, with the input checks run on what the file holds
// before any halfedge data structure is built.

#ifndef CGAL_CONFORMAL_REMESHING_IO_READ_MESH_H
#define CGAL_CONFORMAL_REMESHING_IO_READ_MESH_H

#include <CGAL/Conformal_remeshing/Error.h>
#include <CGAL/Conformal_remeshing/check_mesh.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_mesh_to_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/stitch_borders.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <numeric>
#include <sstream>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {

/// \ingroup PkgConformalRemeshingIO
/// Input defects that `read_and_check_mesh()` repairs before it checks what the file holds. None
/// by default: the checks then see the file as it is. Each repair is one that CGAL's own soup
/// processing makes without changing the surface; what it cannot repair is left for the checks
/// to report.
struct Input_repairs
{
  /// Faces of more than three vertices cut into triangles by CGAL's `triangulate_face()` (a
  /// constrained Delaunay triangulation in the polygon's plane); a polygon it cannot cut (one
  /// that visits a vertex twice, say) is left as it is.
  bool triangulate_polygons = false;
  /// Faces flipped so that each connected component is consistently oriented, by CGAL's
  /// `orient_polygon_soup()`, keeping the orientation of most of the component's faces; only
  /// when every component is orientable and edge-manifold (nothing to cut apart).
  bool orient_faces = false;
  /// Vertices of no face removed.
  bool remove_isolated_vertices = false;
  /// Border edges that run between the same two points, the opposite ways, joined into one edge
  /// by CGAL's `stitch_borders()` (a surface written as pieces whose seams repeat the vertices);
  /// duplicated vertices that are not on such edges stay, and are reported.
  bool stitch_borders = false;
  /// Non-manifold edges and vertices cut apart: every face of an edge of more than two faces is
  /// separated from the others along it, and each fan of faces around a vertex gets its own copy
  /// of the vertex (the surface stays where it is; its sheets then touch at coincident, distinct
  /// vertices, the edge being a border of each).
  bool split_non_manifold = false;

  /// every repair
  static Input_repairs all() { return Input_repairs{true, true, true, true, true}; }
  bool any() const { return triangulate_polygons || orient_faces || remove_isolated_vertices || stitch_borders || split_non_manifold; }
};

/// \ingroup PkgConformalRemeshingIO
/// What `read_and_check_mesh()` repaired (see `Input_repairs`).
struct Input_repair_report
{
  std::size_t file_faces = 0;            ///< faces in the file
  std::size_t triangulated_polygons = 0; ///< faces of more than three vertices cut into triangles
  std::size_t triangles_from_polygons = 0;
  std::size_t reoriented_faces = 0;
  std::size_t removed_isolated_vertices = 0;
  std::size_t stitched_vertices = 0; ///< vertices merged into others by the stitching of borders
  std::size_t split_vertices = 0;    ///< vertices added to cut non-manifold edges and vertices apart
  /// for each face of the mesh read, the index of the file's face it is part of (the identity
  /// when no polygon was triangulated), e.g. to carry per-face data of the file over
  std::vector<std::size_t> file_face;

  bool any() const
  {
    return triangulated_polygons > 0 || reoriented_faces > 0 || removed_isolated_vertices > 0 || stitched_vertices > 0
           || split_vertices > 0;
  }

  /// One line, e.g. "23 polygons triangulated into 46 triangles; 9 faces reoriented" ("nothing
  /// repaired" when nothing was).
  std::string summary() const
  {
    std::ostringstream out;
    const char* separator = "";
    auto plural = [](std::size_t n, const char* one, const char* many) { return n == 1 ? one : many; };
    if(triangulated_polygons > 0)
    {
      out << triangulated_polygons << plural(triangulated_polygons, " polygon", " polygons") << " triangulated into "
          << triangles_from_polygons << " triangles";
      separator = "; ";
    }
    if(reoriented_faces > 0)
    {
      out << separator << reoriented_faces << plural(reoriented_faces, " face", " faces") << " reoriented";
      separator = "; ";
    }
    if(removed_isolated_vertices > 0)
    {
      out << separator << removed_isolated_vertices << plural(removed_isolated_vertices, " isolated vertex", " isolated vertices")
          << " removed";
      separator = "; ";
    }
    if(stitched_vertices > 0)
    {
      out << separator << stitched_vertices << plural(stitched_vertices, " vertex", " vertices") << " stitched along borders";
      separator = "; ";
    }
    if(split_vertices > 0)
      out << separator << split_vertices << plural(split_vertices, " vertex", " vertices")
          << " added to cut non-manifold edges and vertices apart";
    return any() ? out.str() : std::string("nothing repaired");
  }
};

namespace internal {

// Reads `filename` if it is a binary STL file (its size matches the triangle count of its
// header) and returns false otherwise. CGAL's STL reader merges corners through a std::map,
// which merges a NaN corner with an arbitrary vertex and so hides it; here only finite
// corners are merged, so non-finite coordinates reach the input checks.
template <typename Point>
bool read_binary_STL(const std::string& filename, std::vector<Point>& points,
                     std::vector<std::vector<std::size_t> >& polygons)
{
  std::ifstream in(filename, std::ios::binary | std::ios::ate);
  if(!in)
    return false;
  const std::streamoff size = in.tellg();
  if(size < 84)
    return false;
  in.seekg(80);
  unsigned char count_bytes[4];
  in.read(reinterpret_cast<char*>(count_bytes), 4);
  const std::uint64_t count = std::uint64_t(count_bytes[0]) | (std::uint64_t(count_bytes[1]) << 8)
                              | (std::uint64_t(count_bytes[2]) << 16) | (std::uint64_t(count_bytes[3]) << 24);
  if(!in || std::uint64_t(size) != 84 + 50 * count)
    return false;

  auto lexicographic = [](const std::array<float, 3>& a, const std::array<float, 3>& b) { return a < b; };
  std::map<std::array<float, 3>, std::size_t, decltype(lexicographic)> index_of(lexicographic);
  points.clear();
  polygons.assign(count, std::vector<std::size_t>(3));
  for(std::uint64_t t = 0; t < count; ++t)
  {
    unsigned char record[50];
    in.read(reinterpret_cast<char*>(record), 50);
    if(!in)
      return false;
    for(int corner = 0; corner < 3; ++corner)
    {
      std::array<float, 3> xyz;
      for(int k = 0; k < 3; ++k)
      {
        const unsigned char* b = record + 12 * (corner + 1) + 4 * k; // after the facet normal
        const std::uint32_t bits = std::uint32_t(b[0]) | (std::uint32_t(b[1]) << 8)
                                   | (std::uint32_t(b[2]) << 16) | (std::uint32_t(b[3]) << 24);
        std::memcpy(&xyz[k], &bits, sizeof(float));
      }
      const bool finite = std::isfinite(xyz[0]) && std::isfinite(xyz[1]) && std::isfinite(xyz[2]);
      std::size_t index = points.size();
      if(finite)
      {
        const auto inserted = index_of.emplace(xyz, index);
        index = inserted.first->second;
      }
      if(index == points.size())
        points.push_back(Point(xyz[0], xyz[1], xyz[2]));
      polygons[t][corner] = index;
    }
  }
  return true;
}

// --- OFF and PLY ------------------------------------------------------------------------------
// CGAL 5.5's OFF and PLY readers size their arrays from counts found in the file before reading
// the data (a file of 200 bytes can ask for gigabytes, or loop for billions of records after
// its end), cast negative or huge numbers to std::size_t (undefined behaviour), and the PLY
// reader writes through `m_elements.back()` of an empty vector when a property comes before
// any element. The readers below parse the same formats strictly, from the bytes of the whole
// file: every count is checked against the bytes left before anything is allocated, every
// number is range-checked before it is converted, and any violation makes the read fail.

inline bool read_file_bytes(const std::string& filename, std::string& bytes)
{
  std::ifstream in(filename, std::ios::binary);
  if(!in)
    return false;
  bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return !in.bad();
}

inline bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// The lines of a text, from a byte position on, cut into whitespace-separated tokens;
// everything from `comment` to the end of a line is ignored, and so are lines with no token.
class Token_lines
{
public:
  Token_lines(const std::string& text, std::size_t position, char comment)
    : text_(text), position_(position), comment_(comment)
  {}

  bool next(std::vector<std::string_view>& tokens)
  {
    tokens.clear();
    while(tokens.empty() && position_ < text_.size())
    {
      std::size_t end = text_.find('\n', position_);
      if(end == std::string::npos)
        end = text_.size();
      std::string_view line(text_.data() + position_, end - position_);
      position_ = (std::min)(end + 1, text_.size());
      if(comment_ != '\0')
        line = line.substr(0, line.find(comment_));
      std::size_t i = 0;
      while(i < line.size())
      {
        while(i < line.size() && is_blank(line[i]))
          ++i;
        const std::size_t start = i;
        while(i < line.size() && !is_blank(line[i]))
          ++i;
        if(i > start)
          tokens.push_back(line.substr(start, i - start));
      }
    }
    return !tokens.empty();
  }

  std::size_t position() const { return position_; }

private:
  const std::string& text_;
  std::size_t position_;
  char comment_;
};

// A decimal number, locale-independent, "nan" and "inf" included; false unless the whole
// token is a number in the range of double.
inline bool parse_double(std::string_view token, double& x)
{
  if(!token.empty() && token[0] == '+')
    token.remove_prefix(1);
  const auto result = std::from_chars(token.data(), token.data() + token.size(), x);
  return !token.empty() && result.ec == std::errc() && result.ptr == token.data() + token.size();
}

// A count or an index: decimal digits only, below 10^18 (so no overflow).
inline bool parse_count(std::string_view token, std::size_t& n)
{
  if(token.empty() || token.size() > 18)
    return false;
  n = 0;
  for(char c : token)
  {
    if(c < '0' || c > '9')
      return false;
    n = 10 * n + std::size_t(c - '0');
  }
  return true;
}

// Big- or little-endian unsigned integer of `size` bytes at `p`.
inline std::uint64_t load_unsigned(const char* p, std::size_t size, bool big_endian)
{
  std::uint64_t v = 0;
  for(std::size_t i = 0; i < size; ++i)
  {
    const std::uint64_t byte = static_cast<unsigned char>(p[big_endian ? i : size - 1 - i]);
    v = (v << 8) | byte;
  }
  return v;
}

inline double load_float32(const char* p, bool big_endian)
{
  const std::uint32_t bits = static_cast<std::uint32_t>(load_unsigned(p, 4, big_endian));
  float f;
  std::memcpy(&f, &bits, sizeof(float));
  return f;
}

// Every vertex and every face of an OFF or PLY file takes at least this many bytes, whatever
// the encoding: counts above what the file can hold are refused before any allocation.
constexpr std::size_t minimum_record_bytes = 4;

// OFF: the header keyword [ST][C][N][4][n]OFF, optionally followed by BINARY, then the numbers
// of vertices, faces and edges. ASCII files hold a vertex per line (x y z [w], then normals,
// colors or texture coordinates, which are ignored) and a face per line (n, n vertex indices,
// then an optional color). Binary files (big-endian, Geomview's layout) hold float32 vertices
// and int32 faces, each followed by its number of color components and these components.
template <typename Point>
bool read_OFF(const std::string& text, std::vector<Point>& points, std::vector<std::vector<std::size_t> >& polygons)
{
  Token_lines lines(text, 0, '#');
  std::vector<std::string_view> tokens;
  if(!lines.next(tokens))
    return false;
  std::string_view keyword = tokens[0];
  auto take_prefix = [&](std::string_view prefix) {
    const bool found = keyword.substr(0, prefix.size()) == prefix;
    if(found)
      keyword.remove_prefix(prefix.size());
    return found;
  };
  const bool textures = take_prefix("ST");
  const bool colors = take_prefix("C");
  const bool normals = take_prefix("N");
  const bool homogeneous = take_prefix("4");
  const bool dimensional = take_prefix("n");
  if(keyword != "OFF")
    return false;
  const bool binary = tokens.size() > 1 && tokens[1] == "BINARY";
  if(binary && tokens.size() > 2)
    return false;

  std::size_t nv = 0, nf = 0;
  if(binary)
  {
    // Only plain binary OFF: the optional per-vertex data of the prefixes has no fixed layout.
    if(textures || colors || normals || homogeneous || dimensional)
      return false;
    std::size_t at = lines.position();
    auto remaining = [&]() { return text.size() - at; };
    auto read_int32 = [&](std::int64_t& value) {
      if(remaining() < 4)
        return false;
      value = static_cast<std::int32_t>(static_cast<std::uint32_t>(load_unsigned(text.data() + at, 4, true)));
      at += 4;
      return true;
    };
    std::int64_t v = 0, f = 0, e = 0;
    if(!read_int32(v) || !read_int32(f) || !read_int32(e) || v < 0 || f < 0
       || std::size_t(v) > remaining() / 12 || std::size_t(f) > remaining() / 16)
      return false;
    nv = std::size_t(v);
    nf = std::size_t(f);
    points.reserve(nv);
    for(std::size_t i = 0; i < nv; ++i, at += 12)
      points.push_back(Point(load_float32(text.data() + at, true), load_float32(text.data() + at + 4, true),
                             load_float32(text.data() + at + 8, true)));
    polygons.reserve(nf);
    for(std::size_t i = 0; i < nf; ++i)
    {
      std::int64_t n = 0, index = 0, nb_colors = 0;
      if(!read_int32(n) || n < 0 || std::size_t(n) > remaining() / 4)
        return false;
      polygons.emplace_back();
      polygons.back().reserve(std::size_t(n));
      for(std::int64_t k = 0; k < n; ++k)
      {
        if(!read_int32(index) || index < 0 || std::size_t(index) >= nv)
          return false;
        polygons.back().push_back(std::size_t(index));
      }
      if(!read_int32(nb_colors) || nb_colors < 0 || nb_colors > 4 || remaining() < 4 * std::size_t(nb_colors))
        return false;
      at += 4 * std::size_t(nb_colors);
    }
    return true;
  }

  // The counts may follow the keyword on its line or come on the next lines.
  std::vector<std::string_view> header(tokens.begin() + 1, tokens.end());
  const std::size_t nb_header_numbers = dimensional ? 4 : 3;
  while(header.size() < nb_header_numbers && lines.next(tokens))
    header.insert(header.end(), tokens.begin(), tokens.end());
  std::size_t dimension = 3, ne = 0;
  if(header.size() != nb_header_numbers || (dimensional && (!parse_count(header[0], dimension) || dimension != 3))
     || !parse_count(header[nb_header_numbers - 3], nv) || !parse_count(header[nb_header_numbers - 2], nf)
     || !parse_count(header[nb_header_numbers - 1], ne))
    return false;
  const std::size_t rest = text.size() - lines.position();
  if(nv > rest / minimum_record_bytes || nf > rest / minimum_record_bytes)
    return false;

  points.reserve(nv);
  for(std::size_t i = 0; i < nv; ++i)
  {
    double xyzw[4] = {0., 0., 0., 1.};
    const std::size_t needed = homogeneous ? 4 : 3;
    if(!lines.next(tokens) || tokens.size() < needed)
      return false;
    for(std::size_t k = 0; k < needed; ++k)
      if(!parse_double(tokens[k], xyzw[k]))
        return false;
    // w = 0 gives non-finite coordinates, which the input checks report.
    points.push_back(Point(xyzw[0] / xyzw[3], xyzw[1] / xyzw[3], xyzw[2] / xyzw[3]));
  }
  polygons.reserve(nf);
  for(std::size_t i = 0; i < nf; ++i)
  {
    std::size_t n = 0;
    if(!lines.next(tokens) || !parse_count(tokens[0], n) || n >= tokens.size())
      return false; // a face and its indices are on one line
    polygons.emplace_back(n);
    for(std::size_t k = 0; k < n; ++k)
      if(!parse_count(tokens[k + 1], polygons.back()[k]) || polygons.back()[k] >= nv)
        return false;
  }
  return true;
}

// The steps of read_PLY(), whose comment below describes the format.

enum Ply_format { PLY_ASCII, PLY_LITTLE_ENDIAN, PLY_BIG_ENDIAN };

// A scalar type of PLY: its size in bytes, and whether it is signed and a floating-point type.
struct Ply_type { std::size_t size; bool is_signed, is_float; };

// A property of an element: a scalar of `value_type`, or a list of `value_type` values after a
// length of `count_type`.
struct Ply_property { std::string name; bool is_list; Ply_type count_type, value_type; };

struct Ply_element { std::string name; std::size_t count; std::vector<Ply_property> properties; };

// The type called `name` in a PLY header (both the old and the sized names); false for any
// other name.
inline bool ply_type_of(std::string_view name, Ply_type& type)
{
  static const std::pair<const char*, Ply_type> types[] = {
    {"char", {1, true, false}},   {"int8", {1, true, false}},     {"uchar", {1, false, false}}, {"uint8", {1, false, false}},
    {"short", {2, true, false}},  {"int16", {2, true, false}},    {"ushort", {2, false, false}}, {"uint16", {2, false, false}},
    {"int", {4, true, false}},    {"int32", {4, true, false}},    {"uint", {4, false, false}},  {"uint32", {4, false, false}},
    {"float", {4, true, true}},   {"float32", {4, true, true}},   {"double", {8, true, true}},  {"float64", {8, true, true}}};
  for(const auto& t : types)
    if(name == t.first)
    {
      type = t.second;
      return true;
    }
  return false;
}

// The header, line by line, up to "end_header": the format and the elements with their
// properties; false for any other line, and for a property before the first element.
inline bool read_PLY_header(Token_lines& lines, Ply_format& format, std::vector<Ply_element>& elements)
{
  std::vector<std::string_view> tokens;
  if(!lines.next(tokens) || tokens.size() != 1 || tokens[0] != "ply" || !lines.next(tokens) || tokens.size() != 3
     || tokens[0] != "format")
    return false;
  if(tokens[1] == "ascii")
    format = PLY_ASCII;
  else if(tokens[1] == "binary_little_endian")
    format = PLY_LITTLE_ENDIAN;
  else if(tokens[1] == "binary_big_endian")
    format = PLY_BIG_ENDIAN;
  else
    return false;
  for(;;)
  {
    if(!lines.next(tokens))
      return false; // no end_header
    if(tokens[0] == "end_header" && tokens.size() == 1)
      break;
    if(tokens[0] == "comment" || tokens[0] == "obj_info")
      continue;
    if(tokens[0] == "element" && tokens.size() == 3)
    {
      elements.push_back(Ply_element{std::string(tokens[1]), 0, {}});
      if(!parse_count(tokens[2], elements.back().count))
        return false;
    }
    else if(tokens[0] == "property" && !elements.empty() && tokens.size() == 3)
    {
      Ply_property p{std::string(tokens[2]), false, {}, {}};
      if(!ply_type_of(tokens[1], p.value_type))
        return false;
      elements.back().properties.push_back(p);
    }
    else if(tokens[0] == "property" && !elements.empty() && tokens.size() == 5 && tokens[1] == "list")
    {
      Ply_property p{std::string(tokens[4]), true, {}, {}};
      if(!ply_type_of(tokens[2], p.count_type) || p.count_type.is_float || !ply_type_of(tokens[3], p.value_type))
        return false;
      elements.back().properties.push_back(p);
    }
    else
      return false;
  }
  return true;
}

// The body, from byte `at` on: values are read one at a time, as doubles (exact for every PLY
// integer type), as whitespace-separated tokens in ASCII and as bytes in the file's byte order
// otherwise.
class Ply_value_reader
{
public:
  Ply_value_reader(const std::string& text, std::size_t at, Ply_format format)
    : text_(text), at_(at), format_(format), ascii_lines_(text, at, '\0')
  {}

  bool read(const Ply_type& type, double& value)
  {
    if(format_ == PLY_ASCII)
    {
      while(next_token_ == line_tokens_.size())
      {
        if(!ascii_lines_.next(line_tokens_))
          return false;
        next_token_ = 0;
      }
      return parse_double(line_tokens_[next_token_++], value);
    }
    if(text_.size() - at_ < type.size)
      return false;
    const char* p = text_.data() + at_;
    at_ += type.size;
    const std::uint64_t bits = load_unsigned(p, type.size, format_ == PLY_BIG_ENDIAN);
    if(type.is_float && type.size == 4)
      value = load_float32(p, format_ == PLY_BIG_ENDIAN);
    else if(type.is_float)
    {
      double d;
      std::memcpy(&d, &bits, sizeof(double));
      value = d;
    }
    else if(type.is_signed && (bits >> (8 * type.size - 1)) != 0)
      value = double(bits) - std::ldexp(1., int(8 * type.size)); // two's complement
    else
      value = double(bits);
    return true;
  }

  // The bytes not read yet (in ASCII, all those after the header: the tokens are read by lines,
  // not counted in bytes).
  std::size_t remaining() const { return text_.size() - at_; }

  // A bound on the length of a list of `type` values read now: above it the values cannot fit
  // in the bytes left (in ASCII, in the whole text).
  std::size_t list_length_bound(const Ply_type& type) const
  {
    return (format_ == PLY_ASCII ? text_.size() : remaining()) / type.size + 1;
  }

private:
  const std::string& text_;
  std::size_t at_;
  Ply_format format_;
  Token_lines ascii_lines_;
  std::vector<std::string_view> line_tokens_;
  std::size_t next_token_ = 0;
};

// An integer-valued number in [0, bound): a list length or a vertex index.
inline bool ply_index(double value, std::size_t bound, std::size_t& index)
{
  if(!(value >= 0. && value < double(bound) && value == std::floor(value)))
    return false;
  index = static_cast<std::size_t>(value);
  return true;
}

// The values of a list property whose length, `length_value`, was just read; with `is_face`, they
// are the vertex indices of a new face, appended to `polygons`, and skipped otherwise.
inline bool read_PLY_list(Ply_value_reader& values, const Ply_type& value_type, double length_value, bool is_face,
                          std::vector<std::vector<std::size_t> >& polygons)
{
  std::size_t length = 0;
  if(!ply_index(length_value, values.list_length_bound(value_type), length))
    return false;
  if(is_face)
    polygons.emplace_back();
  for(std::size_t i = 0; i < length; ++i)
  {
    double value = 0.;
    if(!values.read(value_type, value))
      return false;
    std::size_t index = 0;
    if(is_face)
    {
      if(!ply_index(value, std::numeric_limits<std::uint32_t>::max(), index))
        return false;
      polygons.back().push_back(index);
    }
  }
  return true;
}

// The records of one element: the x, y, z properties of a "vertex" element appended to `points`,
// the vertex list of a "face" element to `polygons`, and the other properties and elements read
// and skipped.
template <typename Point>
bool read_PLY_element(Ply_value_reader& values, const Ply_element& element, std::vector<Point>& points,
                      std::vector<std::vector<std::size_t> >& polygons)
{
  if(element.properties.empty())
    return element.count == 0;
  // A record takes at least one byte per scalar property, and per list length.
  if(element.count > values.remaining() / element.properties.size())
    return false;
  const bool is_vertex = (element.name == "vertex"), is_face = (element.name == "face");
  std::array<int, 3> xyz{{-1, -1, -1}};
  int face_list = -1;
  for(std::size_t k = 0; k < element.properties.size(); ++k)
  {
    const Ply_property& p = element.properties[k];
    if(is_vertex && !p.is_list && p.name.size() == 1 && p.name[0] >= 'x' && p.name[0] <= 'z')
      xyz[p.name[0] - 'x'] = int(k);
    if(is_face && p.is_list && (p.name == "vertex_indices" || p.name == "vertex_index"))
      face_list = int(k);
  }
  if(is_vertex && (xyz[0] < 0 || xyz[1] < 0 || xyz[2] < 0))
    return false;
  if(is_face && face_list < 0)
    return false;
  if(is_vertex)
    points.reserve(element.count);

  for(std::size_t r = 0; r < element.count; ++r)
  {
    double coordinates[3] = {0., 0., 0.};
    for(std::size_t k = 0; k < element.properties.size(); ++k)
    {
      const Ply_property& p = element.properties[k];
      double value = 0.;
      if(!values.read(p.is_list ? p.count_type : p.value_type, value))
        return false;
      if(!p.is_list)
      {
        for(int c = 0; c < 3; ++c)
          if(is_vertex && xyz[c] == int(k))
            coordinates[c] = value;
        continue;
      }
      if(!read_PLY_list(values, p.value_type, value, is_face && face_list == int(k), polygons))
        return false;
    }
    if(is_vertex)
      points.push_back(Point(coordinates[0], coordinates[1], coordinates[2]));
  }
  return true;
}

// PLY: one "ply" line, a "format" line (ascii, binary_little_endian or binary_big_endian),
// then elements with their scalar or list properties, up to "end_header". The points are the
// x, y, z properties of the "vertex" element and the faces the "vertex_indices" (or
// "vertex_index") list of the "face" element; other elements and properties are skipped.
template <typename Point>
bool read_PLY(const std::string& text, std::vector<Point>& points, std::vector<std::vector<std::size_t> >& polygons)
{
  Token_lines lines(text, 0, '\0');
  Ply_format format = PLY_ASCII;
  std::vector<Ply_element> elements;
  if(!read_PLY_header(lines, format, elements))
    return false;

  Ply_value_reader values(text, lines.position(), format);
  for(const Ply_element& element : elements)
    if(!read_PLY_element(values, element, points, polygons))
      return false;
  // Faces may come before the vertices: their indices are checked once all points are known.
  for(const std::vector<std::size_t>& polygon : polygons)
    for(std::size_t index : polygon)
      if(index >= points.size())
        return false;
  return true;
}

// --- repairs (see `Input_repairs`) -----------------------------------------------------------------

// The points of no face removed, the others renumbered in order; returns how many were removed.
template <typename Point>
std::size_t remove_isolated_points(std::vector<Point>& points, std::vector<std::vector<std::size_t> >& polygons)
{
  const std::size_t unused = std::size_t(-1);
  std::vector<std::size_t> new_index(points.size(), unused);
  for(const std::vector<std::size_t>& polygon : polygons)
    for(std::size_t v : polygon)
      new_index[v] = 0;
  std::size_t used = 0;
  for(std::size_t v = 0; v < points.size(); ++v)
    if(new_index[v] != unused)
    {
      points[used] = points[v];
      new_index[v] = used++;
    }
  const std::size_t removed = points.size() - used;
  points.resize(used);
  for(std::vector<std::size_t>& polygon : polygons)
    for(std::size_t& v : polygon)
      v = new_index[v];
  return removed;
}

// Whether two faces run along an edge the same way: an inconsistent orientation, or a
// non-manifold edge (which orienting cannot repair).
inline bool has_repeated_directed_edge(const std::vector<std::vector<std::size_t> >& polygons)
{
  std::vector<std::pair<std::size_t, std::size_t> > directed;
  for(const std::vector<std::size_t>& polygon : polygons)
    for(std::size_t i = 0; i < polygon.size(); ++i)
      directed.emplace_back(polygon[i], polygon[(i + 1) % polygon.size()]);
  std::sort(directed.begin(), directed.end());
  return std::adjacent_find(directed.begin(), directed.end()) != directed.end();
}

// At least three corners, all different.
inline bool has_distinct_corners(const std::vector<std::size_t>& polygon)
{
  std::vector<std::size_t> sorted(polygon);
  std::sort(sorted.begin(), sorted.end());
  return sorted.size() >= 3 && std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end();
}

// Every edge of more than two faces cut apart, and every vertex whose faces form several fans
// split: around each point, the faces joined across edges of exactly two faces keep one vertex,
// and each other group of them gets a new copy of the point. Returns the number of points added.
template <typename Point>
std::size_t split_non_manifold_elements(std::vector<Point>& points, std::vector<std::vector<std::size_t> >& polygons)
{
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> faces_at_edge;
  for(const std::vector<std::size_t>& polygon : polygons)
    for(std::size_t i = 0; i < polygon.size(); ++i)
      ++faces_at_edge[std::minmax(polygon[i], polygon[(i + 1) % polygon.size()])];
  std::vector<std::vector<std::pair<std::size_t, std::size_t> > > corners_at(points.size()); // (face, corner)
  for(std::size_t f = 0; f < polygons.size(); ++f)
    for(std::size_t i = 0; i < polygons[f].size(); ++i)
      corners_at[polygons[f][i]].emplace_back(f, i);
  const std::size_t before = points.size();
  const std::vector<std::vector<std::size_t> > original = polygons; // the neighbours, before any renaming
  for(std::size_t v = 0; v < before; ++v)
  {
    const std::vector<std::pair<std::size_t, std::size_t> >& corners = corners_at[v];
    // Groups of the corners at v: union-find over faces joined across a manifold edge at v.
    std::vector<std::size_t> parent(corners.size());
    std::iota(parent.begin(), parent.end(), std::size_t(0));
    const auto root = [&](std::size_t c) {
      while(parent[c] != c)
        c = parent[c] = parent[parent[c]];
      return c;
    };
    std::map<std::size_t, std::size_t> corner_across; // other end of an edge at v -> a corner using it
    for(std::size_t c = 0; c < corners.size(); ++c)
    {
      const std::vector<std::size_t>& polygon = original[corners[c].first];
      const std::size_t i = corners[c].second, n = polygon.size();
      for(std::size_t w : {polygon[(i + 1) % n], polygon[(i + n - 1) % n]})
      {
        if(faces_at_edge[std::minmax(v, w)] != 2)
          continue;
        const auto inserted = corner_across.emplace(w, c);
        if(!inserted.second)
          parent[root(c)] = root(inserted.first->second);
      }
    }
    std::map<std::size_t, std::size_t> index_of_group;
    for(std::size_t c = 0; c < corners.size(); ++c)
    {
      const auto inserted = index_of_group.emplace(root(c), index_of_group.empty() ? v : points.size());
      if(inserted.second && inserted.first->second != v)
        points.push_back(points[v]);
      polygons[corners[c].first][corners[c].second] = inserted.first->second;
    }
  }
  return points.size() - before;
}

// Records the faces that CGAL's orient_polygon_soup() reverses.
struct Reversal_visitor : Polygon_mesh_processing::Default_orientation_visitor
{
  std::vector<bool>* reversed;
  void polygon_orientation_reversed(std::size_t p) { (*reversed)[p] = !(*reversed)[p]; }
};

// CGAL's orient_polygon_soup() keeps the orientation of the first face it meets in each
// component; here each component then keeps the orientation of most of its faces (a closed
// surface stays outward when most of the file's faces were). `flipped` counts the faces
// reversed; `polygons` stay as they are when the soup would have to be cut apart to be oriented
// (a non-manifold edge or vertex, a non-orientable component).
template <typename Point>
void orient_faces(const std::vector<Point>& points, std::vector<std::vector<std::size_t> >& polygons, std::size_t& flipped)
{
  // CGAL's orient_polygon_soup() never returns on a polygon that visits a vertex twice (a
  // triangle with two equal corners, say): such a soup is left to the checks.
  flipped = 0;
  if(!std::all_of(polygons.begin(), polygons.end(), has_distinct_corners))
    return;
  std::vector<Point> oriented_points(points);
  std::vector<std::vector<std::size_t> > oriented(polygons);
  std::vector<bool> reversed(polygons.size(), false);
  Reversal_visitor visitor;
  visitor.reversed = &reversed;
  if(!Polygon_mesh_processing::orient_polygon_soup(oriented_points, oriented, CGAL::parameters::visitor(visitor))
     || oriented_points.size() != points.size())
    return;
  // The components: faces joined across their edges (union-find on the faces).
  std::vector<std::size_t> parent(oriented.size());
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  auto root = [&](std::size_t f) {
    while(parent[f] != f)
      f = parent[f] = parent[parent[f]];
    return f;
  };
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> face_at_edge;
  for(std::size_t f = 0; f < oriented.size(); ++f)
    for(std::size_t i = 0; i < oriented[f].size(); ++i)
    {
      const std::size_t a = oriented[f][i], b = oriented[f][(i + 1) % oriented[f].size()];
      const auto inserted = face_at_edge.emplace(std::minmax(a, b), f);
      if(!inserted.second)
        parent[root(f)] = root(inserted.first->second);
    }
  std::vector<std::ptrdiff_t> balance(oriented.size(), 0); // per root: faces flipped minus faces kept
  for(std::size_t f = 0; f < oriented.size(); ++f)
    balance[root(f)] += reversed[f] ? 1 : -1;
  for(std::size_t f = 0; f < oriented.size(); ++f)
  {
    if(balance[root(f)] > 0)
    {
      std::reverse(oriented[f].begin(), oriented[f].end());
      reversed[f] = !reversed[f];
    }
    if(reversed[f])
      ++flipped;
  }
  polygons = std::move(oriented);
}

// Whether CGAL's triangulate_face() can cut `polygon`: distinct, finite corners, and a plane
// (a nonzero Newell normal; its triangulation is projected along that normal).
template <typename Point>
bool is_cuttable_polygon(const std::vector<Point>& points, const std::vector<std::size_t>& polygon)
{
  if(!has_distinct_corners(polygon))
    return false;
  double normal[3] = {0., 0., 0.};
  for(std::size_t i = 0; i < polygon.size(); ++i)
  {
    const Point& p = points[polygon[i]];
    const Point& q = points[polygon[(i + 1) % polygon.size()]];
    const double px = CGAL::to_double(p.x()), py = CGAL::to_double(p.y()), pz = CGAL::to_double(p.z());
    const double qx = CGAL::to_double(q.x()), qy = CGAL::to_double(q.y()), qz = CGAL::to_double(q.z());
    if(!(std::isfinite(px) && std::isfinite(py) && std::isfinite(pz)))
      return false;
    normal[0] += (py - qy) * (pz + qz);
    normal[1] += (pz - qz) * (px + qx);
    normal[2] += (px - qx) * (py + qy);
  }
  const double length = std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
  return std::isfinite(length) && length > 0.;
}

// Each face of more than three vertices cut into triangles by CGAL's triangulate_face(), on a
// mesh of that face alone (so that the rest of the soup need not be a valid mesh); its triangles
// keep its orientation. A polygon that cannot be cut is left for the checks to report.
template <typename Point>
void triangulate_polygons(const std::vector<Point>& points, std::vector<std::vector<std::size_t> >& polygons,
                          Input_repair_report& report)
{
  typedef CGAL::Surface_mesh<Point> Face_mesh;
  Face_mesh face_mesh; // one polygon at a time, emptied for the next (no allocation per polygon)
  std::vector<std::vector<std::size_t> > triangles;
  std::vector<std::size_t> file_face;
  triangles.reserve(polygons.size());
  for(std::size_t f = 0; f < polygons.size(); ++f)
  {
    const std::vector<std::size_t>& polygon = polygons[f];
    bool cut = false;
    if(polygon.size() > 3 && is_cuttable_polygon(points, polygon))
    {
      face_mesh.clear_without_removing_property_maps();
      std::vector<typename Face_mesh::Vertex_index> corners;
      for(std::size_t v : polygon)
        corners.push_back(face_mesh.add_vertex(points[v]));
      const typename Face_mesh::Face_index face = face_mesh.add_face(corners);
      if(face != Face_mesh::null_face() && Polygon_mesh_processing::triangulate_face(face, face_mesh))
      {
        const std::size_t before = triangles.size();
        for(typename Face_mesh::Face_index t : face_mesh.faces())
        {
          std::vector<std::size_t> triangle;
          for(typename Face_mesh::Vertex_index v : CGAL::vertices_around_face(face_mesh.halfedge(t), face_mesh))
            triangle.push_back(polygon[v.idx()]);
          triangles.push_back(std::move(triangle));
        }
        cut = triangles.size() > before;
        if(cut)
        {
          ++report.triangulated_polygons;
          report.triangles_from_polygons += triangles.size() - before;
          file_face.resize(triangles.size(), report.file_face[f]);
        }
      }
    }
    if(!cut)
    {
      triangles.push_back(polygon);
      file_face.push_back(report.file_face[f]);
    }
  }
  polygons = std::move(triangles);
  report.file_face = std::move(file_face);
}

// Whether a soup is a polygon mesh by CGAL's is_polygon_soup_a_polygon_mesh(), remembered until
// a repair changes the soup: the test builds a set of all the soup's edges (seconds on a million
// faces), and reading asks it up to three times.
class Polygon_mesh_test
{
public:
  bool operator()(const std::vector<std::vector<std::size_t> >& polygons)
  {
    if(!known_)
      is_mesh_ = Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(polygons);
    known_ = true;
    return is_mesh_;
  }
  void soup_changed() { known_ = false; }

private:
  bool known_ = false, is_mesh_ = false;
};

// Whether an edge of `polygons` has one face (each directed edge taken once, as in a polygon mesh).
inline bool has_border_edge(const std::vector<std::vector<std::size_t> >& polygons)
{
  std::vector<std::pair<std::size_t, std::size_t> > edges;
  for(const std::vector<std::size_t>& polygon : polygons)
    for(std::size_t i = 0; i < polygon.size(); ++i)
      edges.push_back(std::minmax(polygon[i], polygon[(i + 1) % polygon.size()]));
  std::sort(edges.begin(), edges.end());
  for(std::size_t i = 0; i < edges.size();)
  {
    std::size_t j = i + 1;
    while(j < edges.size() && edges[j] == edges[i])
      ++j;
    if(j - i == 1)
      return true;
    i = j;
  }
  return false;
}

// Border edges joined by CGAL's stitch_borders(), on the mesh of the soup when it is one, with
// finite coordinates (the stitching sorts the points), no isolated vertex (the mesh would drop
// it unsaid) and a border (a closed surface has nothing to stitch); the faces keep their order.
template <typename Point>
void stitch_borders(std::vector<Point>& points, std::vector<std::vector<std::size_t> >& polygons, Polygon_mesh_test& is_mesh,
                    std::size_t& stitched)
{
  stitched = 0;
  const bool finite = std::all_of(points.begin(), points.end(), [](const Point& p) {
    return std::isfinite(CGAL::to_double(p.x())) && std::isfinite(CGAL::to_double(p.y())) && std::isfinite(CGAL::to_double(p.z()));
  });
  if(!finite || polygons.empty() || !is_mesh(polygons) || !has_border_edge(polygons))
    return;
  CGAL::Surface_mesh<Point> mesh;
  Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  const std::size_t vertices = mesh.number_of_vertices();
  if(vertices != points.size() || mesh.number_of_faces() != polygons.size()
     || Polygon_mesh_processing::stitch_borders(mesh) == 0)
    return;
  stitched = vertices - mesh.number_of_vertices();
  mesh.collect_garbage();
  points.clear();
  polygons.clear();
  Polygon_mesh_processing::polygon_mesh_to_polygon_soup(mesh, points, polygons);
  is_mesh.soup_changed();
}

template <typename Point>
void repair_polygon_soup(std::vector<Point>& points, std::vector<std::vector<std::size_t> >& polygons,
                         const Input_repairs& repairs, Input_repair_report& report, Polygon_mesh_test& is_mesh)
{
  report = Input_repair_report();
  report.file_faces = polygons.size();
  report.file_face.resize(polygons.size());
  std::iota(report.file_face.begin(), report.file_face.end(), std::size_t(0));
  // A face that names a missing vertex is left to the checks, and so is the rest: no repair can
  // read such a soup.
  for(const std::vector<std::size_t>& polygon : polygons)
    for(std::size_t v : polygon)
      if(v >= points.size())
        return;
  if(repairs.remove_isolated_vertices)
    report.removed_isolated_vertices = remove_isolated_points(points, polygons);
  // (Each repair that returns a count of 0 left the soup as it was.)
  if(repairs.split_non_manifold && std::all_of(polygons.begin(), polygons.end(), has_distinct_corners) && !is_mesh(polygons))
    report.split_vertices = split_non_manifold_elements(points, polygons);
  if(report.split_vertices > 0)
    is_mesh.soup_changed();
  if(repairs.orient_faces && has_repeated_directed_edge(polygons))
    orient_faces(points, polygons, report.reoriented_faces);
  if(report.reoriented_faces > 0)
    is_mesh.soup_changed();
  if(repairs.stitch_borders && report.split_vertices == 0) // the borders of the cut sheets stay apart
    stitch_borders(points, polygons, is_mesh, report.stitched_vertices);
  if(repairs.triangulate_polygons)
    triangulate_polygons(points, polygons, report);
  if(report.triangulated_polygons > 0)
    is_mesh.soup_changed();
}

// The same, for a soup whose polygon-mesh test is not asked again afterwards.
template <typename Point>
void repair_polygon_soup(std::vector<Point>& points, std::vector<std::vector<std::size_t> >& polygons,
                         const Input_repairs& repairs, Input_repair_report& report)
{
  Polygon_mesh_test is_mesh;
  repair_polygon_soup(points, polygons, repairs, report, is_mesh);
}

} // namespace internal

/// \ingroup PkgConformalRemeshingIO
/// Reads `filename` (OFF, OBJ, PLY or STL, ASCII or binary, chosen by the extension) into
/// `mesh`, and returns the input checks of what the file holds.
///
/// The file is read as a polygon soup and checked with `check_polygon_soup()`, so that defects
/// no halfedge data structure can hold (non-manifold edges, inconsistent orientation,
/// non-orientable surfaces) are reported instead of making the read fail. `mesh` is built only
/// when the soup is a valid polygon mesh; then the report also carries the topology of each
/// connected component (`topology_available`), and `mesh` is cleared otherwise. The STL readers
/// merge the identical corners of the file's triangle soup into shared vertices (corners with
/// non-finite coordinates are never merged, so that the checks see them).
///
/// The OFF and PLY files are parsed by the package's own strict readers (OFF: ASCII with the
/// `ST`, `C`, `N`, `4` and `n` header prefixes, and plain binary; PLY: ASCII and both binary
/// byte orders, any element and property types): every count in a file is checked against the
/// size of the file before memory is allocated, so that a short hostile file cannot exhaust
/// memory. Faces with other than three vertices are read, and reported as non-triangle faces.
///
/// \tparam PolygonMesh a model of `MutableFaceGraph` with an internal point property map
///
/// \throws Error with `Error_code::UNSUPPORTED_FORMAT` for an unknown extension, and with
///         `Error_code::FILE_NOT_READABLE` when the file cannot be opened or parsed; the message
///         names the file and the reason.
template <typename PolygonMesh>
Mesh_check_report read_and_check_mesh(const std::string& filename, PolygonMesh& mesh)
{
  Input_repair_report repaired;
  return read_and_check_mesh(filename, mesh, Input_repairs(), repaired);
}

/// \ingroup PkgConformalRemeshingIO
/// The same, with the defects named by `repairs` repaired first (see `Input_repairs`): the
/// checks and `mesh` are then those of the repaired surface, and `repaired` says what changed.
/// The `remesh_conformal` tool reads its input this way with every repair, unless told not to.
template <typename PolygonMesh>
Mesh_check_report read_and_check_mesh(const std::string& filename, PolygonMesh& mesh, const Input_repairs& repairs,
                                      Input_repair_report& repaired)
{
  typedef typename boost::property_map<PolygonMesh, CGAL::vertex_point_t>::type Vertex_point_map;
  typedef typename boost::property_traits<Vertex_point_map>::value_type Point;
  typedef typename CGAL::Kernel_traits<Point>::Kernel Kernel;

  const std::string::size_type dot = filename.find_last_of('.');
  std::string extension = (dot == std::string::npos) ? std::string() : filename.substr(dot + 1);
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if(extension != "off" && extension != "obj" && extension != "ply" && extension != "stl")
    throw Error(Error_code::UNSUPPORTED_FORMAT,
                "cannot read '" + filename + "': unsupported file extension '"
                + (dot == std::string::npos ? std::string() : "." + extension)
                + "' (expected .off, .obj, .ply or .stl)");

  {
    std::ifstream probe(filename, std::ios::binary);
    if(!probe)
      throw Error(Error_code::FILE_NOT_READABLE, "cannot read '" + filename + "': " + std::strerror(errno));
    if(probe.peek() == std::ifstream::traits_type::eof())
      throw Error(Error_code::FILE_NOT_READABLE, "cannot read '" + filename + "': the file is empty");
  }

  std::vector<Point> points;
  std::vector<std::vector<std::size_t> > polygons;
  bool parsed = false;
  try
  {
    std::string bytes;
    if(extension == "off" || extension == "ply")
      parsed = internal::read_file_bytes(filename, bytes)
               && (extension == "off" ? internal::read_OFF(bytes, points, polygons)
                                      : internal::read_PLY(bytes, points, polygons));
    else
      parsed = (extension == "stl" && internal::read_binary_STL(filename, points, polygons))
               || CGAL::IO::read_polygon_soup(filename, points, polygons, CGAL::parameters::verbose(false));
  }
  catch(const std::exception& e)
  {
    throw Error(Error_code::FILE_NOT_READABLE, "cannot read '" + filename + "': " + e.what());
  }
  // CGAL's readers accept some malformed files; what no mesh format allows is refused here.
  std::string problem;
  if(!parsed)
    problem = "syntax error or truncated data";
  else if(extension == "stl" && polygons.empty())
    problem = "no complete triangle";
  for(std::size_t f = 0; problem.empty() && f < polygons.size(); ++f)
    if(polygons[f].size() < 3)
      problem = "face " + std::to_string(f) + " has fewer than 3 vertices";
  if(!problem.empty())
  {
    for(char& c : extension)
      c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    throw Error(Error_code::FILE_NOT_READABLE,
                "cannot read '" + filename + "': not a valid " + extension + " file (" + problem + ")");
  }

  internal::Polygon_mesh_test is_mesh;
  internal::repair_polygon_soup(points, polygons, repairs, repaired, is_mesh);
  Mesh_check_report report = check_polygon_soup<Kernel>(points, polygons);

  clear(mesh);
  const bool buildable = !polygons.empty() && report.count(Mesh_defect::INVALID_VERTEX_INDEX) == 0
                         && report.count(Mesh_defect::NON_MANIFOLD_VERTEX) == 0
                         && is_mesh(polygons);
  if(buildable)
  {
    Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, mesh);
    report.topology_available = true;
    report.components = internal::component_topologies(mesh);
  }
  return report;
}

} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_IO_READ_MESH_H
