// Tests of the bicubic C2 tensor-product nets of eq. 11 (fair/Tensor_product_spline.h).

#include "test_support.h"

#include <fair/Cubic_spline_2.h>
#include <fair/Rational_bezier_2.h>
#include <fair/Tensor_product_spline.h>

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace {

using fair_test::q;

template <class K>
class TensorNet : public ::testing::Test {};
TYPED_TEST_SUITE(TensorNet, fair_test::All_kernels);

template <class K>
std::vector<std::vector<typename K::Vector_3>> random_net(std::mt19937& rng, std::size_t rows, std::size_t cols) {
  std::uniform_int_distribution<int> d(-64, 64);
  std::vector<std::vector<typename K::Vector_3>> net(rows);
  for (auto& row : net)
    for (std::size_t l = 0; l < cols; ++l) row.push_back(typename K::Vector_3(q<K>(d(rng), 8), q<K>(d(rng), 8), q<K>(d(rng), 8)));
  return net;
}

template <class K, class V>
::testing::AssertionResult same3(const V& a, const V& b, double rel) {
  for (int i = 0; i < 3; ++i) {
    ::testing::AssertionResult r = fair_test::same<K>(a[i], b[i], rel);
    if (!r) return r << " in coordinate " << i;
  }
  return ::testing::AssertionSuccess();
}

// net -> patches (eq. 2 tensored) -> net (eq. 11 with eq.-10 boundaries) is the identity, for
// every combination of open and closed directions on non-uniform breakpoints.
TYPED_TEST(TensorNet, NetPatchesNetRoundTrip) {
  typedef typename TypeParam::FT FT;
  typedef fair::Tensor_product_spline<typename TypeParam::Vector_3> S;
  std::mt19937 rng(11);
  const std::vector<FT> tu{q<TypeParam>(0), q<TypeParam>(1, 3), q<TypeParam>(3, 2), q<TypeParam>(2), q<TypeParam>(7, 2)};
  const std::vector<FT> tv{q<TypeParam>(-1), q<TypeParam>(1, 4), q<TypeParam>(1), q<TypeParam>(5, 2)};
  for (int mode = 0; mode < 4; ++mode) {
    const bool uc = mode & 1, vc = mode & 2;
    const auto net = random_net<TypeParam>(rng, uc ? 4 : 7, vc ? 3 : 6);
    const S s(tu, tv, net, uc, vc);
    const S back = S::from_bezier_patches(tu, tv, s.patches(), uc, vc);
    ASSERT_EQ(back.control_net().size(), net.size());
    for (std::size_t k = 0; k < net.size(); ++k)
      for (std::size_t l = 0; l < net[k].size(); ++l)
        EXPECT_TRUE((same3<TypeParam>(back.control_net()[k][l], net[k][l], 1e-12))) << "mode " << mode << " at " << k << ", " << l;
  }
}

// The printed eq. 11 (checked, not corrected): in the interior, with beta-dot_i = h_i / h_{i-1}
// along u and beta-ddot_j along v, the control point c_ij of breakpoints (u_i, v_j) is
// bd bdd b11 - bd (1 + bdd) b12 - (1 + bd) bdd b21 + (1 + bd)(1 + bdd) b22 of patch (i-1, j-1).
TYPED_TEST(TensorNet, InteriorControlPointsAreEquation11) {
  typedef typename TypeParam::FT FT;
  typedef typename TypeParam::Vector_3 V;
  typedef fair::Tensor_product_spline<V> S;
  std::mt19937 rng(5);
  const std::vector<FT> tu{q<TypeParam>(0), q<TypeParam>(1, 3), q<TypeParam>(3, 2), q<TypeParam>(2), q<TypeParam>(7, 2)};
  const std::vector<FT> tv{q<TypeParam>(-1), q<TypeParam>(1, 4), q<TypeParam>(1), q<TypeParam>(5, 2)};
  const S s(tu, tv, random_net<TypeParam>(rng, 7, 6));
  const auto patches = s.patches();
  for (std::size_t i = 1; i + 1 < tu.size(); ++i)
    for (std::size_t j = 1; j + 1 < tv.size(); ++j) {
      const FT bd = (tu[i + 1] - tu[i]) / (tu[i] - tu[i - 1]), bdd = (tv[j + 1] - tv[j]) / (tv[j] - tv[j - 1]);
      const auto& b = patches[i - 1][j - 1].b;
      const V c = bd * bdd * b[1][1] - bd * (1 + bdd) * b[1][2] - (1 + bd) * bdd * b[2][1] + (1 + bd) * (1 + bdd) * b[2][2];
      // The paper's c_ij is net entry (i + 1, j + 1) of an open-open net (d_{i+1} = c_i).
      EXPECT_TRUE((same3<TypeParam>(s.control_net()[i + 1][j + 1], c, 1e-12))) << i << ", " << j;
    }
}

TYPED_TEST(TensorNet, NonC2PatchesAndBadShapesAreRejected) {
  typedef typename TypeParam::FT FT;
  typedef typename TypeParam::Vector_3 V;
  typedef fair::Tensor_product_spline<V> S;
  std::mt19937 rng(7);
  const std::vector<FT> tu{q<TypeParam>(0), q<TypeParam>(1), q<TypeParam>(3)};
  const std::vector<FT> tv{q<TypeParam>(0), q<TypeParam>(2), q<TypeParam>(3)};
  const S s(tu, tv, random_net<TypeParam>(rng, 5, 5));
  auto patches = s.patches();
  patches[1][0].b[1][2] = patches[1][0].b[1][2] + V(q<TypeParam>(1, 4), 0, 0);
  EXPECT_THROW(S::from_bezier_patches(tu, tv, patches), fair::Invalid_input_error);
  EXPECT_THROW(S(tu, tv, random_net<TypeParam>(rng, 4, 5)), fair::Precondition_error);
  EXPECT_THROW(S(tu, tv, random_net<TypeParam>(rng, 5, 6)), fair::Precondition_error);
  EXPECT_THROW(S(std::vector<FT>{q<TypeParam>(0), q<TypeParam>(0)}, tv, random_net<TypeParam>(rng, 4, 5)),
               fair::Precondition_error);
  EXPECT_THROW(S(tu, tv, random_net<TypeParam>(rng, 2, 2), true, true), fair::Precondition_error);  // 2 patches closed
  EXPECT_THROW(S::from_bezier_patches(tu, tv, std::vector<std::vector<typename S::Patch>>(1)), fair::Precondition_error);
  EXPECT_THROW(s.point(q<TypeParam>(4), q<TypeParam>(1)), fair::Precondition_error);
}

// The patches of a Point_3 net are affine: a bilinear sheet (u, v, u v) sampled as a net stays it.
TEST(TensorNetPoints, Point3CoefficientsAreAffine) {
  typedef fair_test::SC_gmpq K;
  typedef K::Point_3 P;
  typedef fair::Tensor_product_spline<P> S;
  // The bicubic patch of f(u, v) = (u, v, u v) on [0,1]^2: b_rs = (r/3, s/3, r s/9).
  S::Patch p;
  for (int r = 0; r < 4; ++r)
    for (int s = 0; s < 4; ++s) p.b[r][s] = P(q<K>(r, 3), q<K>(s, 3), q<K>(r * s, 9));
  const S one = S::from_bezier_patches({q<K>(0), q<K>(1)}, {q<K>(0), q<K>(1)}, {{p}});
  EXPECT_EQ(one.point(q<K>(1, 5), q<K>(2, 7)), P(q<K>(1, 5), q<K>(2, 7), q<K>(2, 35)));
  // One patch open in both directions: the net is the patch itself (eq. 10 at every end).
  for (int r = 0; r < 4; ++r)
    for (int s = 0; s < 4; ++s) EXPECT_EQ(one.control_net()[r][s], p.b[r][s]);
}

template <class K>
class TensorRevolution : public ::testing::Test {};
using fair_test::Exact_kernels;
TYPED_TEST_SUITE(TensorRevolution, Exact_kernels);

// A surface of revolution of a rational spline profile over a rational quarter circle: patches of
// profile piece x circle piece (homogeneous 4D), converted by eq. 11. Exactly: the net is the
// product of the two curves' B-spline control points, and the surface reproduces the rotated
// profile, with cos^2 + sin^2 = 1, at rational parameters.
TYPED_TEST(TensorRevolution, ProfileTimesCircleIsReproducedExactly) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  typedef typename K::Point_2 P2;
  typedef fair::Rational_bezier_2<K> R;
  typedef fair::Homogeneous_point_3<FT> H;
  // Profile: an open rational spline right of the axis.
  const std::vector<FT> tu{q<K>(0), q<K>(1), q<K>(5, 2), q<K>(3), q<K>(9, 2)};
  const fair::Cubic_spline_2<K> profile(tu, {P2(1, -2), P2(2, -1), P2(q<K>(3, 2), 0), P2(3, 1), P2(2, 2), P2(1, 3), P2(2, 4)},
                                        {q<K>(1), q<K>(2), q<K>(1, 2), q<K>(1), q<K>(3), q<K>(1), q<K>(1)});
  // Circle: (1 - t^2, 2t) / (1 + t^2), t in [0, 1], degree-elevated to a cubic, split at 1/4, 3/5.
  const R quarter({P2(1, 0), P2(1, q<K>(2, 3)), P2(q<K>(1, 2), 1), P2(0, 1)}, {q<K>(1), q<K>(1), q<K>(4, 3), q<K>(2)});
  const auto a = quarter.split(q<K>(1, 4));
  const auto b = a.second.split(q<K>(7, 15));
  const std::vector<R> circle_pieces{a.first, b.first, b.second};
  const std::vector<FT> tv{q<K>(0), q<K>(1, 4), q<K>(3, 5), q<K>(1)};
  const fair::Cubic_spline_2<K> circle = fair::Cubic_spline_2<K>::from_rational_bezier_pieces(tv, circle_pieces);

  std::vector<std::vector<fair::Bicubic_bezier_patch<H>>> patches(profile.number_of_pieces());
  for (std::size_t i = 0; i < profile.number_of_pieces(); ++i)
    for (const R& c : circle_pieces) patches[i].push_back(fair::revolution_patch(profile.piece(i), c));
  const fair::Tensor_product_spline<H> surface = fair::Tensor_product_spline<H>::from_bezier_patches(tu, tv, patches);

  const auto& net = surface.control_net();
  ASSERT_EQ(net.size(), profile.number_of_control_points());
  for (std::size_t k = 0; k < net.size(); ++k) {
    ASSERT_EQ(net[k].size(), circle.number_of_control_points());
    const FT X = profile.weights()[k] * profile.control_points()[k].x(), Y = profile.weights()[k] * profile.control_points()[k].y(),
             W = profile.weights()[k];
    for (std::size_t l = 0; l < net[k].size(); ++l) {
      const FT C = circle.weights()[l] * circle.control_points()[l].x(), S = circle.weights()[l] * circle.control_points()[l].y(),
               V = circle.weights()[l];
      EXPECT_EQ(net[k][l], (H{X * C, Y * V, X * S, W * V})) << k << ", " << l;
    }
  }
  for (const FT& u : {q<K>(0), q<K>(1, 3), q<K>(5, 2), q<K>(31, 10), q<K>(9, 2)})
    for (const FT& v : {q<K>(0), q<K>(1, 7), q<K>(1, 2), q<K>(3, 5), q<K>(1)}) {
      const H h = surface.point(u, v);
      const P2 p = profile.point(u), c = circle.point(v);
      EXPECT_EQ(c.x() * c.x() + c.y() * c.y(), FT(1));
      EXPECT_EQ(h.x / h.w, p.x() * c.x());
      EXPECT_EQ(h.y / h.w, p.y());
      EXPECT_EQ(h.z / h.w, p.x() * c.y());
    }
}

} // namespace
