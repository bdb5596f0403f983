// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The check every family's nurbs() must pass (issue 26 §1): the NURBS is the family's pieces --
// nurbs().pieces() has the family's control points and (normalised) weights, piece by piece, and
// nurbs().point(u) at rational parameters of every span is the family's piece at the matching
// local parameter -- exactly in an exact kernel, to rounding in double. Plus the knot structure
// (multiplicities inside the domain) the family documents.

#ifndef FAIR_TEST_NURBS_FAMILY_CHECKS_H
#define FAIR_TEST_NURBS_FAMILY_CHECKS_H

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

// `pieces` (the family's, each on [0, 1]) against the NURBS `c`: same number, same control
// points, same weights up to one factor per piece, and c.point(b_j + t (b_{j+1} - b_j)) ==
// pieces[j].point(t) at t = 0, 1/3, 1/2, 5/7, 1. `rel`: the tolerance in double.
template <class K, class Piece>
void expect_nurbs_is_pieces(const fair::Nurbs_curve_2<K>& c, const std::vector<Piece>& pieces, const std::string& what,
                            double rel = 1e-12) {
  typedef typename K::FT FT;
  SCOPED_TRACE(what);
  ASSERT_EQ(c.number_of_pieces(), pieces.size());
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
