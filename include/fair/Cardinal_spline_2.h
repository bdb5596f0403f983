// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Cardinal spline curves and the parameter / auxiliary points that minimise their curvature
// variation, after J. Li, "Curvature variation minimizing Cardinal spline curves"
// ([Li] in doc/references.md; eq. numbers refer to it).
// The user manual is doc/cardinal_splines.md.
//
// Conventions. The segment on the four consecutive points (q0, q1, q2, q3) is (eqs. 1-2)
//     r(t) = b0(t) q0 + b1(t) q1 + b2(t) q2 + b3(t) q3,   t in [0,1],
//     b0 = -a t^3 + 2a t^2 - a t,        b1 = (2-a) t^3 + (a-3) t^2 + 1,
//     b2 = (a-2) t^3 + (3-2a) t^2 + a t, b3 = a t^3 - a t^2,
// with a = alpha = (1 - T)/2 (T the tension). It runs from q1 to q2 with end tangents
// alpha (q2 - q0) and alpha (q3 - q1) (eqs. 3-4): alpha = 1/2 is the (uniform) Catmull-Rom spline.
// It is the cubic Bezier piece q1, q1 + alpha (q2 - q0)/3, q2 - alpha (q3 - q1)/3, q2.
//
// Open curve on p_0..p_n: segments i = 0..n-1 run from p_i to p_{i+1} on (p_{i-1}, p_i, p_{i+1},
// p_{i+2}) with the auxiliary points p_{-1} and p_{n+1} (the paper numbers them r_{-1}..r_{n-2}).
// Closed curve on p_0..p_{N-1}: N segments, indices taken mod N; no auxiliary points.
//
// Exactness: construction, evaluation, Bezier conversion, the optimum of eqs. 18-20 and the
// energy of eq. 10 use +, -, *, / of Kernel::FT only, so they are exact in an exact kernel
// (EPECK, Simple_cartesian<Gmpq>) and ordinary rounded arithmetic in double.

#ifndef FAIR_CARDINAL_SPLINE_2_H
#define FAIR_CARDINAL_SPLINE_2_H

#include <fair/Bezier_2.h>
#include <fair/Errors.h>
#include <fair/Fairness_metrics.h>
#include <fair/internal/cardinal/optimum.h>
#include <fair/internal/classic/common.h>
#include <fair/internal/common/input_checks.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/number_utils.h>

#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace fair {

/// The optimum of eqs. 18-20 (open curve) or of its closed analogue (see doc/cardinal_splines.md):
/// the parameter alpha*, the auxiliary points (open curves only; for a closed curve they are
/// left equal to the first and last data point and are not used) and the energy of eq. 10 there.
template <class K>
struct Cardinal_parameters {
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  FT alpha;
  Point_2 aux_start;
  Point_2 aux_end;
  FT energy;
  bool closed;
};

/// The auxiliary points that minimise the energy of eq. 10 for a fixed alpha != 0 (eqs. 16-17,
/// solved as eqs. 19-20): p_{-1} = (1 - 2/alpha)(p_1 - p_0) + p_2 and
/// p_{n+1} = p_{n-2} - (1 - 2/alpha)(p_n - p_{n-1}). With them the two end segments have
/// r''' = 0 (they are parabolic arcs) and contribute nothing to eq. 10.
/// \throws Invalid_input_error for fewer than 3 points or bad points; Precondition_error if alpha == 0.
template <class Point_2>
std::pair<Point_2, Point_2> cardinal_auxiliary_points(const std::vector<Point_2>& p,
                                                      const typename CGAL::Kernel_traits<Point_2>::Kernel::FT& alpha) {
  internal::common::check_interpolation_input(p, 3, false, "cardinal_auxiliary_points");
  internal::require(!CGAL::is_zero(alpha), "cardinal_auxiliary_points: alpha = 0 has no optimal auxiliary points (eqs. 16-17 divide by alpha)");
  const std::pair<Point_2, Point_2> aux = internal::cardinal::auxiliary_points_unchecked(p, alpha);
  // A tiny alpha (1 - 2/alpha huge) or huge coordinates overflow double.
  internal::common::check_finite_points(std::vector<Point_2>{aux.first, aux.second},
                                        "cardinal_auxiliary_points (auxiliary points overflow)");
  return aux;
}

/// The minimiser of the approximate curvature variation energy of eq. 10.
///
/// Open curve (p_0..p_n, n >= 3): alpha* of eq. 18 (the sums run over the n-2 interior segments),
/// then p_{-1}*, p_{n+1}* of eqs. 19-20. Closed curve (N >= 3 points): alpha* = -2 M / D with the
/// sums of eq. 18 taken over all N segments (indices mod N) -- derivation in doc/cardinal_splines.md.
///
/// Degenerate data, reported by Invalid_input_error (never a division by zero):
///  - D = sum |d_i|^2 = 0 (the denominator of eq. 18; e.g. p_{i+2} + p_{i+3} = p_i + p_{i+1} for all
///    i, as for points alternating between two positions): eq. 10 does not depend on alpha, so there
///    is no unique optimum;
///  - alpha* <= 0: the infimum of eq. 10 over alpha > 0 is not attained (alpha* = 0) or the minimiser
///    reverses every tangent (alpha* < 0, cusps at the data points); happens only for data that fold
///    back on themselves. Callers wanting a fallback catch the error and use Catmull-Rom (alpha = 1/2).
/// Also throws Invalid_input_error for too few points, non-finite or duplicate consecutive points.
template <class Point_2>
Cardinal_parameters<typename CGAL::Kernel_traits<Point_2>::Kernel>
optimal_cardinal_parameters(const std::vector<Point_2>& p, bool closed = false) {
  typedef typename CGAL::Kernel_traits<Point_2>::Kernel K;
  typedef typename K::FT FT;
  const char* method = closed ? "optimal_cardinal_parameters (closed)" : "optimal_cardinal_parameters (open)";
  const internal::cardinal::Cardinal_sums<FT> s =
      internal::cardinal::checked_cardinal_interior_sums<FT>(p, closed ? 3 : 4, closed, method); // one pass
  const FT D = s.D(), M = s.M();
  if (CGAL::is_zero(D))
    throw Invalid_input_error(internal::message(
        method, ": the denominator of eq. 18, sum |d_i|^2 with d_i = -p_i - p_{i+1} + p_{i+2} + p_{i+3}, is 0 "
        "(the data alternate so that every d_i vanishes): the energy of eq. 10 does not depend on alpha and "
        "has no unique minimiser"));
  const FT alpha = -FT(2) * M / D; // eq. 18 (closed: same formula over all N segments)
  if (!CGAL::is_positive(alpha))
    throw Invalid_input_error(internal::message(
        method, ": the optimal parameter of eq. 18 is alpha* = ", CGAL::to_double(alpha),
        " <= 0 (sum d_i.m_i / sum |d_i|^2 = ", CGAL::to_double(M) / CGAL::to_double(D),
        "): the data fold back on themselves and no Cardinal spline with alpha > 0 minimises eq. 10; "
        "use a fixed alpha such as 1/2 (Catmull-Rom)"));
  Cardinal_parameters<K> out{alpha, p.front(), p.back(), internal::cardinal::checked_energy(s.energy(alpha), method),
                             closed};
  if (!closed) {
    const std::pair<Point_2, Point_2> aux = internal::cardinal::auxiliary_points_unchecked(p, alpha);
    internal::common::check_finite_points(std::vector<Point_2>{aux.first, aux.second},
                                          "optimal_cardinal_parameters (auxiliary points overflow)");
    out.aux_start = aux.first;
    out.aux_end = aux.second;
    // With the optimal auxiliary points the two end segments contribute 0 (see the doc page):
    // eq. 10 at the optimum is the interior energy only.
  }
  return out;
}

/// \brief A Cardinal spline curve (eqs. 1-2), open with two auxiliary points or closed.
///
/// Models a piecewise curve whose pieces are exactly cubic Bezier_2<K> pieces (pieces()).
template <class K>
class Cardinal_spline_2 {
public:
  typedef K Kernel;
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  typedef typename K::Vector_2 Vector_2;
  typedef Bezier_2<K> Piece;

  /// Open curve through p_0..p_n (n >= 1) with parameter alpha > 0 and the auxiliary points
  /// p_{-1} = aux_start, p_{n+1} = aux_end.
  /// \throws Invalid_input_error for bad data points or non-finite auxiliary points,
  ///         Precondition_error unless alpha > 0.
  Cardinal_spline_2(std::vector<Point_2> points, const FT& alpha, const Point_2& aux_start, const Point_2& aux_end)
    : p_(std::move(points)), alpha_(alpha), closed_(false) {
    internal::common::check_interpolation_input(p_, 2, false, "Cardinal_spline_2");
    internal::common::check_finite_points(std::vector<Point_2>{aux_start, aux_end}, "Cardinal_spline_2 (auxiliary points)");
    check_alpha();
    p_.insert(p_.begin(), aux_start);
    p_.push_back(aux_end);
    check_pieces();
  }

  /// Closed curve (closed = true, N >= 3 points, the last point is joined back to the first; do not
  /// repeat the first point) or open curve whose auxiliary points are the optimal ones of eqs. 19-20
  /// for this alpha (closed = false, n + 1 >= 3 points).
  Cardinal_spline_2(std::vector<Point_2> points, const FT& alpha, bool closed)
    : p_(std::move(points)), alpha_(alpha), closed_(closed) {
    if (closed) {
      internal::common::check_interpolation_input(p_, 3, true, "Cardinal_spline_2 (closed)");
      check_alpha();
    } else {
      check_alpha();
      const std::pair<Point_2, Point_2> aux = cardinal_auxiliary_points(p_, alpha_);
      p_.insert(p_.begin(), aux.first);
      p_.push_back(aux.second);
    }
    check_pieces();
  }

  /// The curve with the optimal parameter and auxiliary points of optimal_cardinal_parameters().
  static Cardinal_spline_2 optimal(const std::vector<Point_2>& points, bool closed = false) {
    const Cardinal_parameters<K> o = optimal_cardinal_parameters(points, closed);
    return closed ? Cardinal_spline_2(points, o.alpha, true) : Cardinal_spline_2(points, o.alpha, o.aux_start, o.aux_end);
  }

  /// The uniform Catmull-Rom spline (alpha = 1/2) with the given auxiliary points.
  static Cardinal_spline_2 catmull_rom(const std::vector<Point_2>& points, const Point_2& aux_start, const Point_2& aux_end) {
    return Cardinal_spline_2(points, FT(1) / FT(2), aux_start, aux_end);
  }

  const FT& alpha() const { return alpha_; }
  /// The tension T = 1 - 2 alpha (alpha = (1-T)/2, eq. 2).
  FT tension() const { return FT(1) - FT(2) * alpha_; }
  bool is_closed() const { return closed_; }

  /// The interpolated data points p_0..p_n (without auxiliary points).
  std::vector<Point_2> data_points() const {
    return closed_ ? p_ : std::vector<Point_2>(p_.begin() + 1, p_.end() - 1);
  }
  /// p_{-1} and p_{n+1}; \throws Precondition_error for a closed curve.
  const Point_2& aux_start() const {
    internal::require(!closed_, "Cardinal_spline_2::aux_start: a closed curve has no auxiliary points");
    return p_.front();
  }
  const Point_2& aux_end() const {
    internal::require(!closed_, "Cardinal_spline_2::aux_end: a closed curve has no auxiliary points");
    return p_.back();
  }

  /// Number of pieces (the paper's segments): n for an open curve on n+1 points, N for a closed
  /// one on N points.
  std::size_t number_of_pieces() const { return closed_ ? p_.size() : p_.size() - 3; }

  /// The four points (q0, q1, q2, q3) that define segment i (eq. 1).
  void segment_points(std::size_t i, const Point_2*& q0, const Point_2*& q1, const Point_2*& q2, const Point_2*& q3) const {
    check_segment(i);
    if (closed_) {
      const std::size_t N = p_.size();
      q0 = &p_[(i + N - 1) % N]; q1 = &p_[i]; q2 = &p_[(i + 1) % N]; q3 = &p_[(i + 2) % N];
    } else {
      q0 = &p_[i]; q1 = &p_[i + 1]; q2 = &p_[i + 2]; q3 = &p_[i + 3];
    }
  }

  /// r_i(t) (eq. 1), t in [0,1], exact in an exact kernel.
  Point_2 point(std::size_t i, const FT& t) const {
    FT b[4];
    basis(t, b);
    return combine(i, b);
  }
  /// r_i'(t).
  Vector_2 derivative(std::size_t i, const FT& t) const {
    const FT a = alpha_, t2 = t * t;
    FT b[4] = {-FT(3) * a * t2 + FT(4) * a * t - a, FT(3) * (FT(2) - a) * t2 + FT(2) * (a - FT(3)) * t,
               FT(3) * (a - FT(2)) * t2 + FT(2) * (FT(3) - FT(2) * a) * t + a, FT(3) * a * t2 - FT(2) * a * t};
    return combine(i, b) - CGAL::ORIGIN;
  }
  /// r_i''(t).
  Vector_2 second_derivative(std::size_t i, const FT& t) const {
    const FT a = alpha_;
    FT b[4] = {-FT(6) * a * t + FT(4) * a, FT(6) * (FT(2) - a) * t + FT(2) * (a - FT(3)),
               FT(6) * (a - FT(2)) * t + FT(2) * (FT(3) - FT(2) * a), FT(6) * a * t - FT(2) * a};
    return combine(i, b) - CGAL::ORIGIN;
  }
  /// r_i''' = 6 alpha d_i + 12 m_i, constant on the segment (eqs. 7-8).
  Vector_2 third_derivative(std::size_t i) const {
    const FT a = alpha_;
    FT b[4] = {-FT(6) * a, FT(12) - FT(6) * a, FT(6) * a - FT(12), FT(6) * a};
    return combine(i, b) - CGAL::ORIGIN;
  }

  /// The point at the global parameter u in [0, number_of_pieces()]: segment floor(u) (the last
  /// segment for u = number_of_pieces()) at t = u - floor(u).
  /// \throws Precondition_error for u outside that range.
  Point_2 point(const FT& u) const {
    const std::size_t S = number_of_pieces();
    internal::require(!(u < FT(0)) && !(FT(static_cast<double>(S)) < u), "Cardinal_spline_2::point: u = ",
                      CGAL::to_double(u), " is outside [0, ", S, "]");
    double f = std::floor(CGAL::to_double(u));
    std::size_t i = f < 0 ? 0 : static_cast<std::size_t>(f);
    if (i >= S) i = S - 1;
    // to_double may round an exact u across an integer: correct the segment index exactly.
    while (i > 0 && u < FT(static_cast<double>(i))) --i;
    while (i + 1 < S && !(u < FT(static_cast<double>(i + 1)))) ++i;
    return point(i, u - FT(static_cast<double>(i)));
  }

  /// Segment i as the cubic Bezier piece q1, q1 + alpha (q2 - q0)/3, q2 - alpha (q3 - q1)/3, q2
  /// (same parametrisation: piece(t) = r_i(t) identically).
  Piece piece(std::size_t i) const {
    const Point_2 *q0, *q1, *q2, *q3;
    segment_points(i, q0, q1, q2, q3);
    const FT c = alpha_ / FT(3);
    return Piece(*q1, Point_2(q1->x() + c * (q2->x() - q0->x()), q1->y() + c * (q2->y() - q0->y())),
                 Point_2(q2->x() - c * (q3->x() - q1->x()), q2->y() - c * (q3->y() - q1->y())), *q2);
  }
  /// All segments as cubic Bezier pieces, joined end to start (C^1 at the joins).
  std::vector<Piece> pieces() const {
    std::vector<Piece> out;
    out.reserve(number_of_pieces());
    for (std::size_t i = 0; i < number_of_pieces(); ++i) out.push_back(piece(i));
    return out;
  }

  /// The approximate curvature variation energy of eq. 10, sum over all segments of
  /// int_0^1 |r_i'''(t)|^2 dt (eq. 9), exact in an exact kernel. \throws Invalid_input_error
  /// if it overflows a floating-point FT (coordinates beyond ~1e150).
  FT approximate_energy() const {
    internal::cardinal::Cardinal_sums<FT> s;
    const Point_2 *q0, *q1, *q2, *q3;
    for (std::size_t i = 0; i < number_of_pieces(); ++i) {
      segment_points(i, q0, q1, q2, q3);
      s.add(*q0, *q1, *q2, *q3);
    }
    return internal::cardinal::checked_energy(s.energy(alpha_), "Cardinal_spline_2::approximate_energy");
  }

  /// The true curvature variation energy, summed over the segments:
  /// measure = Energy_measure::PARAMETER gives sum_i int_0^1 (d kappa/dt)^2 dt (eq. 5),
  /// measure = Energy_measure::ARC_LENGTH gives int (d kappa/ds)^2 ds. Adaptive Gauss-Kronrod
  /// quadrature with the error bound and caps of fair::curvature_variation_energy.
  Quadrature_estimate curvature_variation_energy(Energy_measure measure = Energy_measure::PARAMETER,
                                                 const Quadrature_options& options = Quadrature_options()) const {
    return fair::curvature_variation_energy(pieces(), measure, options);
  }

private:
  void check_alpha() const {
    internal::require(std::isfinite(CGAL::to_double(alpha_)) && CGAL::is_positive(alpha_),
                      "Cardinal_spline_2: alpha = ", CGAL::to_double(alpha_),
                      " must be finite and > 0 (alpha = (1 - tension)/2; alpha <= 0 collapses or reverses the tangents)");
  }
  // Finite data with a huge alpha or coordinates near 1e308 can give pieces (or derivatives)
  // that overflow double: refused (Invalid_input_error) rather than handed out with inf or NaN.
  void check_pieces() const {
    internal::classic::classic_check_finite_pieces(pieces(), "Cardinal_spline_2");
    for (std::size_t i = 0; i < number_of_pieces(); ++i) {
      const Vector_2 d3 = third_derivative(i);
      const double x = CGAL::to_double(d3.x()), y = CGAL::to_double(d3.y());
      if (!std::isfinite(x) || !std::isfinite(y))
        throw Invalid_input_error(internal::message("Cardinal_spline_2: the third derivative of segment ", i, " is (", x,
                                                    ", ", y, ") in this number type: the coordinates are too large"));
    }
  }
  void check_segment(std::size_t i) const {
    internal::require(i < number_of_pieces(), "Cardinal_spline_2: piece index ", i, " >= number of pieces ",
                      number_of_pieces());
  }
  void basis(const FT& t, FT* b) const { // eq. 2
    const FT a = alpha_, t2 = t * t, t3 = t2 * t;
    b[0] = -a * t3 + FT(2) * a * t2 - a * t;
    b[1] = (FT(2) - a) * t3 + (a - FT(3)) * t2 + FT(1);
    b[2] = (a - FT(2)) * t3 + (FT(3) - FT(2) * a) * t2 + a * t;
    b[3] = a * t3 - a * t2;
  }
  Point_2 combine(std::size_t i, const FT* b) const {
    const Point_2 *q0, *q1, *q2, *q3;
    segment_points(i, q0, q1, q2, q3);
    return Point_2(b[0] * q0->x() + b[1] * q1->x() + b[2] * q2->x() + b[3] * q3->x(),
                   b[0] * q0->y() + b[1] * q1->y() + b[2] * q2->y() + b[3] * q3->y());
  }

  std::vector<Point_2> p_; // open: p_{-1}, p_0..p_n, p_{n+1}; closed: p_0..p_{N-1}
  FT alpha_;
  bool closed_;
};

} // namespace fair

#endif // FAIR_CARDINAL_SPLINE_2_H
