// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Fuzz target (issue 29): fair::Optimal_curve_2 with its options and its constraint and lambda
// files, as `fair-curves optimal` reads them. Decoded: an option byte (closed, solver,
// discretisation, lambda, derivative weights), a resolution from a small table (the vertex count is
// capped at 4000, the steps at 40 a level, 20 for conjugate gradients, so that one input stays
// under a second), the points (fuzz_common.h), then the rest of the input as text: the constraint
// file (its kind from a byte) and, after a byte 0x02, the lambda file (fair/io/read_constraints.h,
// read_numbers.h). Oracle (doc/fuzzing.md): typed errors only; on success the polygon's pieces,
// curvatures, energy and report finite, its levels' energies and gradient norms too. Findings
// inside include/fair/internal/optimal are kept in fuzz/findings/optimal/.

#include "fuzz_common.h"

#include <fair/Optimal_curve_2.h>
#include <fair/io/read_constraints.h>
#include <fair/io/read_numbers.h>

#include <CGAL/Simple_cartesian.h>

#include <string>

namespace {
// Named inside the unnamed namespace: fuzz_replay is one unity translation unit of every target
// (fuzz/CMakeLists.txt), whose file-local names must not clash.
namespace optimal_target {

typedef CGAL::Simple_cartesian<double> K;
typedef K::Point_2 Point_2;
using fair_fuzz::require_finite;

} // namespace optimal_target
} // namespace

extern "C" int FAIR_FUZZ_ENTRY(optimal)(const std::uint8_t* data, std::size_t size) {
  using namespace optimal_target;
  fair_fuzz::Fuzz_input in(data, size);
  const std::uint8_t head = in.byte(), more = in.byte();
  fair::Optimal_curve_options o;
  o.closed = head & 1;
  o.solver = (head & 2) ? fair::Optimal_curve_solver::CONJUGATE_GRADIENT : fair::Optimal_curve_solver::NEWTON;
  o.discretisation = static_cast<fair::Curvature_discretisation>((head >> 2) % 3);
  if (head & 16) o.lambda = (more & 1) ? in.number() : in.byte() / 255.0;
  if (head & 32) o.derivative_weight[1 + more % 4] = (more & 8) ? in.number() : in.byte() / 16.0;
  if (head & 64) o.curvature_exponent = 1 + in.byte() / 64.0;
  if (head & 128) o.length_weight = in.number();
  static const double resolutions[] = {5, 20, 50, 100, 200};
  o.resolution = (more & 16) ? in.number() : resolutions[(more >> 5) % 5];
  o.max_vertices = 4000;
  o.max_levels = 8;
  // The paper's conjugate-gradient optimiser takes 10-20 steps a level and runs every level to the
  // end (doc/optimal_curves.md); at 40 a level it spent 1.13 s under the sanitizers on 13 points
  // (8 levels x 40 steps, 136 vertices; 0.16 s in release): the work the caps allow, not a defect
  // (doc/fuzzing.md, session 21). Newton stops at its first capped level.
  o.max_iterations_per_level = o.solver == fair::Optimal_curve_solver::CONJUGATE_GRADIENT ? 20 : 40;
  o.throw_on_failure = more & 128;
  const std::vector<Point_2> p = in.kernel_points<Point_2>();
  const fair::Point_constraint_kind kind = static_cast<fair::Point_constraint_kind>(in.byte() % 3);
  std::string rest;
  while (!in.empty()) rest += static_cast<char>(in.byte());
  const std::size_t sep = rest.find('\x02');
  const std::string constraints = rest.substr(0, sep), lambdas = sep == std::string::npos ? "" : rest.substr(sep + 1);
  return fair_fuzz::run_guarded([&] {
    if (!constraints.empty())
      fair_fuzz::parsed_or_refused([&] {
        o.constraints = fair::io::merge_constraint_files(
            {fair::io::parse_constraints(constraints, "fuzz-constraints.txt", kind, p.size())});
      });
    if (!lambdas.empty())
      fair_fuzz::parsed_or_refused([&] {
        o.segment_lambda = fair::io::parse_segment_lambdas(lambdas, "fuzz-lambda.txt",
                                                           o.closed ? p.size() : (p.empty() ? 0 : p.size() - 1));
      });
    const bool verbose = std::getenv("FAIR_FUZZ_VERBOSE") != nullptr;
    if (verbose) { // before the solve, so that an input that throws is shown too
      std::fprintf(stderr, "closed %d solver %d disc %d lambda %.17g alpha0 %.17g beta %.17g beta0 %.17g rho %.17g throw %d\n",
                   int(o.closed), int(o.solver), int(o.discretisation), o.lambda, o.curvature_exponent, o.length_weight,
                   o.curvature_weight, o.resolution, int(o.throw_on_failure));
      for (const auto& d : o.derivative_weight) std::fprintf(stderr, "dw %.17g\n", d);
      for (const Point_2& q : p) std::fprintf(stderr, "p %.17g %.17g\n", q.x(), q.y());
      std::fprintf(stderr, "constraints %zu lambdas %zu\n", o.constraints.size(), o.segment_lambda.size());
    }
    const fair::Optimal_curve_2<K> c(p, o);
    if (verbose)
      std::fprintf(stderr, "status %d energy %g vertices %zu\n", int(c.report().status), c.energy(), c.polygon().size());
    require_finite(c.energy(), "energy");
    for (const double k : c.curvatures()) require_finite(k, "vertex curvature");
    require_finite(c.report().gradient_norm, "gradient norm");
    for (const fair::Optimal_curve_level& l : c.report().levels) {  // since session 20 (review R20)
      require_finite(l.energy, "level energy");
      require_finite(l.gradient_norm, "level gradient norm");
    }
    fair_fuzz::check_pieces(c.pieces());
  });
}
