// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The certified curvature features of Fairness_metrics.h (the method is in its file comment and in
// doc/fairness_metrics.md): the exact polynomials D (sign of the curvature) and N (sign of its
// derivative) of a Bernstein-form piece, their roots with the signs between them, and the walk
// along the curve that turns sign changes into inflections and curvature extrema.
// Included by Fairness_metrics.h after its report types (Curve_feature, Feature_report).

#ifndef FAIR_INTERNAL_METRICS_FEATURES_H
#define FAIR_INTERNAL_METRICS_FEATURES_H

#include <fair/Bernstein_polynomial.h>
#include <fair/Bernstein_root_isolation.h>
#include <fair/Errors.h>
#include <fair/internal/bernstein/curvature.h>
#include <fair/internal/bernstein/signed_roots.h>
#include <fair/internal/metrics/pieces.h>

#include <CGAL/Gmpq.h>
#include <CGAL/number_utils.h>

#include <cstddef>
#include <vector>

namespace fair {
namespace internal {
namespace metrics {

using bernstein::exact_sign_at;
using bernstein::max_gap_refinements;
using bernstein::signed_roots;
using bernstein::Signed_roots;

/// D = det(P, P', P'') of the homogeneous form (sign of the curvature).
inline Bernstein_polynomial<CGAL::Gmpq> curvature_sign_polynomial(const Homogeneous_form& h) {
  return bernstein::curvature_determinant(h.X, h.Y, h.W);
}

/// N, with sign(N) = sign(d kappa / dt) on regular points (see the file comment).
inline Bernstein_polynomial<CGAL::Gmpq> curvature_derivative_sign_polynomial(const Homogeneous_form& h) {
  typedef CGAL::Gmpq ET;
  const Bernstein_polynomial<ET> D = curvature_sign_polynomial(h);
  const Bernstein_polynomial<ET> W1 = h.W.derivative();
  Bernstein_polynomial<ET> Ax, Ay;
  bernstein::hodograph_numerators(h.X, h.Y, h.W, Ax, Ay);
  const Bernstein_polynomial<ET> Ax1 = Ax.derivative(), Ay1 = Ay.derivative();
  const Bernstein_polynomial<ET> A2 = Ax * Ax + Ay * Ay, AA1 = Ax * Ax1 + Ay * Ay1;
  return ET(2) * (D.derivative() * h.W + ET(3) * D * W1) * A2 - ET(6) * D * h.W * AA1;
}

template <class Piece>
Curve_feature make_feature(const Piece& piece, std::size_t index, double t, const Isolating_interval& I, bool joint) {
  Curve_feature f;
  f.piece = index;
  f.t = t;
  f.interval = I;
  Piece_jet<Piece> jet(piece);
  const Jet j = jet(t);
  f.x = j.x;
  f.y = j.y;
  f.curvature = j.curvature(); // 0 at a singular point
  f.at_joint = joint;
  return f;
}

/// Which sign changes certified_features() looks for.
enum class Feature_kind {
  INFLECTION,        ///< of D, the sign of the curvature
  CURVATURE_EXTREMUM ///< of N, the sign of its derivative
};

/// Samples per piece of the uncertified search on generic pieces: enough to separate the few
/// features of a fair piece, cheap enough for a report.
constexpr int generic_feature_samples = 512;

/// The sign changes of kappa (or dkappa/dt) of one piece on generic_feature_samples + 1 samples,
/// continuing the walk's last sign (uncertified).
template <class Piece>
void sampled_features(const Piece& piece, std::size_t i, Feature_kind which, int& last, int& first,
                      Feature_report& report) {
  Piece_jet<Piece> jet(piece);
  const int m = generic_feature_samples;
  for (int k = 0; k <= m; ++k) {
    const double t = double(k) / m;
    const Jet j = jet(t);
    const double v = which == Feature_kind::INFLECTION ? (j.x1 * j.y2 - j.y1 * j.x2) : j.curvature_derivative();
    const int s = (v > 0) - (v < 0);
    if (s != 0 && last != 0 && s != last) {
      Isolating_interval I;
      I.lower = CGAL::Gmpq(t);
      I.upper = CGAL::Gmpq(t);
      report.features.push_back(make_feature(piece, i, t, I, k == 0));
    }
    if (s != 0) {
      if (first == 0) first = s;
      last = s;
    }
  }
}

template <class Piece>
Feature_report certified_features(const std::vector<Piece>& curve, Feature_kind which, const char* what) {
  check_curve(curve, what);
  Feature_report report;
  if constexpr (kind_of<Piece> == Piece_kind::GENERIC) {
    // Generic pieces: sign changes of kappa (or dkappa/dt) on the samples.
    report.certified = false;
    int last = 0, first = 0;
    for (std::size_t i = 0; i < curve.size(); ++i) sampled_features(curve[i], i, which, last, first, report);
    return report;
  } else {
    int last = 0;          // last nonzero gap sign along the curve
    int first = 0;         // first nonzero gap sign along the curve
    Certification_budget budget(curve.size());
    for (std::size_t i = 0; i < curve.size(); ++i) {
      const Homogeneous_form h = homogeneous_exact(curve[i]);
      // Building D (degree 3 in the form) and N (degree 8) costs more than isolating their
      // roots: a piece whose polynomial would exceed the caps is sampled before any product
      // (degree-30 random p/q: 11 s in the products alone, issue 29 #4). The prediction is
      // checked against the budget here, the actual work below.
      const bool inflection = which == Feature_kind::INFLECTION;
      if (!budget.allows(predicted_work(h, inflection ? 3 : 8, inflection ? 3 : 6))) {
        report.certified = false;
        sampled_features(curve[i], i, which, last, first, report);
        continue;
      }
      const Bernstein_polynomial<CGAL::Gmpq> p =
          inflection ? curvature_sign_polynomial(h) : curvature_derivative_sign_polynomial(h);
      if (p.is_zero()) {
        report.degenerate_pieces.push_back(i);
        continue;
      }
      if (!budget.take(polynomial_work(p))) {
        report.certified = false;
        sampled_features(curve[i], i, which, last, first, report);
        continue;
      }
      const Signed_roots s = signed_roots(p);
      // A piece that certifies its own curvature extrema provides the interior ones; the signs
      // computed here still decide the changes at the joins.
      bool own = false;
      if constexpr (Piece_traits<Piece>::has_own_curvature_extrema) own = (which == Feature_kind::CURVATURE_EXTREMUM);
      for (std::size_t g = 0; g < s.gaps.size(); ++g) {
        const int sign = s.gaps[g];
        if (sign == 0) continue;
        if (first == 0) first = sign;
        if (last != 0 && sign != last) {
          // The sign changed since the last nonempty gap: at root g-1 of this piece when it is an
          // interior one, otherwise across the join into this piece.
          if (g > 0) {
            const bool at_start = s.roots[g - 1].is_point() && CGAL::is_zero(s.roots[g - 1].lower);
            if (!own || at_start)
              report.features.push_back(make_feature(curve[i], i, s.approximations[g - 1], s.roots[g - 1], at_start));
          } else {
            Isolating_interval I;
            report.features.push_back(make_feature(curve[i], i, 0.0, I, true));
          }
        }
        last = sign;
      }
      if constexpr (Piece_traits<Piece>::has_own_curvature_extrema) {
        if (own) {
          for (const auto& x : curve[i].curvature_extrema()) {
            if (x.multiplicity % 2 == 0) continue; // no sign change of kappa': not an extremum
            Isolating_interval I;
            I.lower = x.t_lower;
            I.upper = x.t_upper;
            I.multiplicity = x.multiplicity;
            report.features.push_back(make_feature(curve[i], i, x.t, I, false));
          }
        }
      }
    }
    // A closed curve (last end point == first start point, exactly): the closing join too.
    if (first != 0 && last != first &&
        curve.back().control_points().back() == curve.front().control_points().front()) {
      Isolating_interval I;
      report.features.push_back(make_feature(curve.front(), 0, 0.0, I, true));
    }
    return report;
  }
}

} // namespace metrics
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_METRICS_FEATURES_H
