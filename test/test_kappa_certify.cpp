// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Exact certification of kappa-curves (fair::certify): the curve rebuilt exactly from its
// rational lambda_i, t_i, w_i interpolates exactly, is exactly G1, has exactly one curvature
// maximum per piece near t_i, and matches |kappa| at the joins within a certified interval.
// fair::certify_pieces: the returned pieces themselves, certified piece by piece in O(n).

#include <fair/Kappa_certificate.h>
#include <fair/Kappa_curve_2.h>
#include <fair/internal/classic/tridiagonal.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace {

typedef CGAL::Simple_cartesian<double> Kd;
typedef CGAL::Exact_predicates_exact_constructions_kernel Epeck;

TEST(KappaCertify, PublishedCurveInEpeck) {
  const std::vector<Epeck::Point_2> q = {Epeck::Point_2(-1, 0), Epeck::Point_2(0, 1), Epeck::Point_2(1, 0),
                                         Epeck::Point_2(2, 1)};
  const fair::Kappa_curve_2<Epeck> curve(q);
  const fair::Kappa_certificate c = fair::certify(curve);
  ASSERT_EQ(c.pieces.size(), 2u);
  ASSERT_EQ(c.joins.size(), 1u);
  EXPECT_TRUE(c.all_points_on_pieces()) << c;
  EXPECT_TRUE(c.all_unique_maxima()) << c;
  EXPECT_TRUE(c.all_g1()) << c;
  EXPECT_LE(c.max_kappa_mismatch(), 1e-12) << c;
  EXPECT_LE(c.max_root_distance(), 1e-12) << c;
  EXPECT_TRUE(c.valid(1e-12, 1e-12));
  // The exact end points of the open curve are the input end points.
  EXPECT_EQ(CGAL::to_double(c.exact_pieces.front().source().x()), -1.0);
  EXPECT_EQ(CGAL::to_double(c.exact_pieces.back().target().y()), 1.0);
}

std::vector<Kd::Point_2> spiky(std::mt19937& g, std::size_t n, double amplitude) {
  std::uniform_real_distribution<double> U(0, 1);
  std::vector<Kd::Point_2> p;
  for (std::size_t i = 0; i < n; ++i) {
    const double a = 2 * M_PI * (i + 0.2 * (U(g) - 0.5)) / n;
    const double r = 1 + amplitude * (i % 2 ? 1 : -1) * (0.5 + U(g));
    p.push_back(Kd::Point_2(r * std::cos(a), r * std::sin(a)));
  }
  return p;
}

TEST(KappaCertify, RandomConvergedCurves) {
  std::mt19937 g(77);
  int certified = 0;
  for (int trial = 0; trial < 12; ++trial) {
    fair::Kappa_curve_options o;
    o.closed = trial % 2 == 0;
    o.weights = trial % 3 == 0 ? fair::Kappa_weights::UNIT
                               : (trial % 3 == 1 ? fair::Kappa_weights::FIXED : fair::Kappa_weights::AUTOMATIC);
    const std::size_t n = 6 + 2 * trial;
    o.fixed_weights.assign(n, 1.3);
    const fair::Kappa_curve_2<Kd> curve(spiky(g, n, 0.08), o);
    if (curve.report().status != fair::Kappa_curve_status::INTERIOR) continue;
    const fair::Kappa_certificate c = fair::certify(curve);
    EXPECT_EQ(c.pieces.size(), curve.number_of_pieces());
    EXPECT_TRUE(c.all_points_on_pieces()) << c;
    EXPECT_TRUE(c.all_g1()) << c;
    EXPECT_LE(c.max_kappa_mismatch(), 1e-10) << c;
    if (o.weights != fair::Kappa_weights::AUTOMATIC) {
      // w >= 1: exactly one extremum per piece, a maximum, at t_i.
      EXPECT_TRUE(c.all_unique_maxima()) << c;
      EXPECT_LE(c.max_root_distance(), 1e-9) << c;
    } else {
      // Automatic weights (w < 1, ellipses): Q_i is a certified curvature extremum at t_i;
      // Sec. 3.2 warns it may be a minimum, and the certificate tells which.
      // Where the extremum is not certified near t_i, the piece is nearly circular: |kappa| is
      // almost constant, so the roots of eq. 4 are ill-conditioned and move far under the
      // rounding of lambda, t, w (a property of the data, reported by the certificate).
      for (std::size_t j = 0; j < c.pieces.size(); ++j) {
        const auto& p = c.pieces[j];
        if (p.has_extremum_at_t && p.root_distance <= 1e-9) continue;
        double kmin = 1e300, kmax = 0;
        for (int k = 0; k <= 64; ++k) {
          const double kk = std::abs(curve.piece(j).curvature(k / 64.0));
          kmin = std::min(kmin, kk);
          kmax = std::max(kmax, kk);
        }
        EXPECT_LE(kmax / kmin - 1, 1e-6) << "piece " << j << " distance " << p.root_distance;
      }
      EXPECT_EQ(c.all_unique_maxima(), c.minima_at_points() == 0 && c.all_unique_maxima());
    }
    ++certified;
  }
  EXPECT_GE(certified, 9);
}

// An elliptic piece (w_i < 1, automatic weights) may hold a curvature maximum at t_i AND a
// minimum elsewhere in (0,1) (the paper, after eq. 4): still a kappa-curve piece. The certificate
// accepts it (maximum_at_t) while reporting that it is not unique_maximum; a sampled |kappa|
// confirms the maximum at t_i and a real variation (not rounding noise).
TEST(KappaCertify, EllipticPieceWithAMinimumElsewhereIsAccepted) {
  std::mt19937 g(3);
  std::uniform_real_distribution<double> u(0, 1);
  int elliptic = 0;
  for (int trial = 0; trial < 40 && elliptic < 3; ++trial) {
    std::vector<Kd::Point_2> p;
    for (int k = 0; k < 4 + trial % 10; ++k) p.emplace_back(u(g), u(g));
    fair::Kappa_curve_options o;
    o.closed = trial % 2;
    o.weights = fair::Kappa_weights::AUTOMATIC;
    try {
      const fair::Kappa_curve_2<Kd> c(p, o);
      if (c.report().status != fair::Kappa_curve_status::INTERIOR) continue;
      const fair::Kappa_certificate cert = fair::certify(c);
      for (std::size_t j = 0; j < cert.pieces.size(); ++j) {
        const fair::Kappa_certificate::Piece& pc = cert.pieces[j];
        if (!(pc.extrema == 2 && pc.maxima == 1 && pc.root_distance < 1e-9)) continue;
        double kmax = 0, kmin = std::numeric_limits<double>::infinity();
        for (int s = 0; s <= 2000; ++s) {
          const double k = std::fabs(c.piece(j).curvature(s / 2000.0));
          kmax = std::max(kmax, k), kmin = std::min(kmin, k);
        }
        if ((kmax - kmin) / kmax < 1e-3) continue;  // nearly circular: its roots are noise
        ++elliptic;
        EXPECT_LT(c.weight(j), 1.0);
        EXPECT_TRUE(pc.maximum_at_t) << cert;
        EXPECT_FALSE(pc.unique_maximum);
        // |kappa| at t_i is at least every sample (peaks can be narrower than the sampling).
        EXPECT_GE(std::fabs(c.piece(j).curvature(c.t(j))), kmax * (1 - 1e-9)) << "trial " << trial << " piece " << j;
      }
    } catch (const fair::Error&) {
    }
  }
  EXPECT_GE(elliptic, 1) << "the seeded sets must contain an elliptic piece with a maximum and a minimum";
}

TEST(KappaCertify, NonConvergedCurveFailsTheCertificate) {
  std::mt19937 g(3);
  fair::Kappa_curve_options o;
  o.closed = true;
  o.refinement_passes = 0;
  o.max_iterations = 0;
  const fair::Kappa_curve_2<Kd> curve(spiky(g, 10, 0.1), o);
  ASSERT_NE(curve.report().status, fair::Kappa_curve_status::INTERIOR);
  const fair::Kappa_certificate c = fair::certify(curve);
  // Interpolation and G1 still hold exactly (by construction of eq. 18 and eq. 9) ...
  EXPECT_TRUE(c.all_points_on_pieces());
  EXPECT_TRUE(c.all_g1());
  // ... but curvature continuity or the maxima at Q_i do not.
  EXPECT_FALSE(c.valid());
}

} // namespace

// certify_pieces: the pieces RETURNED by an EPECK curve, certified piece by piece. Their E_j
// are formed exactly from the rounded P_j, so C0 and G1 hold exactly; interpolation holds to
// the rounding of the solve (certified bound), and the certificate agrees with the global
// exact rebuild of certify() (same maxima, same |kappa| mismatch up to rounding). The certified
// exact pieces are the returned pieces themselves.
TEST(KappaCertify, PiecewiseCertificateOfTheReturnedEpeckPieces) {
  std::mt19937 g(5);
  for (const bool closed : {true, false}) {
    const std::vector<Kd::Point_2> pd = spiky(g, 40, 0.05);
    std::vector<Epeck::Point_2> q;
    for (const auto& p : pd) q.push_back(Epeck::Point_2(p.x(), p.y()));
    fair::Kappa_curve_options o;
    o.closed = closed;
    const fair::Kappa_curve_2<Epeck> curve(q, o);
    ASSERT_EQ(curve.report().status, fair::Kappa_curve_status::INTERIOR) << curve.report();
    const fair::Kappa_certificate c = fair::certify_pieces(curve);
    ASSERT_EQ(c.pieces.size(), curve.number_of_pieces());
    ASSERT_EQ(c.exact_pieces.size(), curve.number_of_pieces());
    EXPECT_EQ(c.joins.size(), closed ? curve.number_of_pieces() : curve.number_of_pieces() - 1);
    EXPECT_TRUE(c.all_g1()) << c;
    EXPECT_TRUE(c.all_unique_maxima()) << c;
    EXPECT_LE(c.max_interpolation_error(), 1e-13) << c;
    EXPECT_LE(c.max_kappa_mismatch(), 1e-10) << c;
    EXPECT_LE(c.max_root_distance(), 1e-9) << c;
    EXPECT_TRUE(c.valid_within(1e-13, 1e-10, 1e-9)) << c;
    for (std::size_t j = 0; j < curve.number_of_pieces(); ++j)
      for (std::size_t k = 0; k < 3; ++k) {
        const auto& a = c.exact_pieces[j].control_point(k);
        const auto& b = curve.piece(j).control_point(k);
        EXPECT_TRUE(a.x() == fair::internal::common::to_gmpq(b.x()) && a.y() == fair::internal::common::to_gmpq(b.y()))
            << "piece " << j << " control point " << k;
      }
    const fair::Kappa_certificate global = fair::certify(curve);
    EXPECT_NEAR(c.max_kappa_mismatch(), global.max_kappa_mismatch(), 1e-11);
  }
}

// A double-kernel curve: the rounded E_j are generally not exactly on P_{j-1} P_j, and the
// piecewise certificate says so instead of pretending G1.
TEST(KappaCertify, PiecewiseCertificateReportsRoundedDoubleJoins) {
  std::mt19937 g(6);
  fair::Kappa_curve_options o;
  o.closed = true;
  const fair::Kappa_curve_2<Kd> curve(spiky(g, 30, 0.05), o);
  ASSERT_EQ(curve.report().status, fair::Kappa_curve_status::INTERIOR);
  const fair::Kappa_certificate c = fair::certify_pieces(curve);
  EXPECT_EQ(c.pieces.size(), 30u);
  EXPECT_LE(c.max_interpolation_error(), 1e-13) << c;
  EXPECT_TRUE(c.all_unique_maxima()) << c;
  EXPECT_LE(c.max_kappa_mismatch(), 1e-10) << c;
  std::size_t c0 = 0;
  for (const auto& j : c.joins) c0 += j.c0 ? 1 : 0;
  EXPECT_EQ(c0, 30u);  // the pieces share their join points (same stored point)
}

namespace {

namespace kp = fair::internal::kappa;

// The exact inputs of certify(curve), for certify_parameters with modified parameters.
struct Exact_inputs {
  bool closed = false;
  std::vector<std::size_t> index;
  std::vector<CGAL::Gmpq> qx, qy;
  CGAL::Gmpq sx, sy, ex, ey;
  std::vector<double> lambda, t, w;
};

template <class K>
Exact_inputs inputs_of(const fair::Kappa_curve_2<K>& curve) {
  Exact_inputs in;
  const std::size_t n = curve.number_of_pieces(), m = curve.points().size();
  in.closed = curve.is_closed();
  for (std::size_t j = 0; j < n; ++j) {
    in.index.push_back(curve.point_index(j));
    in.qx.push_back(fair::internal::common::to_gmpq(curve.points()[curve.point_index(j)].x()));
    in.qy.push_back(fair::internal::common::to_gmpq(curve.points()[curve.point_index(j)].y()));
  }
  if (!in.closed) {
    in.sx = fair::internal::common::to_gmpq(curve.points()[0].x());
    in.sy = fair::internal::common::to_gmpq(curve.points()[0].y());
    in.ex = fair::internal::common::to_gmpq(curve.points()[m - 1].x());
    in.ey = fair::internal::common::to_gmpq(curve.points()[m - 1].y());
  }
  in.lambda = curve.state().lambda;
  in.t = curve.state().t;
  in.w = curve.state().w;
  return in;
}

// Reference: eq. 18 for the P_i (x and y separately) by plain Gmpq tridiagonal elimination,
// original coordinates.
// q: interpolated points of the pieces; s/e: fixed end points of an open curve.
void exact_eq18(bool closed, const std::vector<CGAL::Gmpq>& qx, const std::vector<CGAL::Gmpq>& qy,
                       const CGAL::Gmpq& sx, const CGAL::Gmpq& sy, const CGAL::Gmpq& ex, const CGAL::Gmpq& ey,
                       const std::vector<CGAL::Gmpq>& lambda, const std::vector<CGAL::Gmpq>& t,
                       const std::vector<CGAL::Gmpq>& w, std::vector<CGAL::Gmpq>& px, std::vector<CGAL::Gmpq>& py) {
  typedef CGAL::Gmpq Q;
  const std::size_t n = qx.size();
  std::vector<Q> a(n, Q(0)), b(n, Q(0)), c(n, Q(0)), dx(n), dy(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Q u = Q(1) - t[i], c0 = u * u, c2 = t[i] * t[i], c1 = Q(2) * u * t[i] * w[i];
    const Q D = c0 + c1 + c2;
    dx[i] = D * qx[i];
    dy[i] = D * qy[i];
    b[i] = c1;
    if (closed || i > 0) {
      a[i] = c0 * (Q(1) - lambda[i]);
      b[i] += c0 * lambda[i];
    } else {
      dx[i] -= c0 * sx;
      dy[i] -= c0 * sy;
    }
    if (closed || i + 1 < n) {
      const Q& l = lambda[(i + 1) % n];
      c[i] = c2 * l;
      b[i] += c2 * (Q(1) - l);
    } else {
      dx[i] -= c2 * ex;
      dy[i] -= c2 * ey;
    }
  }
  if (closed) {
    px = fair::internal::classic::solve_cyclic_tridiagonal(a, b, c, dx);
    py = fair::internal::classic::solve_cyclic_tridiagonal(a, b, c, dy);
  } else {
    px = fair::internal::classic::solve_tridiagonal(a, b, c, dx);
    py = fair::internal::classic::solve_tridiagonal(a, b, c, dy);
  }
}

// The solver's parameters as rationals (lambda_0 of an open curve, unused, as 1/2) and the exact
// eq.-18 solution for them by plain rational elimination (exact_eq18 above).
struct Rational_solve {
  std::vector<CGAL::Gmpq> lam, t, w, px, py;
};
Rational_solve rational_solve(const Exact_inputs& in) {
  Rational_solve r;
  const std::size_t np = in.qx.size();
  r.lam.resize(np); r.t.resize(np); r.w.resize(np);
  for (std::size_t j = 0; j < np; ++j) {
    r.lam[j] = CGAL::Gmpq(in.closed || j > 0 ? in.lambda[j] : 0.5);
    r.t[j] = CGAL::Gmpq(in.t[j]);
    r.w[j] = CGAL::Gmpq(in.w[j]);
  }
  exact_eq18(in.closed, in.qx, in.qy, in.sx, in.sy, in.ex, in.ey, r.lam, r.t, r.w, r.px, r.py);
  return r;
}

fair::Kappa_certificate certify_inputs(const Exact_inputs& in, kp::Certify_mode mode) {
  return kp::certify_parameters(in.closed, in.index, in.qx, in.qy, in.sx, in.sy, in.ex, in.ey, in.lambda, in.t, in.w,
                                mode);
}

// The filtered certificate (interval filter, exact fallback) and the forced exact one (exact
// isolation of eq. 4 for every piece) must say the same thing, piece by piece: a wrong filter
// shows up here. The root brackets must intersect (both contain the same certified root).
void expect_same_certificate(const fair::Kappa_certificate& f, const fair::Kappa_certificate& e, const char* what) {
  ASSERT_EQ(f.pieces.size(), e.pieces.size()) << what;
  ASSERT_EQ(f.joins.size(), e.joins.size()) << what;
  ASSERT_EQ(f.exact_pieces.size(), e.exact_pieces.size()) << what;
  for (std::size_t j = 0; j < f.pieces.size(); ++j) {
    const auto& a = f.pieces[j];
    const auto& b = e.pieces[j];
    EXPECT_EQ(a.valid_piece, b.valid_piece) << what << " piece " << j;
    EXPECT_EQ(a.point_on_piece, b.point_on_piece) << what << " piece " << j;
    EXPECT_EQ(a.interpolation_error, b.interpolation_error) << what << " piece " << j;
    EXPECT_EQ(a.extrema, b.extrema) << what << " piece " << j;
    EXPECT_EQ(a.maxima, b.maxima) << what << " piece " << j;
    EXPECT_EQ(a.unique_maximum, b.unique_maximum) << what << " piece " << j;
    EXPECT_EQ(a.has_extremum_at_t, b.has_extremum_at_t) << what << " piece " << j;
    if (a.has_extremum_at_t && b.has_extremum_at_t && a.extrema == 1) {
      EXPECT_EQ(a.kind_at_t, b.kind_at_t) << what << " piece " << j;
      EXPECT_LT(a.root_lower, b.root_upper) << what << " piece " << j;
      EXPECT_LT(b.root_lower, a.root_upper) << what << " piece " << j;
      EXPECT_LE(a.root_lower, a.root_upper);
    }
  }
  for (std::size_t k = 0; k < f.joins.size(); ++k) {
    EXPECT_EQ(f.joins[k].c0, e.joins[k].c0) << what << " join " << k;
    EXPECT_EQ(f.joins[k].g1, e.joins[k].g1) << what << " join " << k;
    EXPECT_EQ(f.joins[k].kappa_mismatch_lower, e.joins[k].kappa_mismatch_lower) << what << " join " << k;
    EXPECT_EQ(f.joins[k].kappa_mismatch_upper, e.joins[k].kappa_mismatch_upper) << what << " join " << k;
  }
  for (std::size_t j = 0; j < f.exact_pieces.size(); ++j)
    for (std::size_t k = 0; k < 3; ++k)
      EXPECT_TRUE(f.exact_pieces[j].control_point(k) == e.exact_pieces[j].control_point(k)) << what << " piece " << j;
}

// The fraction-free integer solve of eq. 18 equals the Gmpq tridiagonal solve (exact_eq18), for
// open and closed curves including the smallest ones (closed n = 3, open with one piece).
TEST(KappaCertify, FractionFreeSolveEqualsRationalSolve) {
  std::mt19937 g(11);
  for (const std::size_t n : {3u, 4u, 9u, 25u}) {
    for (const bool closed : {true, false}) {
      fair::Kappa_curve_options o;
      o.closed = closed;
      o.weights = n % 2 ? fair::Kappa_weights::AUTOMATIC : fair::Kappa_weights::UNIT;
      const fair::Kappa_curve_2<Kd> curve(spiky(g, n, 0.1), o);
      const Exact_inputs in = inputs_of(curve);
      const std::size_t np = in.qx.size();
      ASSERT_EQ(np, closed ? n : n - 2);
      const Rational_solve rs = rational_solve(in);
      const std::vector<CGAL::Gmpq>&lam = rs.lam, &w = rs.w, &px = rs.px, &py = rs.py;
      const fair::Kappa_certificate c = certify_inputs(in, kp::Certify_mode::FILTERED);
      ASSERT_EQ(c.exact_pieces.size(), np) << c;
      for (std::size_t j = 0; j < np; ++j) {
        EXPECT_TRUE(c.exact_pieces[j].control_point(1).x() == px[j]) << "n " << n << " piece " << j;
        EXPECT_TRUE(c.exact_pieces[j].control_point(1).y() == py[j]) << "n " << n << " piece " << j;
        EXPECT_TRUE(c.exact_pieces[j].weight() == w[j]);
      }
      // The join points are eq. 9 of these P (and equal as canonical rationals).
      for (std::size_t j = (closed ? 0 : 1); j < np; ++j) {
        const std::size_t a = (j + np - 1) % np;
        const CGAL::Gmpq ex = (1 - lam[j]) * px[a] + lam[j] * px[j], ey = (1 - lam[j]) * py[a] + lam[j] * py[j];
        EXPECT_TRUE(c.exact_pieces[j].source().x() == ex && c.exact_pieces[j].source().y() == ey) << j;
        EXPECT_TRUE(c.exact_pieces[a].target() == c.exact_pieces[j].source()) << j;
      }
      EXPECT_TRUE(c.all_points_on_pieces()) << c;
      EXPECT_TRUE(c.all_g1()) << c;
    }
  }
}

// EPECK input points with non-dyadic rational coordinates (thirds and sevenths): the rows of
// eq. 18 get odd denominators, the scaled copy is no longer dyadic; still exact and equal to
// the rational solve, and the converged curve is certified.
TEST(KappaCertify, NonDyadicRationalInputPoints) {
  std::mt19937 g(31);
  for (const bool closed : {true, false}) {
    std::vector<Epeck::Point_2> q;
    for (const Kd::Point_2& p : spiky(g, 14, 0.06))
      q.push_back(Epeck::Point_2(Epeck::FT(p.x()) / 3, Epeck::FT(p.y()) / 7));
    fair::Kappa_curve_options o;
    o.closed = closed;
    const fair::Kappa_curve_2<Epeck> curve(q, o);
    ASSERT_EQ(curve.report().status, fair::Kappa_curve_status::INTERIOR) << curve.report();
    const fair::Kappa_certificate c = fair::certify(curve);
    EXPECT_TRUE(c.valid()) << c;
    const Exact_inputs in = inputs_of(curve);
    const std::size_t np = in.qx.size();
    std::size_t non_dyadic = 0;  // x / 3 is dyadic only when 3 divides the mantissa of x
    for (std::size_t j = 0; j < np; ++j)
      non_dyadic += (mpz_popcount(mpq_denref(in.qx[j].mpq())) > 1) + (mpz_popcount(mpq_denref(in.qy[j].mpq())) > 1);
    EXPECT_GT(non_dyadic, np);
    const Rational_solve rs = rational_solve(in);
    const std::vector<CGAL::Gmpq>&px = rs.px, &py = rs.py;
    ASSERT_EQ(c.exact_pieces.size(), np);
    for (std::size_t j = 0; j < np; ++j)
      EXPECT_TRUE(c.exact_pieces[j].control_point(1).x() == px[j] && c.exact_pieces[j].control_point(1).y() == py[j]);
    expect_same_certificate(c, certify_inputs(in, kp::Certify_mode::EXACT), "non-dyadic");
  }
}

// canonical_fractions: X_i / (2^e_i Delta) in lowest terms, also with common odd factors (the
// batch gcd G != 1), zero and negative numerators and powers of two on both sides.
TEST(KappaCertify, CanonicalFractionsMatchGmpq) {
  std::mt19937_64 g(8);
  for (int trial = 0; trial < 40; ++trial) {
    kp::Certify_int Delta;
    mpz_set_ui(Delta.v, 1);
    const unsigned long factors[] = {3, 5, 7, 2, 2, 1000003, 4294967291ul};
    for (int k = 0; k < 6; ++k) {
      mpz_mul_ui(Delta.v, Delta.v, factors[g() % 7]);
      mpz_mul_ui(Delta.v, Delta.v, 1 + (g() >> 40));
    }
    std::vector<kp::Certify_int> X(12);
    std::vector<const kp::Certify_int*> px;
    std::vector<mp_bitcnt_t> e;
    for (std::size_t i = 0; i < X.size(); ++i) {
      if (i % 5 == 4) mpz_set_ui(X[i].v, 0);
      else {
        mpz_set_ui(X[i].v, 1 + (g() >> 20));
        mpz_mul_ui(X[i].v, X[i].v, factors[g() % 7]);
        if (trial % 2) mpz_mul(X[i].v, X[i].v, Delta.v);  // all share Delta's factors
        mpz_mul_2exp(X[i].v, X[i].v, g() % 5);
        if (g() % 2) mpz_neg(X[i].v, X[i].v);
      }
      px.push_back(&X[i]);
      e.push_back(g() % 70);
    }
    const std::vector<CGAL::Gmpq> f = kp::canonical_fractions(px, e, Delta);
    for (std::size_t i = 0; i < X.size(); ++i) {
      mpq_t q;
      mpq_init(q);
      mpz_set(mpq_numref(q), X[i].v);
      mpz_mul_2exp(mpq_denref(q), Delta.v, e[i]);
      mpq_canonicalize(q);
      EXPECT_TRUE(f[i] == CGAL::Gmpq(q)) << "trial " << trial << " entry " << i;
      EXPECT_EQ(mpz_cmp(mpq_numref(f[i].mpq()), mpq_numref(q)), 0);  // same representation
      EXPECT_EQ(mpz_cmp(mpq_denref(f[i].mpq()), mpq_denref(q)), 0);
      mpq_clear(q);
    }
  }
}

// Filtered vs forced exact on random curves of all weight kinds, and on deliberately perturbed
// parameters (pieces with far or several extrema, minima: the fallback must kick in and agree).
TEST(KappaCertify, FilteredPathAgreesWithForcedExactPath) {
  std::mt19937 g(2024);
  std::uniform_real_distribution<double> U(-1, 1);
  std::size_t fallback_pieces = 0, pieces = 0;
  for (int trial = 0; trial < 9; ++trial) {
    fair::Kappa_curve_options o;
    o.closed = trial % 2 == 0;
    o.weights = trial % 3 == 0 ? fair::Kappa_weights::UNIT
                               : (trial % 3 == 1 ? fair::Kappa_weights::FIXED : fair::Kappa_weights::AUTOMATIC);
    const std::size_t n = 6 + trial;
    o.fixed_weights.assign(n, 0.8);
    const fair::Kappa_curve_2<Kd> curve(spiky(g, n, 0.12), o);
    Exact_inputs in = inputs_of(curve);
    expect_same_certificate(certify_inputs(in, kp::Certify_mode::FILTERED), certify_inputs(in, kp::Certify_mode::EXACT),
                            "solved");
    // Perturbed: t, w and lambda moved by up to 5 %, so the eq.-4 roots leave t_i.
    for (std::size_t j = 0; j < in.t.size(); ++j) {
      in.t[j] = std::min(0.95, std::max(0.05, in.t[j] + 0.05 * U(g)));
      in.w[j] *= 1 + 0.3 * U(g);
      if (in.closed || j > 0) in.lambda[j] = std::min(0.95, std::max(0.05, in.lambda[j] + 0.05 * U(g)));
    }
    const fair::Kappa_certificate f = certify_inputs(in, kp::Certify_mode::FILTERED);
    const fair::Kappa_certificate e = certify_inputs(in, kp::Certify_mode::EXACT);
    expect_same_certificate(f, e, "perturbed");
    for (const auto& p : f.pieces) {
      ++pieces;
      fallback_pieces += p.root_distance > 0x1p-20 || p.extrema != 1;
    }
    EXPECT_FALSE(f.valid()) << f;
  }
  EXPECT_GT(fallback_pieces, 0u);  // the comparison exercised the exact fallback
  EXPECT_GT(pieces, 50u);
}

// Certificates of slightly wrong curves must fail: the exact curve of a converged solve with one
// t_i, w_i or lambda_i moved by 1e-7 still interpolates exactly and is G1 (eqs. 18 and 9 are
// re-solved exactly), but the maximum at Q_i or the |kappa| continuity is lost beyond the
// default tolerances (1e-9).
TEST(KappaCertify, PerturbedParametersFailTheCertificate) {
  std::mt19937 g(99);
  fair::Kappa_curve_options o;
  o.closed = true;
  const fair::Kappa_curve_2<Kd> curve(spiky(g, 16, 0.06), o);
  ASSERT_EQ(curve.report().status, fair::Kappa_curve_status::INTERIOR) << curve.report();
  const Exact_inputs base = inputs_of(curve);
  ASSERT_TRUE(certify_inputs(base, kp::Certify_mode::FILTERED).valid()) << certify_inputs(base, kp::Certify_mode::FILTERED);
  for (int what = 0; what < 3; ++what) {
    for (const std::size_t j : {0u, 7u, 15u}) {
      Exact_inputs in = base;
      double& v = what == 0 ? in.t[j] : (what == 1 ? in.w[j] : in.lambda[j]);
      v += 1e-7;
      const fair::Kappa_certificate c = certify_inputs(in, kp::Certify_mode::FILTERED);
      EXPECT_TRUE(c.all_points_on_pieces()) << c;
      EXPECT_TRUE(c.all_g1()) << c;
      EXPECT_FALSE(c.valid()) << "parameter " << what << " of piece " << j << ": " << c;
      EXPECT_TRUE(c.max_kappa_mismatch() > 1e-9 || c.max_root_distance() > 1e-9) << c;
    }
  }
}

// Pieces that are not the exact curve: a middle control point moved by 1e-12 breaks exact
// interpolation (a certified positive distance bound, at least the true distance) and G1 at both
// of its joins; the filtered and exact paths agree on it.
TEST(KappaCertify, MovedControlPointFailsInterpolationAndG1) {
  typedef fair::Kappa_certificate::Exact_kernel EK;
  std::mt19937 g(5);
  fair::Kappa_curve_options o;
  o.closed = true;
  const fair::Kappa_curve_2<Kd> curve(spiky(g, 12, 0.05), o);
  const fair::Kappa_certificate c = fair::certify(curve);
  ASSERT_TRUE(c.valid()) << c;
  const std::size_t n = c.exact_pieces.size();
  std::vector<EK::Point_2> E(n + 1), P(n), Q(n);
  std::vector<CGAL::Gmpq> w(n);
  std::vector<double> t(n);
  std::vector<std::size_t> index(n);
  for (std::size_t j = 0; j < n; ++j) {
    E[j] = c.exact_pieces[j].source();
    P[j] = c.exact_pieces[j].control_point(1);
    w[j] = c.exact_pieces[j].weight();
    t[j] = curve.t(j);
    index[j] = j;
    Q[j] = EK::Point_2(fair::internal::common::to_gmpq(curve.points()[j].x()), fair::internal::common::to_gmpq(curve.points()[j].y()));
  }
  E[n] = E[0];
  const fair::Kappa_certificate same = kp::certify_exact(true, index, E, P, w, t, Q);
  EXPECT_TRUE(same.valid()) << same;
  P[4] = EK::Point_2(P[4].x() + CGAL::Gmpq(1e-12), P[4].y());
  const fair::Kappa_certificate f = kp::certify_exact(true, index, E, P, w, t, Q);
  expect_same_certificate(f, kp::certify_exact(true, index, E, P, w, t, Q, kp::Certify_mode::EXACT), "moved P");
  EXPECT_FALSE(f.pieces[4].point_on_piece);
  EXPECT_GT(f.pieces[4].interpolation_error, 0.0);
  // the true distance is 2 (1-t) t w / W(t) * 1e-12
  const double tt = t[4], ww = CGAL::to_double(w[4]);
  const double moved = 2 * (1 - tt) * tt * ww / ((1 - tt) * (1 - tt) + 2 * (1 - tt) * tt * ww + tt * tt) * 1e-12;
  EXPECT_GE(f.pieces[4].interpolation_error, moved * (1 - 1e-6));
  EXPECT_LE(f.pieces[4].interpolation_error, moved * (1 + 1e-3));
  for (std::size_t j = 0; j < n; ++j) EXPECT_EQ(f.pieces[j].point_on_piece, j != 4) << j;
  EXPECT_FALSE(f.joins[4].g1);
  EXPECT_FALSE(f.joins[5].g1);
  EXPECT_TRUE(f.joins[6].g1);
  EXPECT_FALSE(f.all_g1());
  EXPECT_FALSE(f.valid());
  // The same with the lambda_j given (the filtered G1 identity E_j - P_{j-1} == lambda_j (P_j -
  // P_{j-1})): it fails at the moved point and the exact predicates decide; a join point slid
  // along its tangent line (mu != lambda) is still G1, but breaks interpolation of both pieces.
  std::vector<double> lambda(curve.state().lambda);
  const fair::Kappa_certificate fl = kp::certify_exact(true, index, E, P, w, t, Q, kp::Certify_mode::FILTERED, &lambda);
  expect_same_certificate(fl, f, "moved P, lambda given");
  P[4] = c.exact_pieces[4].control_point(1);
  const CGAL::Gmpq mu(0.3);
  ASSERT_NE(CGAL::to_double(mu), lambda[8]);
  E[8] = EK::Point_2(P[7].x() + mu * (P[8].x() - P[7].x()), P[7].y() + mu * (P[8].y() - P[7].y()));
  const fair::Kappa_certificate slid = kp::certify_exact(true, index, E, P, w, t, Q, kp::Certify_mode::FILTERED, &lambda);
  expect_same_certificate(slid, kp::certify_exact(true, index, E, P, w, t, Q, kp::Certify_mode::EXACT), "slid E");
  EXPECT_TRUE(slid.all_g1()) << slid;
  for (std::size_t j = 0; j < n; ++j) EXPECT_EQ(slid.pieces[j].point_on_piece, j != 7 && j != 8) << j;
  // A piece whose control points are collinear is not a conic piece: the joins are then not
  // certified at all, and the accessors must not read as success.
  E[8] = c.exact_pieces[8].source();
  P[2] = EK::Point_2((E[2].x() + E[3].x()) / 2, (E[2].y() + E[3].y()) / 2);
  const fair::Kappa_certificate broken = kp::certify_exact(true, index, E, P, w, t, Q);
  EXPECT_FALSE(broken.pieces[2].valid_piece);
  EXPECT_FALSE(broken.valid());
  EXPECT_FALSE(broken.all_g1()) << broken;
  EXPECT_EQ(broken.max_kappa_mismatch(), std::numeric_limits<double>::infinity());
}

// Converged curves at extreme scales (the solver normalises; the certificate works on the exact
// input coordinates): the |kappa| mismatch enclosure must stay tight (no overflow of l^3 or
// underflow of the cross products), so the certificate holds at 1e+-120 and 1e+-150 too.
TEST(KappaCertify, ExtremeScales) {
  std::mt19937 g(17);
  const std::vector<Kd::Point_2> base = spiky(g, 10, 0.06);
  for (const double scale : {1e-150, 1e-120, 1e103, 1e120, 1e150}) {
    std::vector<Kd::Point_2> q;
    for (const Kd::Point_2& p : base) q.push_back(Kd::Point_2(scale * p.x(), scale * p.y()));
    fair::Kappa_curve_options o;
    o.closed = true;
    const fair::Kappa_curve_2<Kd> curve(q, o);
    ASSERT_EQ(curve.report().status, fair::Kappa_curve_status::INTERIOR) << "scale " << scale << " " << curve.report();
    const fair::Kappa_certificate c = fair::certify(curve);
    EXPECT_TRUE(c.valid()) << "scale " << scale << " " << c;
    EXPECT_LE(c.max_kappa_mismatch(), 1e-9) << "scale " << scale;
  }
}

} // namespace
