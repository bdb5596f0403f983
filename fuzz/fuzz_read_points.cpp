// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Fuzz target: the CSV and JSON point readers of fair/io/read_points.h on raw text (the first
// byte chooses CSV, JSON or the sniffing of is_json_point_text; the rest is the file). Each
// text is read into Simple_cartesian<double> and into EPECK (exact rationals "p/q" take the
// exact path of to_ft there). Oracle: Parse_error (or another typed error) or a point file
// whose points are finite, whose line numbers are increasing and inside the text, and which
// both kernels read alike (same outcome, same count, same lines, same closed flag);
// check_point_file on the result throws typed errors only (doc/fuzzing.md).

#include "fuzz_common.h"

#include <fair/io/read_points.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>

namespace {
// Named inside the unnamed namespace: fuzz_replay is one unity translation unit of every target
// (fuzz/CMakeLists.txt), whose file-local names must not clash.
namespace read_points_target {

typedef CGAL::Simple_cartesian<double> Kd;
typedef CGAL::Exact_predicates_exact_constructions_kernel Ke;

template <class K>
bool read(const std::string& text, std::size_t how, fair::io::Point_file<K>& out) {
  return fair_fuzz::parsed_or_refused([&] {
    if (how == 0)
      out = fair::io::parse_points_csv<K>(text, "fuzz.csv");
    else if (how == 1)
      out = fair::io::parse_points_json<K>(text, "fuzz.json");
    else
      out = fair::io::is_json_point_text("fuzz", text) ? fair::io::parse_points_json<K>(text, "fuzz")
                                                       : fair::io::parse_points_csv<K>(text, "fuzz");
  });
}

template <class K>
void check_file(const fair::io::Point_file<K>& f, const std::string& text) {
  if (f.points.empty()) fair_fuzz::fuzz_fail("a point file without points");
  if (f.points.size() != f.lines.size()) fair_fuzz::fuzz_fail("points and lines differ in number");
  const std::size_t lines = static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')) + 1;
  for (std::size_t i = 0; i < f.points.size(); ++i) {
    fair_fuzz::require_finite_point(f.points[i], "point read");
    if (f.lines[i] == 0 || f.lines[i] > lines || (i > 0 && f.lines[i] < f.lines[i - 1]))
      fair_fuzz::fuzz_fail("line number out of order or outside the text");
  }
  for (const bool closed : {false, true}) {
    try {
      fair::io::check_point_file(f, 3, closed, "fuzz");
    } catch (const fair::Internal_error&) {
      throw;
    } catch (const fair::Error&) {
    }
  }
}

} // namespace read_points_target
} // namespace

extern "C" int FAIR_FUZZ_ENTRY(read_points)(const std::uint8_t* data, std::size_t size) {
  using namespace read_points_target;
  if (size == 0) return 0;
  const std::size_t how = data[0] % 3;
  const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  return fair_fuzz::run_guarded([&] {
    fair::io::Point_file<Kd> fd;
    fair::io::Point_file<Ke> fe;
    const bool ok_d = read(text, how, fd), ok_e = read(text, how, fe);
    if (ok_d != ok_e) fair_fuzz::fuzz_fail("the double and the exact kernel disagree on accepting the text");
    if (!ok_d) return;
    check_file(fd, text);
    check_file(fe, text);
    if (fd.points.size() != fe.points.size() || fd.lines != fe.lines || fd.closed != fe.closed ||
        fd.closed_given != fe.closed_given)
      fair_fuzz::fuzz_fail("the double and the exact kernel read different point files");
    for (std::size_t i = 0; i < fd.points.size(); ++i) {
      // Both kernels start from the same correctly rounded double, except exact rationals.
      const double ex = CGAL::to_double(fe.points[i].x()), ey = CGAL::to_double(fe.points[i].y());
      const double dx = fd.points[i].x(), dy = fd.points[i].y();
      if (std::fabs(ex - dx) > 1e-15 * std::fabs(dx) || std::fabs(ey - dy) > 1e-15 * std::fabs(dy))
        fair_fuzz::fuzz_fail("the double and the exact kernel read different coordinates");
    }
  });
}
