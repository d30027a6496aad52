// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// JSON spelling of the library's reports, shared by the tools.

#ifndef CGAL_CONFORMAL_REMESHING_TOOLS_REPORT_JSON_H
#define CGAL_CONFORMAL_REMESHING_TOOLS_REPORT_JSON_H

#include "json_writer.h"

#include <CGAL/Conformal_remeshing/angles_at_sharp_corners.h>
#include <CGAL/Conformal_remeshing/check_mesh.h>
#include <CGAL/Conformal_remeshing/mesh_quality.h>

namespace Conformal_remeshing_tools {

namespace CR = CGAL::Conformal_remeshing;

inline void write_json(Json_writer& json, const CR::Mesh_check_report& r)
{
  json.begin_object();
  json.field("valid", r.is_valid());
  json.field("summary", r.summary());
  json.field("vertices", r.number_of_vertices);
  json.field("faces", r.number_of_faces);
  json.key("defects").begin_array();
  for(const CR::Defect_summary& d : r.defects)
    json.begin_object().field("defect", CR::defect_name(d.defect, 2)).field("count", d.count)
        .field("example", d.example).end_object();
  json.end_array();
  json.field("topology_available", r.topology_available);
  if(r.topology_available)
  {
    json.field("total_genus", r.total_genus());
    json.field("total_boundary_loops", r.total_boundary_loops());
    json.key("components").begin_array();
    for(const CR::Component_topology& c : r.components)
      json.begin_object().field("vertices", c.vertices).field("edges", c.edges).field("faces", c.faces)
          .field("boundary_loops", c.boundary_loops).field("euler_characteristic", c.euler_characteristic)
          .field("genus", c.genus).end_object();
    json.end_array();
  }
  json.end_object();
}

inline void write_json(Json_writer& json, const CR::Statistics& s)
{
  json.begin_object().field("min", s.min).field("mean", s.mean).field("max", s.max).end_object();
}

inline void write_json(Json_writer& json, const CR::Histogram& h)
{
  json.begin_object().field("lower", h.lower).field("bin_width", h.bin_width).array("counts", h.counts).end_object();
}

inline void write_json(Json_writer& json, const CR::Mesh_quality_report& q)
{
  json.begin_object();
  json.field("vertices", q.number_of_vertices).field("edges", q.number_of_edges).field("faces", q.number_of_faces);
  json.key("minimum_angle"); write_json(json, q.minimum_angle);
  json.key("maximum_angle"); write_json(json, q.maximum_angle);
  json.key("share_with_minimum_angle_below").begin_object();
  for(std::size_t i = 0; i < q.angle_thresholds.size(); ++i)
    json.field(std::to_string(int(q.angle_thresholds[i])), q.share_below[i]);
  json.end_object();
  json.key("equiangle_skewness"); write_json(json, q.skewness);
  json.key("aspect_ratio"); write_json(json, q.aspect_ratio);
  json.field("degenerate_faces", q.number_of_degenerate_faces);
  json.key("edge_length"); write_json(json, q.edge_length);
  json.field("median_edge_length", q.median_edge_length);
  json.array("valence_histogram", q.valence_histogram);
  json.key("angle_histogram"); write_json(json, q.angle_histogram);
  json.key("minimum_angle_histogram"); write_json(json, q.minimum_angle_histogram);
  json.key("skewness_histogram"); write_json(json, q.skewness_histogram);
  json.end_object();
}

inline void write_json(Json_writer& json, const CR::Sharp_corner_angles& a)
{
  json.begin_object().field("threshold_degrees", a.threshold_degrees).field("sharp_input_corners", a.sharp_corners)
      .field("triangles_below", a.triangles_below).field("triangles_below_at_sharp_input_corners", a.triangles_below_at_sharp_corners)
      .field("share_below_away_from_sharp_input_corners", a.share_below_away_from_sharp_corners()).end_object();
}

inline void write_json(Json_writer& json, const CR::Reference_comparison& c)
{
  json.begin_object();
  json.field("reference_diagonal", c.reference_diagonal);
  json.field("relative_hausdorff_to_reference", c.relative_distance_to_reference);
  json.field("relative_hausdorff_from_reference", c.relative_distance_from_reference);
  json.field("relative_hausdorff", c.relative_hausdorff_distance());
  json.field("area_ratio", c.area_ratio);
  json.field("self_intersects", c.self_intersects);
  for(const auto& farthest : {std::make_pair("farthest_point_to_reference", c.farthest_point_to_reference),
                              std::make_pair("farthest_point_from_reference", c.farthest_point_from_reference)})
  {
    json.key(farthest.first).begin_array();
    for(double x : farthest.second)
      json.value(x);
    json.end_array();
  }
  json.end_object();
}

} // namespace Conformal_remeshing_tools

#endif // CGAL_CONFORMAL_REMESHING_TOOLS_REPORT_JSON_H
