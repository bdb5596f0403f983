// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Surfaces of revolution with reflection lines (zebra stripes): the test by which Karciauskas and
// Peters judge a profile curve [KP13], Figs. 13, 14. A planar profile -- any range of CurvePiece_2
// pieces, e.g. Cubic_spline_2::pieces() -- is rotated about an axis in its plane and rendered in
// software (no OpenGL) with the reflection lines of parallel light tubes [Kla80] and diffuse
// shading. The surface normal comes from each piece's exact derivative (the profile normal,
// rotated), evaluated per pixel at the surface point that projects to the pixel centre, so the
// stripes show what the curve's continuity is: a tangent-continuous profile gives continuous
// stripes, a curvature jump gives a kink in them, a curvature-continuous profile smooth ones.
// Method, accuracy and options: doc/surfaces_of_revolution.md.
//
// Output: an RGB buffer with per-pixel normals, positions, parameters and stripe function (for
// tests and analysis), a PNG (libpng) and an SVG embedding the PNG as a base64 data URI.
// Needs libpng (target fair::io links PNG::PNG).

#ifndef FAIR_IO_SURFACE_OF_REVOLUTION_H
#define FAIR_IO_SURFACE_OF_REVOLUTION_H

#include <fair/Errors.h>
#include <fair/internal/common/constants.h>
#include <fair/io/internal/render/png.h>
#include <fair/io/internal/render/profile.h>
#include <fair/io/internal/render/raster.h>
#include <fair/io/svg.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

namespace fair {
namespace io {

/// Options of the renderer. Angles in radians; the axis lies in the profile's plane.
struct Surface_of_revolution_options {
  std::array<double, 2> axis_point{{0, 0}};      ///< a point of the axis (profile coordinates)
  std::array<double, 2> axis_direction{{0, 1}};  ///< its direction (default: the y-axis), not zero
  int width = 480, height = 480;                 ///< image size in pixels, 1..16384
  double elevation = 0.35;       ///< the viewer above the plane perpendicular to the axis, in (-pi/2, pi/2)
  int stripes = 16;              ///< light tubes around the environment (a full turn); integer: no seam
  double stripe_width = 0.5;     ///< dark part of each stripe period, in (0, 1)
  double stripe_tilt = 0.35;     ///< angle of the tubes from the axis, towards the screen's x axis
  double diffuse = 0.35;         ///< weight of the diffuse shading, in [0, 1]
  std::array<double, 3> light{{-0.4, 0.7, 0.6}};  ///< direction towards the light (world frame), not zero
  int samples_per_piece = 32;    ///< mesh rows per piece (the starting guess of the inverse mapping), 1..4096
  int angular_samples = 128;     ///< mesh columns around the axis, 8..16384
  bool inverse_mapping = true;   ///< per pixel, the exact surface point (Newton); else the mesh's interpolation
};

/// An 8-bit RGB image, rows top to bottom, 3 bytes per pixel.
struct Rgb_image {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;
  std::array<unsigned char, 3> pixel(int x, int y) const {
    fair::internal::require(x >= 0 && y >= 0 && x < width && y < height, "Rgb_image::pixel: (", x, ", ", y,
                            ") is outside ", width, " x ", height);
    const std::size_t q = 3 * (static_cast<std::size_t>(y) * width + x);
    return {{rgb[q], rgb[q + 1], rgb[q + 2]}};
  }
};

/// One rendering with its per-pixel data (pixel q = y * width + x). The world frame is that of
/// the axis: x = r cos(phi), y = h, z = r sin(phi), with h the coordinate along the axis
/// direction from the axis point and r the distance from the axis (profile units).
struct Surface_of_revolution_render {
  Rgb_image image;
  int width = 0, height = 0;
  std::vector<unsigned char> covered;   ///< 1 where the surface is seen
  std::vector<unsigned char> refined;   ///< 1 where the inverse mapping hit the pixel centre (to 1e-12 of the view)
  std::vector<double> normal;           ///< 3 per pixel: unit normal facing the viewer
  std::vector<double> position;         ///< 3 per pixel: the surface point seen
  std::vector<double> parameter;        ///< 2 per pixel: profile parameter s = piece + u, and phi
  std::vector<double> stripe_phase;     ///< the stripe function f (dark where |f - round(f)| < width/2)
  double view_x[3] = {1, 0, 0}, view_y[3] = {0, 1, 0}, view_direction[3] = {0, 0, 1};  ///< screen axes, towards the viewer
  double axial_center = 0, scale = 1, pixels_per_unit = 1;

  /// Pixel coordinates (column, row; pixel centres at +0.5) of a world point.
  std::array<double, 2> project(const std::array<double, 3>& p) const {
    const double q[3] = {p[0], p[1] - axial_center, p[2]};
    const double sx = q[0] * view_x[0] + q[1] * view_x[1] + q[2] * view_x[2];
    const double sy = q[0] * view_y[0] + q[1] * view_y[1] + q[2] * view_y[2];
    return {{0.5 * width + pixels_per_unit * sx, 0.5 * height - pixels_per_unit * sy}};
  }
};

namespace internal {
inline void check_render_options(const Surface_of_revolution_options& o) {
  using fair::internal::require;
  const char* f = "surface_of_revolution: ";
  require(o.width >= 1 && o.height >= 1 && o.width <= render::max_png_side && o.height <= render::max_png_side, f,
          "image size ", o.width, " x ", o.height, " is not in 1..", render::max_png_side);
  require(std::isfinite(o.axis_point[0]) && std::isfinite(o.axis_point[1]), f, "the axis point (", o.axis_point[0],
          ", ", o.axis_point[1], ") is not finite");
  const double m = std::max(std::fabs(o.axis_direction[0]), std::fabs(o.axis_direction[1]));
  require(std::isfinite(m) && m > 0, f, "the axis direction (", o.axis_direction[0], ", ", o.axis_direction[1],
          ") is zero or not finite");
  using fair::internal::common::half_pi;
  require(std::isfinite(o.elevation) && std::fabs(o.elevation) < half_pi, f, "elevation ", o.elevation,
          " is not in (-pi/2, pi/2)");
  require(o.stripes >= 1 && o.stripes <= 4096, f, "stripes = ", o.stripes, " is not in 1..4096");
  require(o.stripe_width > 0 && o.stripe_width < 1, f, "stripe_width = ", o.stripe_width, " is not in (0, 1)");
  require(std::isfinite(o.stripe_tilt), f, "stripe_tilt = ", o.stripe_tilt, " is not finite");
  require(o.diffuse >= 0 && o.diffuse <= 1, f, "diffuse = ", o.diffuse, " is not in [0, 1]");
  const double l = std::max({std::fabs(o.light[0]), std::fabs(o.light[1]), std::fabs(o.light[2])});
  require(std::isfinite(l) && l > 0, f, "the light direction (", o.light[0], ", ", o.light[1], ", ", o.light[2],
          ") is zero or not finite");
  require(o.samples_per_piece >= 1 && o.samples_per_piece <= 4096, f, "samples_per_piece = ", o.samples_per_piece,
          " is not in 1..4096");
  require(o.angular_samples >= 8 && o.angular_samples <= 16384, f, "angular_samples = ", o.angular_samples,
          " is not in 8..16384");
}
} // namespace internal

/// Renders the surface of revolution of the profile `pieces` (a range of CurvePiece_2 pieces,
/// joined end to start) about the axis of `options`. The profile is fitted to the view whatever
/// its coordinates (1e-300 .. 1e300). Cost: O(width * height) evaluations of the pieces (a few
/// Newton steps per pixel) plus the mesh; in an exact kernel each evaluation is exact and slow.
/// \throws Precondition_error on invalid options; Invalid_input_error if the range is empty, a
/// point or derivative is not finite, a tangent vanishes (the normal is undefined), the profile
/// crosses the axis (both sides beyond 1e-12 of its extent) or lies on it.
template <class PieceRange>
Surface_of_revolution_render render_surface_of_revolution(const PieceRange& pieces,
                                                          const Surface_of_revolution_options& options = {}) {
  internal::check_render_options(options);
  typedef typename std::decay<decltype(*std::begin(pieces))>::type Piece;
  std::vector<Piece> list(std::begin(pieces), std::end(pieces));
  if (list.empty()) throw Invalid_input_error("surface_of_revolution: the profile has no piece");
  internal::render::Profile<Piece> profile(std::move(list), options.axis_point[0], options.axis_point[1],
                                           options.axis_direction[0], options.axis_direction[1]);
  internal::render::fit_frame(profile, options.samples_per_piece);
  Surface_of_revolution_render r;
  internal::render::render(profile, options, r);
  return r;
}

/// The stripe kink across a parallel of the surface (the paper's test, Fig. 14): in the image
/// columns of the central band (width/6 either side of the middle, every 4th column), the row
/// where the profile parameter s crosses `join_s` (s = piece + u) between two refined pixels,
/// and there the largest |second difference| of the stripe function along the column (rows
/// -2..+2 about it, wrapped modulo the stripe period). The stripe function depends on the normal
/// only: across a curvature jump its derivative along the meridian jumps, and the second
/// difference is of the size of that jump whatever the resolution; across a curvature-continuous
/// join it is of the size of f'' times a pixel squared. Meaningful away from the poles of the
/// environment (where R is parallel to the tubes, f is singular and every difference is large).
struct Stripe_kink {
  double kink = 0;          ///< the largest |second difference| found (stripe periods per pixel^2)
  std::size_t columns = 0;  ///< columns in which the join was found
};

inline Stripe_kink stripe_kink(const Surface_of_revolution_render& r, double join_s, int stripes) {
  Stripe_kink out;
  auto wrapped = [stripes](double a, double b) { return internal::render::phase_difference(a, b, stripes); };
  const int band = std::max(1, r.width / 6);
  for (int x = std::max(0, r.width / 2 - band); x <= std::min(r.width - 1, r.width / 2 + band); x += 4) {
    int join = -1;
    for (int y = 3; y + 3 < r.height && join < 0; ++y) {
      const std::size_t a = static_cast<std::size_t>(y - 1) * r.width + x, b = a + r.width;
      if (r.covered[a] && r.covered[b] && r.refined[a] && r.refined[b] &&
          (r.parameter[2 * a] - join_s) * (r.parameter[2 * b] - join_s) <= 0 && r.parameter[2 * a] != r.parameter[2 * b])
        join = y;
    }
    if (join < 0) continue;
    bool seen = true;
    double worst = 0;
    for (int y = join - 2; y <= join + 2; ++y) {
      const std::size_t p = static_cast<std::size_t>(y) * r.width + x;
      if (!r.covered[p - r.width] || !r.covered[p] || !r.covered[p + r.width]) seen = false;
      const double d1 = wrapped(r.stripe_phase[p + r.width], r.stripe_phase[p]);
      const double d0 = wrapped(r.stripe_phase[p], r.stripe_phase[p - r.width]);
      worst = std::max(worst, std::fabs(d1 - d0));
    }
    if (!seen) continue;
    ++out.columns;
    out.kink = std::max(out.kink, worst);
  }
  return out;
}

/// The PNG file content of `image`. \throws Precondition_error if the buffer does not match the size.
inline std::string png_bytes(const Rgb_image& image) {
  return internal::render::encode_png(image.rgb, image.width, image.height);
}

/// Decodes PNG file content (any bit depth and colour type, converted to 8-bit RGB).
/// \throws Parse_error if `bytes` is not a readable PNG; `where` names the source in the message.
inline Rgb_image read_png_bytes(const std::string& bytes, const std::string& where = "PNG data") {
  Rgb_image im;
  internal::render::decode_png(bytes, where, im.width, im.height, im.rgb);
  return im;
}

/// Writes `image` as a PNG file. \throws Error if the file cannot be written.
inline void write_png_file(const std::string& path, const Rgb_image& image) {
  const std::string bytes = png_bytes(image);
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out) throw Error("write_png_file: cannot write " + path);
}

/// Reads a PNG file. \throws Parse_error if it cannot be read or is not a PNG.
inline Rgb_image read_png_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Parse_error(path, 0, "cannot open");
  std::ostringstream s;
  s << in.rdbuf();
  return read_png_bytes(s.str(), path);
}

/// An SVG document of the image's size showing `image` (a PNG in a base64 data URI), with an
/// optional title (escaped) as its accessible name.
inline std::string png_svg(const Rgb_image& image, const std::string& title = std::string()) {
  const std::string w = std::to_string(image.width), h = std::to_string(image.height);
  const std::string t = xml_escape(title);
  std::string out = "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\" width=\"" +
                    w + "\" height=\"" + h + "\" viewBox=\"0 0 " + w + " " + h + "\">\n";
  if (!t.empty()) out += "<title>" + t + "</title>\n";
  const std::string uri = "data:image/png;base64," + internal::render::base64(png_bytes(image));
  out += "<image width=\"" + w + "\" height=\"" + h + "\" href=\"" + uri + "\" xlink:href=\"" + uri + "\"/>\n</svg>\n";
  return out;
}

/// One call: the surface of revolution of `pieces` with its stripes, as an SVG embedding the PNG.
template <class PieceRange>
std::string surface_of_revolution_svg(const PieceRange& pieces, const Surface_of_revolution_options& options = {}) {
  return png_svg(render_surface_of_revolution(pieces, options).image, "surface of revolution with reflection lines");
}

/// The same as a PNG file content.
template <class PieceRange>
std::string surface_of_revolution_png(const PieceRange& pieces, const Surface_of_revolution_options& options = {}) {
  return png_bytes(render_surface_of_revolution(pieces, options).image);
}

} // namespace io
} // namespace fair

#endif // FAIR_IO_SURFACE_OF_REVOLUTION_H
