// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The check every family's nurbs() must pass (issue 26 §1): the NURBS is the family's pieces --
// nurbs().pieces() has the family's control points and (normalised) weights, piece by piece, and
// nurbs().point(u) at rational parameters of every span is the family's piece at the matching
// local parameter -- exactly in an exact kernel, to rounding in double. Plus the knot structure
// (multiplicities inside the domain) the family documents.
//
// nurbs().pieces() patch their joints (a joint is computed once and given to both pieces), and
// so do the families' pieces(): comparing the two alone could hide a knot vector whose curve
// is not continuous, or a closed form whose periodic extension does not wrap. So every check
// also evaluates the NURBS by the literal Cox-de Boor recursion (cox_de_boor.h) at every
// breakpoint from both sides and across the seam of a closed curve (review finding 2).

#ifndef FAIR_TEST_NURBS_FAMILY_CHECKS_H
#define FAIR_TEST_NURBS_FAMILY_CHECKS_H

#include "cox_de_boor.h"
#include "test_support.h"

#include <fair/Nurbs_curve_2.h>
#include <fair/internal/common/piece_detection.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace fair_test {

// The typed kernels of the family tests: double and the two exact kernels (EPICK is the double
// path again; the sanitizer stage keeps its subset).
#ifdef FAIR_TEST_KERNEL_SUBSET
typedef All_kernels Family_kernels;
#else
typedef ::testing::Types<SC_double, EPECK, SC_gmpq> Family_kernels;
#endif

template <class Piece>
std::vector<typename Piece::FT> weights_of(const Piece& piece) {
  if constexpr (fair::internal::common::Is_bezier<Piece>::value) {
    return std::vector<typename Piece::FT>(piece.degree() + 1, typename Piece::FT(1));
  } else {
    const auto w = piece.weights();
    return std::vector<typename Piece::FT>(w.begin(), w.end());
  }
}

// The NURBS `c` by Cox-de Boor (from its knots, control points and weights only) at the joints
// of the family's `pieces`: c(b_j^+) is piece j's start and c(b_{j+1}^-) its end, for every j;
// closed, the wrap too: c(u_p^-) -- the periodic extension's span before the domain -- is the
// last piece's end and c(u_n^+) the first piece's start (and the family's loop closes). Exactly
// in an exact kernel.
template <class K, class Piece>
void expect_joints_by_cox_de_boor(const fair::Nurbs_curve_2<K>& c, const std::vector<Piece>& pieces, double rel) {
  typedef typename K::FT FT;
  const std::vector<FT> b = c.breakpoints();
  ASSERT_EQ(b.size(), pieces.size() + 1);
  auto first = [](const Piece& piece) { return piece.control_points()[0]; };
  auto last = [](const Piece& piece) { return piece.control_points()[piece.degree()]; };
  for (std::size_t j = 0; j < pieces.size(); ++j) {
    EXPECT_TRUE(same<K>(cox_de_boor(c, b[j], Side::RIGHT), first(pieces[j]), rel)) << "start of piece " << j;
    EXPECT_TRUE(same<K>(cox_de_boor(c, b[j + 1], Side::LEFT), last(pieces[j]), rel)) << "end of piece " << j;
  }
  if (!c.is_closed()) return;
  EXPECT_TRUE(same<K>(last(pieces.back()), first(pieces.front()), rel)) << "the family's loop closes";
  EXPECT_TRUE(same<K>(cox_de_boor(c, b.front(), Side::LEFT), last(pieces.back()), rel)) << "c(u_p^-)";
  EXPECT_TRUE(same<K>(cox_de_boor(c, b.back(), Side::RIGHT), first(pieces.front()), rel)) << "c(u_n^+)";
}

// `pieces` (the family's, each on [0, 1]) against the NURBS `c`: same number, same control
// points, same weights up to one factor per piece, and c.point(b_j + t (b_{j+1} - b_j)) ==
// pieces[j].point(t) at t = 0, 1/3, 1/2, 5/7, 1. `rel`: the tolerance in double.
template <class K, class Piece>
void expect_nurbs_is_pieces(const fair::Nurbs_curve_2<K>& c, const std::vector<Piece>& pieces, const std::string& what,
                            double rel = 1e-12) {
  typedef typename K::FT FT;
  SCOPED_TRACE(what);
  ASSERT_EQ(c.number_of_pieces(), pieces.size());
  expect_joints_by_cox_de_boor(c, pieces, rel);
  const std::vector<FT> b = c.breakpoints();
  const FT ts[] = {FT(0), FT(1) / FT(3), FT(1) / FT(2), FT(5) / FT(7), FT(1)};
  for (std::size_t j = 0; j < pieces.size(); ++j) {
    const auto& mine = c.pieces()[j];
    ASSERT_EQ(mine.degree(), pieces[j].degree()) << "piece " << j;
    const auto cp = pieces[j].control_points();
    const std::vector<FT> w = weights_of(pieces[j]);
    for (std::size_t k = 0; k < cp.size(); ++k) {
      EXPECT_TRUE(same<K>(mine.control_point(k), cp[k], rel)) << "piece " << j << " control point " << k;
      // w_k / w_0 equal (the same rational piece)
      EXPECT_TRUE(same<K>(mine.weight(k) * w[0], w[k] * mine.weight(0), rel)) << "piece " << j << " weight " << k;
    }
    for (const FT& t : ts)
      EXPECT_TRUE(same<K>(c.point(b[j] + t * (b[j + 1] - b[j])), pieces[j].point(t), rel))
          << "piece " << j << " at t = " << CGAL::to_double(t);
  }
}

// The multiplicity of every knot value strictly inside the domain.
template <class K>
std::vector<std::size_t> interior_multiplicities(const fair::Nurbs_curve_2<K>& c) {
  std::vector<std::size_t> m;
  const std::vector<typename K::FT> b = c.breakpoints();
  for (std::size_t j = 1; j + 1 < b.size(); ++j)
    m.push_back(static_cast<std::size_t>(std::count(c.knots().begin(), c.knots().end(), b[j])));
  return m;
}

}  // namespace fair_test

#endif  // FAIR_TEST_NURBS_FAMILY_CHECKS_H
