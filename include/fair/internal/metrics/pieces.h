// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// How the fairness metrics look inside a curve piece:
//  - kind_of<P> is the fair::Piece_kind of fair/Curve_traits.h: polynomial Bezier (fair::Bezier_2),
//    rational Bezier (control_points() and weights()) or generic (only the CurvePiece_2 concept);
//  - Piece_jet evaluates position and the first three derivatives in double, fast;
//  - homogeneous_exact() gives the exact homogeneous form (X, Y, W) as Bernstein polynomials over
//    CGAL::Gmpq, for certified root isolation.

#ifndef FAIR_INTERNAL_METRICS_PIECES_H
#define FAIR_INTERNAL_METRICS_PIECES_H

#include <fair/Bernstein_polynomial.h>
#include <fair/Curve_traits.h>
#include <fair/Errors.h>
#include <fair/internal/common/curvature.h>
#include <fair/internal/common/exact_conversion.h>

#include <CGAL/Gmpq.h>
#include <CGAL/Gmpz.h>
#include <gmp.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <type_traits>
#include <utility>
#include <vector>

namespace fair {
namespace internal {
namespace metrics {

// ---------------------------------------------------------------- classification
/// The kind of the piece type P (fair/Curve_traits.h).
template <class P>
constexpr Piece_kind kind_of = Piece_traits<P>::kind;

/// Control points and weights of a Bernstein-form piece (weights all 1 for polynomial pieces).
template <class P>
void bernstein_form(const P& piece, std::vector<typename P::Point_2>& cp, std::vector<typename P::FT>& w) {
  const auto& c = piece.control_points();
  cp.assign(c.begin(), c.end());
  if constexpr (kind_of<P> == Piece_kind::RATIONAL_BEZIER) {
    const auto& ws = piece.weights();
    w.assign(ws.begin(), ws.end());
    require(w.size() == cp.size(), "fairness metrics: a rational piece has ", cp.size(), " control points but ",
            w.size(), " weights");
  } else {
    w.assign(cp.size(), typename P::FT(1));
  }
}

// ---------------------------------------------------------------- double jets
/// Position and derivatives 1..3 at one parameter, in double.
struct Jet {
  double x = 0, y = 0, x1 = 0, y1 = 0, x2 = 0, y2 = 0, x3 = 0, y3 = 0;
  double speed() const { return std::hypot(x1, y1); }
  /// Signed curvature (c' x c'') / |c'|^3, scale-safe; 0 where c' = 0 (internal/common/curvature.h).
  double curvature() const { return common::signed_curvature(x1, y1, x2, y2); }
  // Divides by the speed s before multiplying, so that huge or tiny coordinates neither overflow
  // nor underflow (u = c'/s is a unit vector).
  /// d kappa / dt = (c' x c''') / |c'|^3 - 3 (c' x c'')(c'.c'') / |c'|^5.
  double curvature_derivative() const {
    const double s = speed(), ux = x1 / s, uy = y1 / s;
    const double a = (ux * (y3 / s) - uy * (x3 / s)) / s;
    const double b = (ux * (y2 / s) - uy * (x2 / s)), c = (ux * (x2 / s) + uy * (y2 / s));
    return a - 3 * b * c / s;
  }
};

/// A Bernstein polynomial in double with its derivative coefficient arrays, evaluated up to the
/// third derivative by de Casteljau (backward stable).
class Double_bernstein {
public:
  Double_bernstein() = default;
  explicit Double_bernstein(std::vector<double> b) {
    d_[0] = std::move(b);
    for (int k = 1; k <= 3; ++k) {
      const std::vector<double>& p = d_[k - 1];
      const double n = double(p.size()) - 1;
      if (p.size() <= 1) {
        d_[k].assign(1, 0.0);
        continue;
      }
      d_[k].resize(p.size() - 1);
      for (std::size_t i = 0; i + 1 < p.size(); ++i) d_[k][i] = n * (p[i + 1] - p[i]);
    }
  }
  void evaluate(double t, double* v, std::vector<double>& scratch) const {
    for (int k = 0; k <= 3; ++k) v[k] = de_casteljau(d_[k], t, scratch);
  }

private:
  static double de_casteljau(const std::vector<double>& b, double t, std::vector<double>& s) {
    s.assign(b.begin(), b.end());
    const double u = 1 - t;
    for (std::size_t r = s.size() - 1; r > 0; --r)
      for (std::size_t i = 0; i < r; ++i) s[i] = u * s[i] + t * s[i + 1];
    return s[0];
  }
  std::vector<double> d_[4];
};

/// Step of the central difference of second derivatives giving the third derivative of a generic
/// piece: the truncation error h^2 |c^(5)| / 6 and the rounding error eps |c''| / h balance near
/// 1e-4..1e-5; 1e-4 gives about 1e-8 relative for smooth pieces.
constexpr double generic_third_derivative_step = 1e-4;

/// Evaluates Jets of one piece. Bernstein-form pieces are converted to double once; a generic piece
/// is evaluated through its concept functions, with the third derivative by a central difference
/// of second derivatives (step 1e-4: relative error about 1e-8 for smooth pieces).
template <class P>
class Piece_jet {
public:
  typedef typename P::FT FT;
  explicit Piece_jet(const P& piece) : piece_(&piece) {
    if constexpr (is_bernstein_form(kind_of<P>)) {
      std::vector<typename P::Point_2> cp;
      std::vector<FT> w;
      bernstein_form(piece, cp, w);
      std::vector<double> X(cp.size()), Y(cp.size()), W(cp.size());
      for (std::size_t i = 0; i < cp.size(); ++i) {
        const double wi = CGAL::to_double(w[i]);
        X[i] = wi * CGAL::to_double(cp[i].x());
        Y[i] = wi * CGAL::to_double(cp[i].y());
        W[i] = wi;
      }
      X_ = Double_bernstein(std::move(X));
      Y_ = Double_bernstein(std::move(Y));
      W_ = Double_bernstein(std::move(W));
    }
  }

  /// The jet at t. Derivatives above `order` (1..3) may be left 0: only a generic piece saves work
  /// with that (its third derivative costs two more evaluations).
  Jet operator()(double t, int order = 3) const {
    Jet j;
    if constexpr (is_bernstein_form(kind_of<P>)) {
      double X[4], Y[4], W[4];
      X_.evaluate(t, X, scratch_);
      Y_.evaluate(t, Y, scratch_);
      if constexpr (kind_of<P> == Piece_kind::POLYNOMIAL_BEZIER) {
        j.x = X[0]; j.y = Y[0]; j.x1 = X[1]; j.y1 = Y[1]; j.x2 = X[2]; j.y2 = Y[2]; j.x3 = X[3]; j.y3 = Y[3];
      } else {
        W_.evaluate(t, W, scratch_);
        // Quotient rule on c = (X, Y) / W:  W c^(k) = X^(k) - sum_{j<k} C(k,j) W^(k-j) c^(j).
        const double iw = 1 / W[0];
        j.x = X[0] * iw;
        j.y = Y[0] * iw;
        j.x1 = (X[1] - W[1] * j.x) * iw;
        j.y1 = (Y[1] - W[1] * j.y) * iw;
        j.x2 = (X[2] - 2 * W[1] * j.x1 - W[2] * j.x) * iw;
        j.y2 = (Y[2] - 2 * W[1] * j.y1 - W[2] * j.y) * iw;
        j.x3 = (X[3] - 3 * W[1] * j.x2 - 3 * W[2] * j.x1 - W[3] * j.x) * iw;
        j.y3 = (Y[3] - 3 * W[1] * j.y2 - 3 * W[2] * j.y1 - W[3] * j.y) * iw;
      }
    } else {
      const auto p = piece_->point(FT(t));
      const auto d1 = piece_->derivative(FT(t));
      const auto d2 = piece_->second_derivative(FT(t));
      j.x = CGAL::to_double(p.x()); j.y = CGAL::to_double(p.y());
      j.x1 = CGAL::to_double(d1.x()); j.y1 = CGAL::to_double(d1.y());
      j.x2 = CGAL::to_double(d2.x()); j.y2 = CGAL::to_double(d2.y());
      if (order < 3) return j;
      // Second-order differences that stay inside [0,1] (pieces may reject other parameters):
      // central inside, one-sided three-point formulas within h of an end.
      const double h = generic_third_derivative_step;
      auto second = [&](double u, double& x, double& y) {
        const auto v = piece_->second_derivative(FT(u));
        x = CGAL::to_double(v.x());
        y = CGAL::to_double(v.y());
      };
      double ax, ay, bx, by, cx, cy;
      if (t - h >= 0 && t + h <= 1) {
        second(t - h, ax, ay);
        second(t + h, bx, by);
        j.x3 = (bx - ax) / (2 * h);
        j.y3 = (by - ay) / (2 * h);
      } else {
        const double s = (t - h < 0) ? h : -h; // step into the interval
        second(t + s, bx, by);
        second(t + 2 * s, cx, cy);
        j.x3 = (-3 * j.x2 + 4 * bx - cx) / (2 * s);
        j.y3 = (-3 * j.y2 + 4 * by - cy) / (2 * s);
      }
    }
    return j;
  }

private:
  const P* piece_;
  Double_bernstein X_, Y_, W_;
  mutable std::vector<double> scratch_;
};

/// Rejects an empty curve: every metric needs at least one piece. Returns `what`.
template <class Piece>
const char* check_curve(const std::vector<Piece>& curve, const char* what) {
  require(!curve.empty(), what, ": the curve has no piece");
  return what;
}

// ---------------------------------------------------------------- exact homogeneous form
/// The homogeneous form (X, Y, W) = (sum B_i w_i x_i, sum B_i w_i y_i, sum B_i w_i) of a
/// Bernstein-form piece over the rationals (W = 1 of degree 0 for polynomial pieces), exact:
/// every coordinate and weight is converted by internal::common::to_gmpq, exact for every number
/// type it accepts (a double is the dyadic rational it stores).
struct Homogeneous_form {
  Bernstein_polynomial<CGAL::Gmpq> X, Y, W;
};

/// Scales the coefficients of X, Y, W by one positive rational so that they become integers with
/// no common factor: multiplies by the lcm of their denominators, divides by the gcd of the
/// numerators. Every polynomial built from the form (D, N of the features, G of the circle
/// deviation) is homogeneous in (X, Y, W) of a fixed degree k, so the scaling multiplies it by a
/// positive constant^k: its roots and signs are unchanged. Why: with coordinates p/q of distinct
/// denominators, every coefficient of a product over the rationals carries the lcm of many
/// denominators and each rational operation a gcd of that size (issue 29 #4: a degree-30 piece
/// with random 12-digit p/q spent 11 s in GMP's gcd building N, before the size cap sampled it).
/// In integer form the size of the form is what the products will carry, so the cap on it
/// (features.h) decides before any product, and the arithmetic has no large gcds.
inline void make_primitive_integer(std::vector<CGAL::Gmpq>& X, std::vector<CGAL::Gmpq>& Y, std::vector<CGAL::Gmpq>& W) {
  struct Integer {  // an mpz_t that clears itself
    mpz_t v;
    Integer() { mpz_init(v); }
    ~Integer() { mpz_clear(v); }
    Integer(const Integer&) = delete;
    Integer& operator=(const Integer&) = delete;
  } l, g;
  mpz_set_ui(l.v, 1);
  for (const std::vector<CGAL::Gmpq>* p : {&X, &Y, &W})
    for (const CGAL::Gmpq& c : *p) mpz_lcm(l.v, l.v, mpq_denref(c.mpq()));
  const CGAL::Gmpq scale{CGAL::Gmpz(l.v)};
  for (std::vector<CGAL::Gmpq>* p : {&X, &Y, &W})
    for (CGAL::Gmpq& c : *p) {
      c = c * scale;
      mpz_gcd(g.v, g.v, mpq_numref(c.mpq()));
    }
  if (mpz_cmp_ui(g.v, 1) <= 0) return;  // all zero (not a valid piece) or already primitive
  const CGAL::Gmpq inverse(CGAL::Gmpz(1), CGAL::Gmpz(g.v));
  for (std::vector<CGAL::Gmpq>* p : {&X, &Y, &W})
    for (CGAL::Gmpq& c : *p) c = c * inverse;
}

template <class P>
Homogeneous_form homogeneous_exact(const P& piece) {
  using common::to_gmpq;
  std::vector<typename P::Point_2> cp;
  std::vector<typename P::FT> w;
  bernstein_form(piece, cp, w);
  std::vector<CGAL::Gmpq> X, Y, W;
  for (std::size_t i = 0; i < cp.size(); ++i) {
    const CGAL::Gmpq wi = to_gmpq(w[i]);
    X.push_back(wi * to_gmpq(cp[i].x()));
    Y.push_back(wi * to_gmpq(cp[i].y()));
    W.push_back(wi);
  }
  if (kind_of<P> == Piece_kind::POLYNOMIAL_BEZIER) W.assign(1, CGAL::Gmpq(1));
  make_primitive_integer(X, Y, W);
  Homogeneous_form h;
  h.X = Bernstein_polynomial<CGAL::Gmpq>(X);
  h.Y = Bernstein_polynomial<CGAL::Gmpq>(Y);
  h.W = Bernstein_polynomial<CGAL::Gmpq>(W);
  return h;
}

/// Caps on the work of certifying exact polynomials (D or N of the features, G of the circle
/// deviation), measured as the polynomial's size in bits (summed over the numerators and
/// denominators of its Bernstein coefficients) times (degree + 1)^2: building it (products of
/// the form's polynomials) and isolating its roots (Descartes' rule on Bernstein coefficients)
/// both grow about so. Measured (release, one piece, doc/fairness_metrics.md): 5.6e8 -> 0.15 s,
/// 1.5e9 -> 0.33 s, 4.6e9 -> 2.4 s, 1.2e10 -> 2.2 s; the 59 exact cubics of `cardinal --exact`
/// through 60 points: 1.0e9 in all, 0.11 s. A piece whose work would exceed either cap is
/// sampled instead (certified = false, reported):
///  - one piece: 1e8 (about 0.03 s in release; the fuzz build, whose Gmpq wrappers allocate
///    through ASan, is several times slower); a rational cubic with 12-digit p/q coordinates
///    needs 2e7, the old cap of 60 000 bits allowed about 2e7 for a cubic, 8e7 for a quintic;
///  - one curve: max(1e9, 3e7 per piece) for each feature kind, so that a file of pieces each
///    just under the piece cap is not 100 x 0.03 s (issue 29's oracle: under 1 s below 100
///    pieces), while the program's own exact curves (at most 2e7 a piece, as above) stay
///    certified at any length.
constexpr double max_certified_piece_work = 1e8;
constexpr double min_certified_curve_work = 1e9;
constexpr double certified_work_per_piece = 3e7;

/// The size of an exact Bernstein polynomial in bits.
inline std::size_t polynomial_bits(const Bernstein_polynomial<CGAL::Gmpq>& p) {
  std::size_t bits = 0;
  for (const CGAL::Gmpq& c : p.coefficients())
    bits += mpz_sizeinbase(mpq_numref(c.mpq()), 2) + mpz_sizeinbase(mpq_denref(c.mpq()), 2);
  return bits;
}

/// The work of certifying p: bits * (degree + 1)^2.
inline double polynomial_work(const Bernstein_polynomial<CGAL::Gmpq>& p) {
  const double d1 = static_cast<double>(p.degree()) + 1;
  return static_cast<double>(polynomial_bits(p)) * d1 * d1;
}

/// The work of a polynomial homogeneous of degree k in the (primitive integer) form h, of degree
/// k deg(h) - degree_drop, predicted before it is built (building costs more than isolating):
/// its coefficients have about k times the bits of the form's largest one (the binomial factors
/// of the Bernstein products add O(k deg) bits: the prediction is 0.7-1.0 of the actual size,
/// measured). D of the features: k = 3, degree 3d - 3; N: k = 8, degree 8d - 6; G of the circle
/// deviation: k = 3, degree 3d - 1.
inline double predicted_work(const Homogeneous_form& h, std::size_t k, std::size_t degree_drop) {
  std::size_t largest = 0, degree = 0;
  for (const Bernstein_polynomial<CGAL::Gmpq>* p : {&h.X, &h.Y, &h.W}) {
    degree = std::max(degree, p->degree());
    for (const CGAL::Gmpq& c : p->coefficients()) largest = std::max(largest, mpz_sizeinbase(mpq_numref(c.mpq()), 2));
  }
  const double d1 = static_cast<double>(k * degree > degree_drop ? k * degree - degree_drop : 0) + 1;
  return d1 * static_cast<double>(k * largest) * d1 * d1;
}

/// The certification work left for one curve (see max_certified_piece_work).
class Certification_budget {
public:
  explicit Certification_budget(std::size_t pieces)
      : left_(std::max(min_certified_curve_work, certified_work_per_piece * static_cast<double>(pieces))) {}
  /// Whether one piece may spend `work`.
  bool allows(double work) const { return work <= max_certified_piece_work && work <= left_; }
  /// Takes `work` from the budget if one piece may spend it; false (nothing taken) otherwise.
  bool take(double work) {
    if (!allows(work)) return false;
    left_ -= work;
    return true;
  }

private:
  double left_;
};

} // namespace metrics
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_METRICS_PIECES_H
