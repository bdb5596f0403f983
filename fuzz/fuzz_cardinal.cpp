// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Fuzz target: fair::Cardinal_spline_2 and optimal_cardinal_parameters (open and closed, decoded
// alpha, optimal and caller-given auxiliary points) on decoded point sets (fuzz_common.h).
// Oracle: alpha*, the energies, every piece and the evaluation at the global parameter finite;
// typed errors only (doc/fuzzing.md).

#include "fuzz_common.h"

#include <fair/Cardinal_spline_2.h>
#include <fair/Fairness_metrics.h>

#include <CGAL/Simple_cartesian.h>

namespace {
// Named inside the unnamed namespace: fuzz_replay is one unity translation unit of every target
// (fuzz/CMakeLists.txt), whose file-local names must not clash.
namespace cardinal_target {

typedef CGAL::Simple_cartesian<double> K;
typedef K::Point_2 Point_2;
typedef fair::Cardinal_spline_2<K> Spline;
using fair_fuzz::require_finite;

void check_spline(const Spline& s, bool energy) {
  fair_fuzz::check_pieces(s.pieces());
  require_finite(s.alpha(), "alpha");
  require_finite(s.approximate_energy(), "approximate energy (eq. 10)");
  require_finite(s.report().alpha, "report alpha");
  fair_fuzz::require_finite_point(s.report().aux_start, "report aux_start");
  fair_fuzz::require_finite_point(s.report().aux_end, "report aux_end");
  if (s.number_of_pieces() != s.pieces().size()) fair_fuzz::fuzz_fail("number_of_pieces() != pieces().size()");
  const double S = static_cast<double>(s.number_of_pieces());
  for (const double u : {0.0, 0.5 * S, S}) fair_fuzz::require_finite_point(s.point(u), "point(u)");
  for (std::size_t i = 0; i < s.number_of_pieces(); ++i)
    fair_fuzz::require_finite_vector(s.third_derivative(i), "third derivative");
  if (energy && s.number_of_pieces() <= 24) {  // the quadrature is the slow part: small curves only
    fair::Quadrature_options q;
    q.max_subintervals = 64;  // keeps one input well below the hang timeout
    try {
      const fair::Quadrature_estimate e = fair::curvature_variation_energy(s.pieces(), fair::Energy_measure::PARAMETER, q);
      require_finite(e.value, "curvature variation energy");
      require_finite(e.error_bound, "curvature variation error bound");
    } catch (const fair::Internal_error&) {
      throw;
    } catch (const fair::Error&) {
    }
  }
}

} // namespace cardinal_target
} // namespace

extern "C" int FAIR_FUZZ_ENTRY(cardinal)(const std::uint8_t* data, std::size_t size) {
  using namespace cardinal_target;
  fair_fuzz::Fuzz_input in(data, size);
  const std::uint8_t head = in.byte();
  const bool closed = head & 1;
  const std::size_t mode = (head >> 1) % 4;  // optimal, alpha + optimal aux, alpha + given aux, Catmull-Rom
  fair::Cardinal_spline_options options;
  options.closed = closed;
  options.throw_on_failure = head & 64;  // NO_OPTIMUM: a Solve_error (a typed fair::Error), or Catmull-Rom
  const bool energy = head & 16;
  const double alpha = (head & 32) ? in.number() : (1 + in.byte()) / 128.0;
  std::vector<Point_2> p = in.kernel_points<Point_2>();
  const Point_2 a(in.number(), in.number()), b(in.number(), in.number());
  return fair_fuzz::run_guarded([&] {
    switch (mode) {
      case 0: {
        // The class first (its NO_OPTIMUM fallback is Catmull-Rom), then the engine (which throws there).
        const Spline s(p, options);
        check_spline(s, energy);
        const fair::Cardinal_parameters<K> o = fair::optimal_cardinal_parameters(p, closed);
        require_finite(o.alpha, "alpha*");
        require_finite(o.energy, "energy at alpha*");
        fair_fuzz::require_finite_point(o.aux_start, "aux_start");
        fair_fuzz::require_finite_point(o.aux_end, "aux_end");
        if (s.status() != fair::Cardinal_spline_status::OPTIMAL) fair_fuzz::fuzz_fail("the engine found alpha* but the class did not");
        break;
      }
      case 1: {
        const std::pair<Point_2, Point_2> aux = fair::cardinal_auxiliary_points(p, alpha);
        fair_fuzz::require_finite_point(aux.first, "auxiliary point");
        fair_fuzz::require_finite_point(aux.second, "auxiliary point");
        check_spline(Spline(p, alpha, options), energy);
        break;
      }
      case 2: check_spline(Spline(p, alpha, a, b), energy); break;
      default: check_spline(Spline(p, 0.5, a, b), energy); break;
    }
  });
}
