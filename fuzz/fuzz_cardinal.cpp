// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Fuzz target: fair::Cardinal_spline_2 and optimal_cardinal_parameters (open and closed, decoded
// alpha, optimal and caller-given auxiliary points) on decoded point sets (fuzz_common.h).
// Oracle: alpha*, the energies, every piece and the evaluation at the global parameter finite;
// typed errors only (doc/fuzzing.md).

#include "fuzz_common.h"

#include <fair/Cardinal_spline_2.h>

#include <CGAL/Simple_cartesian.h>

namespace {

typedef CGAL::Simple_cartesian<double> K;
typedef K::Point_2 Point_2;
typedef fair::Cardinal_spline_2<K> Spline;
using fair_fuzz::require_finite;

void check_spline(const Spline& s, bool energy) {
  fair_fuzz::check_pieces(s.pieces());
  require_finite(s.alpha(), "alpha");
  require_finite(s.approximate_energy(), "approximate energy (eq. 10)");
  const double S = static_cast<double>(s.number_of_pieces());
  for (const double u : {0.0, 0.5 * S, S}) fair_fuzz::require_finite_point(s.point(u), "point(u)");
  for (std::size_t i = 0; i < s.number_of_pieces(); ++i)
    fair_fuzz::require_finite_vector(s.third_derivative(i), "third derivative");
  if (energy && s.number_of_pieces() <= 24) {  // the quadrature is the slow part: small curves only
    fair::Quadrature_options q;
    q.max_subintervals = 64;  // keeps one input well below the hang timeout
    try {
      const fair::Quadrature_estimate e = s.curvature_variation_energy(fair::Energy_measure::PARAMETER, q);
      require_finite(e.value, "curvature variation energy");
      require_finite(e.error_bound, "curvature variation error bound");
    } catch (const fair::Internal_error&) {
      throw;
    } catch (const fair::Error&) {
    }
  }
}

} // namespace

extern "C" int FAIR_FUZZ_ENTRY(cardinal)(const std::uint8_t* data, std::size_t size) {
  fair_fuzz::Fuzz_input in(data, size);
  const std::uint8_t head = in.byte();
  const bool closed = head & 1;
  const std::size_t mode = (head >> 1) % 4;  // optimal, alpha + optimal aux, alpha + given aux, Catmull-Rom
  const bool energy = head & 16;
  const double alpha = (head & 32) ? in.number() : (1 + in.byte()) / 128.0;
  std::vector<Point_2> p = in.kernel_points<Point_2>();
  const Point_2 a(in.number(), in.number()), b(in.number(), in.number());
  return fair_fuzz::run_guarded([&] {
    switch (mode) {
      case 0: {
        const fair::Cardinal_parameters<K> o = fair::optimal_cardinal_parameters(p, closed);
        require_finite(o.alpha, "alpha*");
        require_finite(o.energy, "energy at alpha*");
        fair_fuzz::require_finite_point(o.aux_start, "aux_start");
        fair_fuzz::require_finite_point(o.aux_end, "aux_end");
        check_spline(Spline::optimal(p, closed), energy);
        break;
      }
      case 1: {
        const std::pair<Point_2, Point_2> aux = fair::cardinal_auxiliary_points(p, alpha);
        fair_fuzz::require_finite_point(aux.first, "auxiliary point");
        fair_fuzz::require_finite_point(aux.second, "auxiliary point");
        check_spline(Spline(p, alpha, closed), energy);
        break;
      }
      case 2: check_spline(Spline(p, alpha, a, b), energy); break;
      default: check_spline(Spline::catmull_rom(p, a, b), energy); break;
    }
  });
}
