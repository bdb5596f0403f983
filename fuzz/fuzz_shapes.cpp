// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Fuzz target (issue 29): the design reader (fair/io/read_design.h), basic_shape_design (the merge
// of Fig. 9) and the exact conversion behind every shape (exact_spline), as `fair-curves shapes`
// runs them. The first byte chooses the kernel: double (Simple_cartesian<double>) or, for texts
// under 600 bytes, EPECK (the --exact path); the rest is the design file's text. Oracle
// (doc/fuzzing.md): typed errors only (a Parse_error names the file), and on success the
// merged spline's pieces, knots, control points and weights, the join distances and the merge
// distance all finite; spline_convexity (Proposition 1) answers with typed errors only.

#include "fuzz_common.h"

#include <fair/Basic_shape_design.h>
#include <fair/Spline_convexity.h>
#include <fair/io/read_design.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>

#include <string>

namespace {
// Named inside the unnamed namespace: fuzz_replay is one unity translation unit of every target
// (fuzz/CMakeLists.txt), whose file-local names must not clash.
namespace shapes_target {

typedef CGAL::Simple_cartesian<double> Kd;
typedef CGAL::Exact_predicates_exact_constructions_kernel Ke;

template <class K>
void run_design(const std::string& text) {
  fair::io::Design_file<K> f;
  if (!fair_fuzz::parsed_or_refused([&] { f = fair::io::parse_design<K>(text, "fuzz.json"); })) return;
  for (const auto& marks : f.marked_points)
    for (const auto& p : marks) fair_fuzz::require_finite_point(p, "marked point");
  const fair::Basic_shape_design_2<K> d = fair::basic_shape_design(f.shapes, f.options());
  fair_fuzz::require_finite(d.merge_distance, "merge distance");
  for (const fair::Shape_join& j : d.joins) fair_fuzz::require_finite(j.distance, "join distance");
  for (const auto& t : d.spline.breakpoints()) fair_fuzz::require_finite(CGAL::to_double(t), "breakpoint");
  for (const auto& c : d.spline.control_points()) fair_fuzz::require_finite_point(c, "spline control point");
  for (const auto& w : d.spline.weights()) fair_fuzz::require_finite(CGAL::to_double(w), "spline weight");
  // Evaluating EPECK pieces at 5 parameters is slow: the double kernel checks every piece.
  if constexpr (std::is_same<K, Kd>::value) fair_fuzz::check_pieces(d.spline.pieces());
  try {
    (void)fair::spline_convexity(d.spline);
  } catch (const fair::Internal_error&) {
    throw;
  } catch (const fair::Error&) {
  }
}

} // namespace shapes_target
} // namespace

extern "C" int FAIR_FUZZ_ENTRY(shapes)(const std::uint8_t* data, std::size_t size) {
  using namespace shapes_target;
  if (size == 0) return 0;
  const bool exact = (data[0] & 1) && size < 600;
  const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  return fair_fuzz::run_guarded([&] {
    if (exact) run_design<Ke>(text);
    else run_design<Kd>(text);
  });
}
