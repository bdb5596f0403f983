// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The curve exports every curve command of fair-curves offers, in one place (issue 26):
//   --dxf OUT.dxf        the curve's NURBS as an R2000 DXF SPLINE (fair/io/write_dxf.h)
//   --svg-path OUT.txt   the curve as an SVG path `d` attribute (fair/io/write_svg_path.h: exact
//                        L/Q/C for polynomial pieces of degree <= 3, certified cubics within
//                        1e-6 of the curve's extent otherwise)
// A command adds them with add_export_options(sub) and passes its output files through
// export_files(curve.nurbs(), files) to write_outputs, so that the exports are made (and may
// fail) before anything is written. One subcommand runs per process: the request is one object.

#ifndef FAIR_CURVES_EXPORT_OPTIONS_H
#define FAIR_CURVES_EXPORT_OPTIONS_H

#include <fair/Nurbs_curve_2.h>
#include <fair/io/write_dxf.h>
#include <fair/io/write_svg_path.h>

#include <CLI/CLI.hpp>

#include <string>
#include <utility>
#include <vector>

namespace fair_curves {

/// The files the parsed subcommand asked for (empty: not asked).
struct Export_request {
  std::string dxf, svg_path;
};

inline Export_request& export_request() {
  static Export_request request;
  return request;
}

/// Adds --dxf and --svg-path to a curve command.
inline void add_export_options(CLI::App* sub) {
  sub->add_option("--dxf", export_request().dxf,
                  "write the curve as a DXF drawing (R2000, one SPLINE: the exact NURBS in 17-digit doubles)");
  sub->add_option("--svg-path", export_request().svg_path,
                  "write the curve as an SVG path d attribute (exact Q/C for polynomial pieces; rational pieces as "
                  "cubics within 1e-6 of the curve's extent)");
}

/// `files` plus the exports asked for, of the curves `curves` (the DXF has one SPLINE each; the
/// SVG path one subpath each, one line each).
template <class K>
std::vector<std::pair<std::string, std::string>> export_files(const std::vector<fair::Nurbs_curve_2<K>>& curves,
                                                              std::vector<std::pair<std::string, std::string>> files = {}) {
  const Export_request& r = export_request();
  if (!r.dxf.empty()) files.emplace_back(r.dxf, fair::io::dxf_text(curves));
  if (!r.svg_path.empty()) {
    std::string text;
    for (const auto& c : curves) text += fair::io::svg_path(c).d + "\n";
    files.emplace_back(r.svg_path, text);
  }
  return files;
}

template <class K>
std::vector<std::pair<std::string, std::string>> export_files(const fair::Nurbs_curve_2<K>& curve,
                                                              std::vector<std::pair<std::string, std::string>> files = {}) {
  return export_files(std::vector<fair::Nurbs_curve_2<K>>{curve}, std::move(files));
}

} // namespace fair_curves

#endif // FAIR_CURVES_EXPORT_OPTIONS_H
