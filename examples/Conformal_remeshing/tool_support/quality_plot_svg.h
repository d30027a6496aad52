// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// An SVG picture in the style of the paper's Fig. 10: the proportion of angles and of
// equiangle skewness values per bin, side by side, with several meshes (before and after
// remeshing, for example) overlaid in translucent colours.

#ifndef CGAL_CONFORMAL_REMESHING_TOOLS_QUALITY_PLOT_SVG_H
#define CGAL_CONFORMAL_REMESHING_TOOLS_QUALITY_PLOT_SVG_H

#include <CGAL/Conformal_remeshing/mesh_quality.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace Conformal_remeshing_tools {

struct Plot_series
{
  std::string label;
  CGAL::Conformal_remeshing::Mesh_quality_report quality;
};

namespace internal {

inline std::string xml_escape(const std::string& text)
{
  std::string out;
  for(char c : text)
  {
    switch(c)
    {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

// The colours of the paper's Fig. 10: blue for the first series (the original), orange next.
inline const char* series_colour(std::size_t i)
{
  static const char* colours[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728"};
  return colours[i % 4];
}

// A tick spacing of 1, 2 or 5 times a power of ten giving about five ticks up to `max`.
inline double tick_step(double max)
{
  const double raw = max / 5.;
  const double power = std::pow(10., std::floor(std::log10(raw)));
  for(double m : {1., 2., 5.})
    if(m * power >= raw)
      return m * power;
  return 10. * power;
}

inline std::vector<double> proportions(const CGAL::Conformal_remeshing::Histogram& h)
{
  const double total = double((std::max)(h.total(), std::size_t(1)));
  std::vector<double> p;
  for(std::size_t c : h.counts)
    p.push_back(double(c) / total);
  return p;
}

struct Panel
{
  double x, y, width, height;
  double lower, upper;  // horizontal data range
  std::string title, axis_label;
  double label_step;    // spacing of the horizontal labels, in data units
};

inline void draw_panel(std::ostringstream& svg, const Panel& panel,
                       const std::vector<const CGAL::Conformal_remeshing::Histogram*>& histograms)
{
  double top = 0.;
  std::vector<std::vector<double> > series;
  for(const auto* h : histograms)
  {
    series.push_back(proportions(*h));
    top = (std::max)(top, *std::max_element(series.back().begin(), series.back().end()));
  }
  if(top <= 0.)
    top = 1.;
  const double step = tick_step(top);
  top = std::ceil(top / step) * step;

  auto sx = [&](double v) { return panel.x + (v - panel.lower) / (panel.upper - panel.lower) * panel.width; };
  auto sy = [&](double p) { return panel.y + panel.height - p / top * panel.height; };

  svg << "<text x='" << panel.x + panel.width / 2 << "' y='" << panel.y - 12
      << "' text-anchor='middle' font-size='15' font-weight='bold'>" << panel.title << "</text>\n";
  for(double p = 0.; p <= top + 1e-12; p += step)
  {
    svg << "<line x1='" << panel.x << "' x2='" << panel.x + panel.width << "' y1='" << sy(p) << "' y2='" << sy(p)
        << "' stroke='#dddddd'/>\n";
    svg << "<text x='" << panel.x - 6 << "' y='" << sy(p) + 4 << "' text-anchor='end' font-size='11'>" << p << "</text>\n";
  }
  for(double v = panel.lower; v <= panel.upper + 1e-12; v += panel.label_step)
    svg << "<text x='" << sx(v) << "' y='" << panel.y + panel.height + 16 << "' text-anchor='middle' font-size='11'>"
        << v << "</text>\n";
  svg << "<text x='" << panel.x + panel.width / 2 << "' y='" << panel.y + panel.height + 36
      << "' text-anchor='middle' font-size='12'>" << panel.axis_label << "</text>\n";
  svg << "<text transform='translate(" << panel.x - 42 << "," << panel.y + panel.height / 2
      << ") rotate(-90)' text-anchor='middle' font-size='12'>proportion</text>\n";

  for(std::size_t s = 0; s < histograms.size(); ++s)
  {
    const auto& h = *histograms[s];
    for(std::size_t b = 0; b < series[s].size(); ++b)
    {
      if(series[s][b] <= 0.)
        continue;
      const double x0 = sx(h.lower + double(b) * h.bin_width), x1 = sx(h.lower + double(b + 1) * h.bin_width);
      svg << "<rect x='" << x0 << "' y='" << sy(series[s][b]) << "' width='" << (std::max)(x1 - x0, 0.5)
          << "' height='" << sy(0.) - sy(series[s][b]) << "' fill='" << series_colour(s) << "' fill-opacity='0.6'/>\n";
    }
  }
  svg << "<rect x='" << panel.x << "' y='" << panel.y << "' width='" << panel.width << "' height='" << panel.height
      << "' fill='none' stroke='black'/>\n";
}

} // namespace internal

// The whole picture, as an SVG document.
inline std::string quality_histograms_svg(const std::vector<Plot_series>& series, const std::string& title)
{
  const double width = 1000, height = 430 + 20 * double(series.size());
  std::ostringstream svg;
  svg << "<?xml version='1.0' encoding='UTF-8'?>\n"
      << "<svg xmlns='http://www.w3.org/2000/svg' width='" << width << "' height='" << height
      << "' viewBox='0 0 " << width << " " << height << "' font-family='sans-serif'>\n"
      << "<rect width='100%' height='100%' fill='white'/>\n"
      << "<text x='" << width / 2 << "' y='24' text-anchor='middle' font-size='17'>" << internal::xml_escape(title) << "</text>\n";

  std::vector<const CGAL::Conformal_remeshing::Histogram*> angles, skewness;
  for(const Plot_series& s : series)
  {
    angles.push_back(&s.quality.angle_histogram);
    skewness.push_back(&s.quality.skewness_histogram);
  }
  internal::draw_panel(svg, {80, 70, 380, 290, 0., 180., "Angles", "angle (degrees)", 30.}, angles);
  internal::draw_panel(svg, {580, 70, 380, 290, 0., 1., "Equiangle skewness", "skewness", 0.2}, skewness);

  // One legend line per series, below the panels.
  for(std::size_t i = 0; i < series.size(); ++i)
  {
    const double y = 420 + 20 * double(i);
    svg << "<rect x='80' y='" << y - 12 << "' width='14' height='14' fill='" << internal::series_colour(i)
        << "' fill-opacity='0.6'/>\n"
        << "<text x='100' y='" << y << "' font-size='12'>" << internal::xml_escape(series[i].label) << "</text>\n";
  }
  svg << "</svg>\n";
  return svg.str();
}

} // namespace Conformal_remeshing_tools

#endif // CGAL_CONFORMAL_REMESHING_TOOLS_QUALITY_PLOT_SVG_H
