// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair::occt: the exchange form fair::Nurbs_curve_2<K> (fair/Nurbs_curve_2.h) to and from
// OpenCASCADE's Geom2d_BSplineCurve, with the same parametrisation (OCCT's Value(u) is the
// library's point(u) for every u of the domain). Needs OCCT (TKernel, TKMath, TKG2d): link the
// CMake target fair::occt (find_package(fair COMPONENTS occt)); fair::fair never depends on it.
//
//   Handle(Geom2d_BSplineCurve) g = fair::occt::to_geom2d_bspline(curve.nurbs());
//   fair::Nurbs_curve_2<K> back = fair::occt::from_geom2d_bspline<K>(g);
//
// Open curves: OCCT's flat knot sequence is the full knot vector, its poles the control points
// (its knots are the distinct values, its multiplicities the counts).
// Closed curves: OCCT's periodic form -- N = n - p poles (the unique ones), the distinct knots
// of one period k_1 = u_p < ... < k_m = u_n, the first and last of equal multiplicity m_1, the
// other multiplicities summing with m_1 to N. OCCT's flat sequence f of that curve has the
// copies of k_1 at f_{p+1-m_1} .. f_p (the domain starts at the last copy) and pole j (1-based)
// belongs to the basis function on [f_{j-1}, f_{j+p}]. The library's form may place u_p at any
// copy of its knot, so with the copies of u_p at u_a .. u_b (a <= p <= b): f_k = u_{k+s} with
// s = a - (p + 1 - m_1), and OCCT's pole j is P_{(j-1+s) mod N}. Back, the library's knots are f
// extended by the period (u_k = u_{k-N} + T past f's end) and P_k = pole (k mod N) + 1: u_p is
// then the last copy of its knot. Derivation and measurements: doc/nurbs.md, "OpenCASCADE".
//
// Numbers: OCCT works in double; to_geom2d_bspline rounds FT with CGAL::to_double (exact for a
// double kernel), from_geom2d_bspline converts each double to FT exactly.
//
// Errors: Precondition_error when the degree exceeds Geom2d_BSplineCurve::MaxDegree(), when the
// rounding to double merges knots into one of too high a multiplicity (OCCT refuses the curve),
// for a null handle, or for an OCCT curve the library's form rejects (as Nurbs_curve_2's
// constructor). OCCT's own exceptions (Standard_Failure) do not leave these functions.

#ifndef FAIR_OCCT_GEOM2D_CONVERSION_H
#define FAIR_OCCT_GEOM2D_CONVERSION_H

#include <fair/Errors.h>
#include <fair/Nurbs_curve_2.h>
#include <fair/internal/common/checks.h>

#include <CGAL/number_utils.h>

#include <Geom2d_BSplineCurve.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt2d.hxx>
#include <gp_Pnt2d.hxx>

#include <cstddef>
#include <string>
#include <vector>

namespace fair {
namespace occt {

/// The curve as an OCCT B-spline with the same parametrisation: non-periodic for an open curve,
/// periodic for a closed one (file comment).
/// \throws Precondition_error as listed in the file comment.
template <class K>
Handle(Geom2d_BSplineCurve) to_geom2d_bspline(const Nurbs_curve_2<K>& curve) {
  const char* who = "fair::occt::to_geom2d_bspline";
  const std::size_t p = curve.degree(), n = curve.number_of_control_points();
  fair::internal::require(p <= static_cast<std::size_t>(Geom2d_BSplineCurve::MaxDegree()), who, ": degree ", p,
                          " is above OCCT's maximum ", Geom2d_BSplineCurve::MaxDegree());
  const auto& u = curve.knots();
  const auto& P = curve.control_points();
  const auto& w = curve.weights();
  const bool closed = curve.is_closed();

  // The knots OCCT takes: every distinct value of the full vector (open), of [u_p, u_n] (closed).
  const std::size_t first = closed ? p : 0, last = closed ? n : n + p;
  std::vector<double> knots;
  std::vector<int> mults;
  for (std::size_t k = first; k <= last; ++k) {
    const double x = CGAL::to_double(u[k]);
    if (!knots.empty() && x == knots.back()) {
      ++mults.back();
    } else {
      knots.push_back(x);
      mults.push_back(1);
    }
  }
  std::vector<std::size_t> pole_index(n);
  for (std::size_t k = 0; k < n; ++k) pole_index[k] = k;
  if (closed) {
    // m_1 and a from the domain's knots only: the copies u_a..u_b of u_p are u_p..u_b at the
    // left end and (by periodicity) u_{a+N}..u_n at the right end.
    const std::size_t N = n - p;
    std::size_t b = p, left = n;
    while (b + 1 < n && u[b + 1] == u[p]) ++b;
    while (left > p && u[left - 1] == u[n]) --left;
    const std::size_t a = left - N, m1 = b - a + 1;
    mults.front() = static_cast<int>(m1);
    mults.back() = static_cast<int>(m1);
    // pole j (0-based) is P_{(j + s) mod N}, s = a - (p + 1 - m1) (may be negative)
    const long s = static_cast<long>(a) - static_cast<long>(p + 1 - m1);
    pole_index.resize(N);
    for (std::size_t j = 0; j < N; ++j) {
      const long k = ((static_cast<long>(j) + s) % static_cast<long>(N) + static_cast<long>(N)) % static_cast<long>(N);
      pole_index[j] = static_cast<std::size_t>(k);
    }
  }

  TColgp_Array1OfPnt2d poles(1, static_cast<int>(pole_index.size()));
  TColStd_Array1OfReal weights(1, static_cast<int>(pole_index.size()));
  for (std::size_t j = 0; j < pole_index.size(); ++j) {
    const std::size_t k = pole_index[j];
    poles(static_cast<int>(j) + 1) = gp_Pnt2d(CGAL::to_double(P[k].x()), CGAL::to_double(P[k].y()));
    weights(static_cast<int>(j) + 1) = CGAL::to_double(w[k]);
  }
  TColStd_Array1OfReal occt_knots(1, static_cast<int>(knots.size()));
  TColStd_Array1OfInteger occt_mults(1, static_cast<int>(knots.size()));
  for (std::size_t i = 0; i < knots.size(); ++i) {
    occt_knots(static_cast<int>(i) + 1) = knots[i];
    occt_mults(static_cast<int>(i) + 1) = mults[i];
  }
  try {
    if (curve.is_rational())
      return new Geom2d_BSplineCurve(poles, weights, occt_knots, occt_mults, static_cast<int>(p), closed);
    return new Geom2d_BSplineCurve(poles, occt_knots, occt_mults, static_cast<int>(p), closed);
  } catch (const Standard_Failure& e) {
    fair::internal::require(false, who, ": OCCT refuses the curve (", e.GetMessageString(),
                            "): its knots rounded to double no longer form a valid vector");
  }
  return Handle(Geom2d_BSplineCurve)();  // not reached
}

/// The OCCT B-spline as the library's exchange form, same parametrisation: open for a
/// non-periodic curve (its flat knots, poles and weights as they are), closed for a periodic one
/// (file comment). Every double converts to FT exactly.
/// \throws Precondition_error for a null handle or a curve the library's form rejects.
template <class K>
Nurbs_curve_2<K> from_geom2d_bspline(const Handle(Geom2d_BSplineCurve)& g) {
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  const char* who = "fair::occt::from_geom2d_bspline";
  fair::internal::require(!g.IsNull(), who, ": null handle");
  const std::size_t p = static_cast<std::size_t>(g->Degree());
  const std::size_t poles = static_cast<std::size_t>(g->NbPoles());
  const bool periodic = g->IsPeriodic();
  const TColStd_Array1OfReal& flat = g->KnotSequence();
  std::vector<FT> u;
  for (int i = flat.Lower(); i <= flat.Upper(); ++i) u.push_back(FT(flat(i)));
  const std::size_t n = periodic ? poles + p : poles;
  if (periodic) {  // f extended by the period to n + p + 1 knots (u_{k} = u_{k-N} + T)
    const FT T = FT(g->Knot(g->NbKnots())) - FT(g->Knot(1));
    while (u.size() < n + p + 1) u.push_back(u[u.size() - poles] + T);
    u.resize(n + p + 1);
  }
  std::vector<Point_2> P;
  std::vector<FT> w;
  for (std::size_t k = 0; k < n; ++k) {
    const int j = static_cast<int>(k % poles) + 1;
    const gp_Pnt2d& q = g->Pole(j);
    P.push_back(Point_2(FT(q.X()), FT(q.Y())));
    if (g->IsRational()) w.push_back(FT(g->Weight(j)));
  }
  return Nurbs_curve_2<K>(p, std::move(u), std::move(P), std::move(w), periodic);
}

}  // namespace occt
}  // namespace fair

#endif  // FAIR_OCCT_GEOM2D_CONVERSION_H
