// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Fuzz target: fair::Kappa_curve_2 (open and closed; unit, fixed and automatic weights) on
// decoded point sets (fuzz_common.h), then one warm re-solve after moving a point. Oracle:
// every piece, t_j, lambda_j, w_j and report number finite; the status one of the three; the
// point lists of the report valid indices; typed errors only (doc/fuzzing.md).

#include "fuzz_common.h"

#include <fair/Kappa_curve_2.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <sstream>

namespace {
// Named inside the unnamed namespace: fuzz_replay is one unity translation unit of every target
// (fuzz/CMakeLists.txt), whose file-local names must not clash.
namespace kappa_target {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_2 Point_2;
using fair_fuzz::require_finite;

void check_indices(const std::vector<std::size_t>& v, std::size_t n, const char* what) {
  for (std::size_t k = 0; k < v.size(); ++k)
    if (v[k] >= n || (k > 0 && v[k] <= v[k - 1]))
      fair_fuzz::fuzz_fail(std::string(what) + ": index list not increasing in [0, n)");
}

// With FAIR_FUZZ_VERBOSE set (replaying a finding), the input and the report of every solve.
void describe(const fair::Kappa_curve_2<K>& c) {
  if (!std::getenv("FAIR_FUZZ_VERBOSE")) return;
  std::fprintf(stderr, "closed %d, weights %d, %zu points:\n", int(c.is_closed()), int(c.options().weights),
               c.points().size());
  for (const Point_2& q : c.points()) std::fprintf(stderr, "  %.17g %.17g\n", q.x(), q.y());
  for (const double w : c.options().fixed_weights) std::fprintf(stderr, "  weight %.17g\n", w);
  std::ostringstream out;
  out << c.report();
  std::fprintf(stderr, "%s\n", out.str().c_str());
}

void check_curve(const fair::Kappa_curve_2<K>& c) {
  describe(c);
  const fair::Kappa_curve_report& r = c.report();
  const std::size_t n = c.points().size();
  if (c.number_of_pieces() != (c.is_closed() ? n : n - 2)) fair_fuzz::fuzz_fail("wrong number of pieces");
  fair_fuzz::check_pieces(c.pieces());
  for (std::size_t j = 0; j < c.number_of_pieces(); ++j) {
    require_finite(c.t(j), "t_j");
    require_finite(c.weight(j), "w_j");
    if (c.is_closed() || j > 0) require_finite(c.lambda(j), "lambda_j");
  }
  require_finite(c.normalisation_scale(), "normalisation scale");
  const double numbers[] = {r.residual, r.interpolation_residual, r.curvature_residual, r.g2_residual,
                            r.weight_residual, r.energy_interpolation, r.energy_curvature, r.energy_g2,
                            r.energy_weight, r.energy()};
  for (const double v : numbers) require_finite(v, "report number");
  if (r.status != fair::Kappa_curve_status::INTERIOR && r.status != fair::Kappa_curve_status::ON_JOINS &&
      r.status != fair::Kappa_curve_status::UNSOLVED)
    fair_fuzz::fuzz_fail("status out of range");
  if (r.status == fair::Kappa_curve_status::INTERIOR && !r.points_on_joins.empty())
    fair_fuzz::fuzz_fail("INTERIOR with points on joins");
  if (r.status != fair::Kappa_curve_status::UNSOLVED && !(r.residual <= c.options().tolerance))
    fair_fuzz::fuzz_fail("solved status with residual above the tolerance");
  check_indices(r.points_on_joins, n, "points_on_joins");
  check_indices(r.points_at_minima, n, "points_at_minima");
  check_indices(r.points_beyond_density_limit, n, "points_beyond_density_limit");
  if (r.status != fair::Kappa_curve_status::UNSOLVED && !r.points_beyond_density_limit.empty())
    fair_fuzz::fuzz_fail("points beyond the density limit listed for a solved curve");
  // An open curve has no estimate at its fixed ends nor at the points next to them.
  if (!c.is_closed())
    for (const std::size_t p : r.points_beyond_density_limit)
      if (p < 2 || p + 2 >= n) fair_fuzz::fuzz_fail("an open curve's end point listed beyond the density limit");
  for (const fair::Kappa_point_residual& p : r.worst_points) {
    if (p.point >= n) fair_fuzz::fuzz_fail("worst point index out of range");
    require_finite(p.residual, "worst point residual");
  }
}

} // namespace kappa_target
} // namespace

extern "C" int FAIR_FUZZ_ENTRY(kappa)(const std::uint8_t* data, std::size_t size) {
  using namespace kappa_target;
  fair_fuzz::Fuzz_input in(data, size);
  fair::Kappa_curve_options opt;
  const std::uint8_t head = in.byte();
  opt.closed = head & 1;
  opt.weights = static_cast<fair::Kappa_weights>((head >> 1) % 3);
  const bool odd_options = head & 8;  // decoded weights, tension and clamp instead of the defaults
  const bool move = head & 16;
  opt.throw_on_failure = head & 32;
  std::vector<Point_2> points = in.kernel_points<Point_2>();
  if (opt.weights == fair::Kappa_weights::FIXED || odd_options) {
    // One weight per point (sometimes a wrong count): mostly in [1/4, 4], sometimes any number.
    const std::size_t m = points.size() + (in.byte() == 255 ? 1 : 0);
    for (std::size_t i = 0; i < m; ++i) {
      const std::uint8_t b = in.byte();
      opt.fixed_weights.push_back(b < 240 ? std::ldexp(1.0 + b / 240.0, static_cast<int>(b % 5) - 2) : in.number());
    }
  }
  if (odd_options && opt.weights == fair::Kappa_weights::AUTOMATIC) {
    for (std::size_t i = 0; i < points.size(); ++i) {
      const std::uint8_t b = in.byte();
      opt.tension.push_back(b < 240 ? 0.25 + b / 60.0 : in.number());
    }
    const std::uint8_t b = in.byte();
    opt.weight_clamp = b < 240 ? 0.05 + b / 200.0 : in.number();
  }
  const std::size_t moved = in.byte();
  const std::pair<double, double> to(in.number(), in.number());
  return fair_fuzz::run_guarded([&] {
    fair::Kappa_curve_2<K> curve(points, opt);
    check_curve(curve);
    if (move && !points.empty()) {
      try {
        curve.move_point(moved % points.size(), Point_2(to.first, to.second));
      } catch (const fair::Internal_error&) {
        throw;
      } catch (const fair::Error&) {
        // refused: the curve must be unchanged and still valid
      }
      check_curve(curve);
    }
  });
}
