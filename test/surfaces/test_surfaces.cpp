// Tests of the surface-of-revolution renderer (fair/io/surface_of_revolution.h) and of the
// tensor-product nets of eq. 11 (fair/Tensor_product_spline.h). doc/surfaces_of_revolution.md.

#include "test_support.h"

#include <fair/Bezier_2.h>
#include <fair/Cubic_interpolating_spline_2.h>
#include <fair/Rational_bezier_2.h>
#include <fair/io/surface_of_revolution.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace {

using fair_test::q;

// The unit semicircle x >= 0 from (0,-1) over (1,0) to (0,1) as two rational quadratics with the
// rational parametrisation (1 - t^2, 2t) / (1 + t^2): control points (1,0), (1,1), (0,1), weights
// 1, 1, 2 (exact in every kernel), times `scale`.
template <class K>
std::vector<fair::Rational_bezier_2<K>> semicircle(typename K::FT scale = 1) {
  typedef typename K::Point_2 P;
  typedef typename K::FT FT;
  const FT s = scale;
  return {fair::Rational_bezier_2<K>({P(0, -s), P(s, -s), P(s, 0)}, {FT(2), FT(1), FT(1)}),
          fair::Rational_bezier_2<K>({P(s, 0), P(s, s), P(0, s)}, {FT(1), FT(1), FT(2)})};
}

// A line segment from (1,-1) up to (1,0) joined G1 to the quarter circle from (1,0) to (0,1) about
// the origin: the curvature jumps from 0 to 1 at the join (Fig. 14a of Karciauskas-Peters).
template <class K>
std::vector<fair::Rational_bezier_2<K>> line_and_quarter_circle() {
  typedef typename K::Point_2 P;
  typedef typename K::FT FT;
  return {fair::Rational_bezier_2<K>({P(1, -1), P(1, FT(-1) / 2), P(1, 0)}, {FT(1), FT(1), FT(1)}),
          fair::Rational_bezier_2<K>({P(1, 0), P(1, 1), P(0, 1)}, {FT(1), FT(1), FT(2)})};
}

template <class K>
class SurfaceRender : public ::testing::Test {};
TYPED_TEST_SUITE(SurfaceRender, fair_test::Floating_kernels);

fair::io::Surface_of_revolution_options small_options(int side) {
  fair::io::Surface_of_revolution_options o;
  o.width = o.height = side;
  return o;
}

// The semicircle centred on the axis sweeps the unit sphere: every pixel's refined surface point is
// on the sphere and projects to the pixel centre, and its normal is the sphere's, p / |p|.
TYPED_TEST(SurfaceRender, SphereNormalsAreTheAnalyticOnes) {
  const fair::io::Surface_of_revolution_render r =
      fair::io::render_surface_of_revolution(semicircle<TypeParam>(), small_options(160));
  std::size_t covered = 0, refined = 0;
  for (int y = 0; y < r.height; ++y)
    for (int x = 0; x < r.width; ++x) {
      const std::size_t p = static_cast<std::size_t>(y) * r.width + x;
      if (!r.covered[p]) continue;
      ++covered;
      if (!r.refined[p]) continue;
      ++refined;
      const std::array<double, 3> pos{{r.position[3 * p], r.position[3 * p + 1], r.position[3 * p + 2]}};
      const double len = std::sqrt(pos[0] * pos[0] + pos[1] * pos[1] + pos[2] * pos[2]);
      ASSERT_NEAR(len, 1.0, 1e-9) << "pixel " << x << ", " << y;
      for (int a = 0; a < 3; ++a) ASSERT_NEAR(r.normal[3 * p + a], pos[a] / len, 1e-9) << "pixel " << x << ", " << y;
      const std::array<double, 2> pix = r.project(pos);
      ASSERT_NEAR(pix[0], x + 0.5, 1e-6);
      ASSERT_NEAR(pix[1], y + 0.5, 1e-6);
    }
  // The disc of the sphere's outline: radius pixels_per_unit, area pi R^2 (the mesh polygon's
  // outline is inside the circle by less than a pixel).
  const double R = r.pixels_per_unit, area = std::acos(-1.0) * R * R;
  EXPECT_NEAR(static_cast<double>(covered), area, 2 * std::acos(-1.0) * R);
  EXPECT_GT(refined, 0.97 * covered);
}

// A symmetric profile, view and environment (tubes parallel to the axis, light in the symmetry
// plane) give an image symmetric in the vertical centre line: normals mirror to 1e-9 and the
// pixels agree (up to the few whose stripe phase sits on a threshold).
TYPED_TEST(SurfaceRender, SymmetricSceneGivesMirrorSymmetricImage) {
  fair::io::Surface_of_revolution_options o = small_options(160);
  o.stripe_tilt = 0;
  o.light = {{0, 1, 1}};
  const fair::io::Surface_of_revolution_render r = fair::io::render_surface_of_revolution(semicircle<TypeParam>(), o);
  std::size_t same = 0, total = 0, compared = 0;
  for (int y = 0; y < r.height; ++y)
    for (int x = 0; x < r.width; ++x) {
      const std::size_t p = static_cast<std::size_t>(y) * r.width + x;
      const std::size_t m = static_cast<std::size_t>(y) * r.width + (r.width - 1 - x);
      ++total;
      if (r.image.pixel(x, y) == r.image.pixel(r.width - 1 - x, y)) ++same;
      if (r.refined[p] && r.refined[m]) {
        ++compared;
        ASSERT_NEAR(r.normal[3 * p], -r.normal[3 * m], 1e-9);
        ASSERT_NEAR(r.normal[3 * p + 1], r.normal[3 * m + 1], 1e-9);
        ASSERT_NEAR(r.normal[3 * p + 2], r.normal[3 * m + 2], 1e-9);
        ASSERT_NEAR(r.stripe_phase[p], -r.stripe_phase[m], 1e-7);
      }
    }
  EXPECT_GT(compared, total / 3);
  EXPECT_GE(same, total - total / 200);
}

// Scaling the profile by 2^400 or 2^-400 (exact in binary floating point) changes nothing: the
// renderer normalises to the view without overflow or underflow, and the image is the same.
TYPED_TEST(SurfaceRender, HugeAndTinyProfilesRenderAlike) {
  const fair::io::Surface_of_revolution_options o = small_options(64);
  const std::vector<unsigned char> unit = fair::io::render_surface_of_revolution(semicircle<TypeParam>(), o).image.rgb;
  for (int e : {400, -400}) {
    const fair::io::Surface_of_revolution_render r =
        fair::io::render_surface_of_revolution(semicircle<TypeParam>(std::ldexp(1.0, e)), o);
    EXPECT_EQ(r.image.rgb, unit) << "scale 2^" << e;
    EXPECT_NEAR(r.scale / std::ldexp(1.0, e), std::sqrt(2.0), 1e-15);
  }
}

TYPED_TEST(SurfaceRender, DegenerateInputsAreTypedErrors) {
  typedef typename TypeParam::Point_2 P;
  typedef fair::Bezier_2<TypeParam> B;
  const fair::io::Surface_of_revolution_options o = small_options(32);
  EXPECT_THROW(fair::io::render_surface_of_revolution(std::vector<B>{}, o), fair::Invalid_input_error);
  // Crosses the y-axis.
  EXPECT_THROW(fair::io::render_surface_of_revolution(std::vector<B>{B({P(-1, 0), P(1, 1)})}, o),
               fair::Invalid_input_error);
  // On the axis.
  EXPECT_THROW(fair::io::render_surface_of_revolution(std::vector<B>{B({P(0, 0), P(0, 1)})}, o),
               fair::Invalid_input_error);
  // A point piece: zero tangent.
  EXPECT_THROW(fair::io::render_surface_of_revolution(std::vector<B>{B({P(1, 0), P(1, 0), P(1, 0)})}, o),
               fair::Invalid_input_error);
  // A cusp at u = 1/2 (control polygon folds back), found by the mesh samples.
  EXPECT_THROW(fair::io::render_surface_of_revolution(std::vector<B>{B(P(1, 0), P(2, 1), P(1, 1), P(2, 0))}, o),
               fair::Invalid_input_error);
  // Not finite.
  const double nan = std::nan("");
  EXPECT_THROW(fair::io::render_surface_of_revolution(std::vector<B>{B({P(1, 0), P(nan, 1)})}, o),
               fair::Invalid_input_error);
  // Touching the axis at an end is fine (the poles of the sphere), and so is the other side.
  EXPECT_NO_THROW(fair::io::render_surface_of_revolution(std::vector<B>{B({P(0, 0), P(-1, 1)})}, o));
  // Options.
  const std::vector<B> ok{B({P(1, 0), P(1, 1)})};
  fair::io::Surface_of_revolution_options bad = o;
  bad.width = 0;
  EXPECT_THROW(fair::io::render_surface_of_revolution(ok, bad), fair::Precondition_error);
  bad = o;
  bad.axis_direction = {{0, 0}};
  EXPECT_THROW(fair::io::render_surface_of_revolution(ok, bad), fair::Precondition_error);
  bad = o;
  bad.elevation = nan;
  EXPECT_THROW(fair::io::render_surface_of_revolution(ok, bad), fair::Precondition_error);
  bad = o;
  bad.stripe_width = 1;
  EXPECT_THROW(fair::io::render_surface_of_revolution(ok, bad), fair::Precondition_error);
  bad = o;
  bad.axis_point = {{nan, 0}};
  EXPECT_THROW(fair::io::render_surface_of_revolution(ok, bad), fair::Precondition_error);
}

// The exact kernels render too (each evaluation exact, then rounded): the same sphere image as
// in double, up to the pixels whose stripe phase sits on a threshold.
TEST(SurfaceRenderExact, EpeckSphereMatchesDouble) {
  const fair::io::Surface_of_revolution_options o = small_options(40);
  const auto a = fair::io::render_surface_of_revolution(semicircle<fair_test::EPECK>(), o).image.rgb;
  const auto b = fair::io::render_surface_of_revolution(semicircle<fair_test::SC_double>(), o).image.rgb;
  ASSERT_EQ(a.size(), b.size());
  std::size_t differ = 0;
  for (std::size_t i = 0; i < a.size(); ++i) differ += std::abs(int(a[i]) - int(b[i])) > 2;
  EXPECT_LE(differ, a.size() / 100);
}

TEST(SurfacePng, RoundTripKeepsEveryPixel) {
  const fair::io::Rgb_image im =
      fair::io::render_surface_of_revolution(semicircle<fair_test::SC_double>(), small_options(96)).image;
  const std::string path = ::testing::TempDir() + "fair_surface_round_trip.png";
  fair::io::write_png_file(path, im);
  const fair::io::Rgb_image back = fair::io::read_png_file(path);
  std::remove(path.c_str());
  EXPECT_EQ(back.width, 96);
  EXPECT_EQ(back.height, 96);
  EXPECT_EQ(back.rgb, im.rgb);
  // In memory too, and the PNG signature.
  const std::string bytes = fair::io::png_bytes(im);
  EXPECT_EQ(bytes.substr(1, 3), "PNG");
  EXPECT_EQ(fair::io::read_png_bytes(bytes).rgb, im.rgb);
  EXPECT_THROW(fair::io::read_png_bytes("not a png at all"), fair::Parse_error);
  EXPECT_THROW(fair::io::read_png_bytes(bytes.substr(0, bytes.size() / 2)), fair::Parse_error);
  EXPECT_THROW(fair::io::read_png_file(path), fair::Parse_error);
  fair::io::Rgb_image wrong = im;
  wrong.rgb.pop_back();
  EXPECT_THROW(fair::io::png_bytes(wrong), fair::Precondition_error);
}

TEST(SurfacePng, SvgEmbedsThePngAsBase64) {
  EXPECT_EQ(fair::io::internal::render::base64("Man"), "TWFu");
  EXPECT_EQ(fair::io::internal::render::base64("Ma"), "TWE=");
  EXPECT_EQ(fair::io::internal::render::base64("M"), "TQ==");
  EXPECT_EQ(fair::io::internal::render::base64(""), "");
  fair::io::Surface_of_revolution_options o = small_options(24);
  const auto pieces = semicircle<fair_test::SC_double>();
  const std::string svg = fair::io::surface_of_revolution_svg(pieces, o);
  const std::string png = fair::io::surface_of_revolution_png(pieces, o);
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_NE(svg.find("width=\"24\" height=\"24\""), std::string::npos);
  EXPECT_NE(svg.find("href=\"data:image/png;base64," + fair::io::internal::render::base64(png) + "\""),
            std::string::npos);
}

// The stripe kink (the paper's test, Fig. 14; fair::io::stripe_kink): the second difference of
// the stripe function f across the join row, along image columns. f depends on the normal only,
// so on a G1 profile with a curvature jump its derivative along the meridian jumps (second
// difference ~ the jump, independent of resolution); on a C2 profile it is continuous (second
// difference ~ f'' times a pixel squared).
template <class Pieces>
double stripe_kink(const Pieces& pieces, double join_s, const fair::io::Surface_of_revolution_options& o) {
  const fair::io::Stripe_kink k =
      fair::io::stripe_kink(fair::io::render_surface_of_revolution(pieces, o), join_s, o.stripes);
  EXPECT_GT(k.columns, 5u);
  return k.kink;
}

TYPED_TEST(SurfaceRender, CurvatureJumpKinksTheStripesAndC2DoesNot) {
  typedef typename TypeParam::Point_2 P;
  fair::io::Surface_of_revolution_options o = small_options(240);
  o.axis_point = {{-0.5, 0}};
  const auto g1 = line_and_quarter_circle<TypeParam>();
  // The classic C2 interpolant (chordal knots) through samples of the same curve, the join (1,0) a sample.
  std::vector<P> samples;
  for (int k = 0; k < 4; ++k) samples.push_back(P(1, -1 + 0.25 * k));
  const double half_pi = 2 * std::atan(1.0);
  for (int k = 0; k <= 6; ++k) samples.push_back(P(std::cos(half_pi * k / 6), std::sin(half_pi * k / 6)));
  const fair::Cubic_interpolating_spline_2<TypeParam> c2(samples, fair::Cubic_interpolating_spline_options{false, fair::Spline_end_condition::NATURAL, fair::Knot_spacing::CHORDAL});
  const double kink_g1 = stripe_kink(g1, 1.0, o);
  const double kink_c2 = stripe_kink(c2.pieces(), 4.0, o);
  std::printf("stripe kink: G1 %.5f, C2 %.5f\n", kink_g1, kink_c2);
  EXPECT_GT(kink_g1, 4 * kink_c2);
  // The statistic sees the join, not the surface: a parallel a tenth of the arc above the join is
  // smooth (higher up the columns run into the pole of the environment, R parallel to the tubes,
  // where f is singular and every difference is large).
  EXPECT_LT(stripe_kink(g1, 1.1, o), kink_g1 / 4);
}

} // namespace
