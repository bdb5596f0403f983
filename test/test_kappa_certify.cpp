// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Exact certification of kappa-curves (fair::certify): the curve rebuilt exactly from its
// rational lambda_i, t_i, w_i interpolates exactly, is exactly G1, has exactly one curvature
// maximum per piece near t_i, and matches |kappa| at the joins within a certified interval.
// fair::certify_pieces: the returned pieces themselves, certified piece by piece in O(n).

#include <fair/Kappa_curve_2.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>

#include <gtest/gtest.h>

#include <cmath>
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
    if (!curve.report().converged) continue;
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

TEST(KappaCertify, NonConvergedCurveFailsTheCertificate) {
  std::mt19937 g(3);
  fair::Kappa_curve_options o;
  o.closed = true;
  o.refinement_passes = 0;
  o.max_iterations = 0;
  const fair::Kappa_curve_2<Kd> curve(spiky(g, 10, 0.1), o);
  ASSERT_FALSE(curve.report().converged);
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
    ASSERT_TRUE(curve.report().converged) << curve.report();
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
        EXPECT_TRUE(a.x() == fair::internal::to_gmpq(b.x()) && a.y() == fair::internal::to_gmpq(b.y()))
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
  ASSERT_TRUE(curve.report().converged);
  const fair::Kappa_certificate c = fair::certify_pieces(curve);
  EXPECT_EQ(c.pieces.size(), 30u);
  EXPECT_LE(c.max_interpolation_error(), 1e-13) << c;
  EXPECT_TRUE(c.all_unique_maxima()) << c;
  EXPECT_LE(c.max_kappa_mismatch(), 1e-10) << c;
  std::size_t c0 = 0;
  for (const auto& j : c.joins) c0 += j.c0 ? 1 : 0;
  EXPECT_EQ(c0, 30u);  // the pieces share their join points (same stored point)
}
