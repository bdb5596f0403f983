// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The software renderer of fair/io/surface_of_revolution.h (method: doc/surfaces_of_revolution.md).
//
//  1. Mesh: the surface S(s, phi) = (r(s) cos phi, h(s), r(s) sin phi) of the normalised profile
//     (profile.h) is sampled on a grid (samples_per_piece per piece) x (angular_samples), each grid
//     cell split into two triangles, projected orthographically (view direction V, screen axes
//     ex, ey) and rasterised with a z-buffer. Each pixel keeps the (s, phi) interpolated
//     barycentrically over the nearest triangle: only a starting guess.
//  2. Inverse mapping: per pixel, Newton's method on the two equations
//     S(s, phi).ex = x_pixel, S(s, phi).ey = y_pixel finds the surface point whose projection is
//     the pixel centre (to 1e-12 of the view radius). Where it does not converge within
//     newton_iterations (at the silhouette, where the Jacobian is singular) or lands on another
//     sheet (its depth differs from the z-buffer's by more than depth_slack pixels, or it faces
//     the other way than the z-buffer's triangle), the
//     interpolated (s, phi) is kept and `refined` is 0.
//  3. Normal: from the piece's exact derivative at (s, phi): N = (n_r cos phi, n_h, n_r sin phi),
//     (n_r, n_h) = (t_h, -t_r) the profile's unit normal; turned to face the viewer.
//  4. Reflection lines: R = 2 (N.V) N - V, reflected in an environment of light tubes parallel to
//     L = (sin tau, cos tau, 0) spaced evenly in angle around L: the stripe function is
//     f = stripes * atan2(R.e1, R.e2) / (2 pi), e1 = (cos tau, -sin tau, 0), e2 = (0, 0, 1), and a
//     pixel is dark where |f - round(f)| < stripe_width / 2 (a dark band centred on each integer,
//     so that the image of a mirror-symmetric scene is mirror-symmetric). f is a function of the
//     normal only: continuous where the surface is G1, with a continuous gradient where it is G2.
//     Edges are anti-aliased over the pixel footprint of f (its differences to the neighbours).
//  5. Shade: colour * ((1 - diffuse) + diffuse * max(0, N.light)).

#ifndef FAIR_IO_INTERNAL_RENDER_RASTER_H
#define FAIR_IO_INTERNAL_RENDER_RASTER_H

#include <fair/Errors.h>
#include <fair/internal/common/constants.h>
#include <fair/io/internal/render/profile.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace fair {
namespace io {
namespace internal {
namespace render {

constexpr int newton_iterations = 12;        // quadratic convergence from a sub-pixel guess needs 3-5
constexpr double newton_tolerance = 1e-12;   // residual, in units of the view radius
constexpr double depth_slack = 3.0;          // pixels: a Newton solution deeper than this is another sheet
constexpr double view_margin = 0.94;         // the unit ball fills 94% of the smaller image side

typedef std::array<double, 3> V3;

inline double dot(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/// The orthographic camera: screen x = k P.ex + W/2, row coordinate H/2 - k P.ey.
struct Camera {
  V3 ex{{1, 0, 0}}, ey{{0, 1, 0}}, view{{0, 0, 1}};
  double k = 1, half_w = 0, half_h = 0;
};

inline Camera make_camera(int width, int height, double elevation) {
  Camera c;
  const double se = std::sin(elevation), ce = std::cos(elevation);
  c.ex = V3{{1, 0, 0}};
  c.ey = V3{{0, ce, -se}};
  c.view = V3{{0, se, ce}};  // ex x ey: towards the viewer
  c.k = view_margin * 0.5 * std::min(width, height);
  c.half_w = 0.5 * width;
  c.half_h = 0.5 * height;
  return c;
}

inline V3 surface_point(const Profile_jet& j, double phi) {
  return V3{{j.r * std::cos(phi), j.h, j.r * std::sin(phi)}};
}

/// Buffers of one rendering (the fields of the public Surface_of_revolution_render).
template <class Options, class Result>
void shade_pixels(const Options& o, const Camera& cam, Result& res, const std::vector<double>& phase_buffer);

/// Renders `profile` (its frame fitted) with options `o` into `res` (a Surface_of_revolution_render).
template <class Piece, class Options, class Result>
void render(const Profile<Piece>& profile, const Options& o, Result& res) {
  const int W = o.width, H = o.height;
  const std::size_t npix = static_cast<std::size_t>(W) * static_cast<std::size_t>(H);
  const Camera cam = make_camera(W, H, o.elevation);
  const Profile_frame& fr = profile.frame();
  res.width = W;
  res.height = H;
  res.covered.assign(npix, 0);
  res.refined.assign(npix, 0);
  res.normal.assign(3 * npix, 0.0);
  res.position.assign(3 * npix, 0.0);
  res.parameter.assign(2 * npix, 0.0);
  res.stripe_phase.assign(npix, 0.0);
  for (int a = 0; a < 3; ++a) {
    res.view_x[a] = cam.ex[a];
    res.view_y[a] = cam.ey[a];
    res.view_direction[a] = cam.view[a];
  }
  res.axial_center = fr.h_center;
  res.scale = fr.scale;
  res.pixels_per_unit = cam.k / fr.scale;

  // 1. The mesh vertices: jets at the global parameters s, angles phi.
  const std::size_t n = profile.size();
  const int per = o.samples_per_piece, na = o.angular_samples;
  std::vector<double> svals;
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < per; ++k) svals.push_back(static_cast<double>(i) + static_cast<double>(k) / per);
  svals.push_back(static_cast<double>(n));
  using fair::internal::common::two_pi;
  std::vector<double> cs(na + 1), sn(na + 1), phis(na + 1);
  for (int j = 0; j <= na; ++j) {
    phis[j] = two_pi * j / na;
    cs[j] = std::cos(phis[j]);
    sn[j] = std::sin(phis[j]);
  }
  struct Vertex {
    double x, y, depth, s, phi;
  };
  const std::size_t ns = svals.size();
  std::vector<Vertex> vert(ns * (na + 1));
  for (std::size_t a = 0; a < ns; ++a) {
    const Profile_jet jt = profile.jet_at(svals[a]);
    for (int j = 0; j <= na; ++j) {
      const V3 p{{jt.r * cs[j], jt.h, jt.r * sn[j]}};
      vert[a * (na + 1) + j] =
          Vertex{cam.half_w + cam.k * dot(p, cam.ex), cam.half_h - cam.k * dot(p, cam.ey), dot(p, cam.view), svals[a],
                 phis[j]};
    }
  }

  // z-buffer rasterisation of the triangles; per pixel the interpolated (s, phi) and depth.
  std::vector<double> zbuf(npix, -HUGE_VAL);
  std::vector<signed char> facing(npix, 0);  // the sign of the nearest triangle's area
  auto raster_triangle = [&](const Vertex& A, const Vertex& B, const Vertex& C) {
    const double area = (B.x - A.x) * (C.y - A.y) - (B.y - A.y) * (C.x - A.x);
    if (!(std::fabs(area) > 1e-14)) return;
    const int x0 = std::max(0, static_cast<int>(std::floor(std::min({A.x, B.x, C.x}))));
    const int x1 = std::min(W - 1, static_cast<int>(std::ceil(std::max({A.x, B.x, C.x}))));
    const int y0 = std::max(0, static_cast<int>(std::floor(std::min({A.y, B.y, C.y}))));
    const int y1 = std::min(H - 1, static_cast<int>(std::ceil(std::max({A.y, B.y, C.y}))));
    const double eps = -1e-9;  // closed triangles: no cracks between neighbours
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const double px = x + 0.5, py = y + 0.5;
        const double wa = ((B.x - px) * (C.y - py) - (B.y - py) * (C.x - px)) / area;
        const double wb = ((C.x - px) * (A.y - py) - (C.y - py) * (A.x - px)) / area;
        const double wc = 1 - wa - wb;
        if (wa < eps || wb < eps || wc < eps) continue;
        const double z = wa * A.depth + wb * B.depth + wc * C.depth;
        const std::size_t q = static_cast<std::size_t>(y) * W + x;
        if (z <= zbuf[q]) continue;
        zbuf[q] = z;
        facing[q] = area > 0 ? 1 : -1;
        res.covered[q] = 1;
        res.parameter[2 * q] = wa * A.s + wb * B.s + wc * C.s;
        res.parameter[2 * q + 1] = wa * A.phi + wb * B.phi + wc * C.phi;
      }
  };
  for (std::size_t a = 0; a + 1 < ns; ++a)
    for (int j = 0; j < na; ++j) {
      const Vertex& v00 = vert[a * (na + 1) + j];
      const Vertex& v01 = vert[a * (na + 1) + j + 1];
      const Vertex& v10 = vert[(a + 1) * (na + 1) + j];
      const Vertex& v11 = vert[(a + 1) * (na + 1) + j + 1];
      raster_triangle(v00, v10, v11);
      raster_triangle(v00, v11, v01);
    }

  // 2.-4. Per pixel: inverse mapping, analytic normal, stripe function.
  const double tau = o.stripe_tilt;
  const V3 e1{{std::cos(tau), -std::sin(tau), 0}}, e2{{0, 0, 1}};
  const double smax = static_cast<double>(n);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const std::size_t q = static_cast<std::size_t>(y) * W + x;
      if (!res.covered[q]) continue;
      const double tx = (x + 0.5 - cam.half_w) / cam.k, ty = (cam.half_h - y - 0.5) / cam.k;
      double s = res.parameter[2 * q], phi = res.parameter[2 * q + 1];
      bool ok = false;
      if (o.inverse_mapping) {
        double s1 = s, p1 = phi;
        for (int it = 0; it < newton_iterations; ++it) {
          const Profile_jet jt = profile.jet_at(s1);
          const double c = std::cos(p1), sn1 = std::sin(p1);
          const V3 P{{jt.r * c, jt.h, jt.r * sn1}};
          const V3 Ps{{jt.dr * c, jt.dh, jt.dr * sn1}};
          const V3 Pp{{-jt.r * sn1, 0, jt.r * c}};
          const double fx = dot(P, cam.ex) - tx, fy = dot(P, cam.ey) - ty;
          const double a11 = dot(Ps, cam.ex), a12 = dot(Pp, cam.ex), a21 = dot(Ps, cam.ey), a22 = dot(Pp, cam.ey);
          const double det = a11 * a22 - a12 * a21;
          if (std::fabs(fx) < newton_tolerance && std::fabs(fy) < newton_tolerance) {
            // The same sheet as the z-buffer's triangle: near in depth, and facing the same way
            // (the triangle's pixel-space area has the opposite sign of det: rows grow downwards).
            ok = std::fabs(dot(P, cam.view) - zbuf[q]) < depth_slack / cam.k && det * facing[q] < 0;
            break;
          }
          if (!(std::fabs(det) > 1e-300)) break;
          const double ds = (a22 * fx - a12 * fy) / det, dp = (a11 * fy - a21 * fx) / det;
          if (!std::isfinite(ds) || !std::isfinite(dp) || std::fabs(dp) > 0.5) break;
          s1 = std::min(std::max(s1 - ds, 0.0), smax);
          p1 -= dp;
        }
        if (ok) {
          s = s1;
          phi = p1;
        }
      }
      res.refined[q] = ok ? 1 : 0;
      res.parameter[2 * q] = s;
      res.parameter[2 * q + 1] = phi;
      const Profile_jet jt = profile.jet_at(s);
      const double c = std::cos(phi), sn1 = std::sin(phi);
      V3 N{{jt.th * c, -jt.tr, jt.th * sn1}};
      if (dot(N, cam.view) < 0) N = V3{{-N[0], -N[1], -N[2]}};
      const V3 P{{jt.r * c, jt.h, jt.r * sn1}};
      for (int a = 0; a < 3; ++a) res.normal[3 * q + a] = N[a];
      res.position[3 * q] = P[0] * fr.scale;
      res.position[3 * q + 1] = P[1] * fr.scale + fr.h_center;
      res.position[3 * q + 2] = P[2] * fr.scale;
      const double nv = dot(N, cam.view);
      const V3 R{{2 * nv * N[0] - cam.view[0], 2 * nv * N[1] - cam.view[1], 2 * nv * N[2] - cam.view[2]}};
      res.stripe_phase[q] = o.stripes * std::atan2(dot(R, e1), dot(R, e2)) / two_pi;
    }
  shade_pixels(o, cam, res, res.stripe_phase);
}

/// The difference a - b of two stripe phases, wrapped to (-stripes/2, stripes/2] (the phase is an
/// angle times stripes / (2 pi)).
inline double phase_difference(double a, double b, double stripes) {
  double d = a - b;
  if (d > 0.5 * stripes) d -= stripes;
  else if (d <= -0.5 * stripes) d += stripes;
  return d;
}

template <class Options, class Result>
void shade_pixels(const Options& o, const Camera&, Result& res, const std::vector<double>& f) {
  const int W = res.width, H = res.height;
  const std::size_t npix = static_cast<std::size_t>(W) * H;
  res.image.width = W;
  res.image.height = H;
  res.image.rgb.assign(3 * npix, 0);
  V3 light{{o.light[0], o.light[1], o.light[2]}};
  const double ln = std::sqrt(dot(light, light));
  for (double& v : light) v /= ln;
  const double dark[3] = {24, 30, 48}, bright[3] = {250, 250, 244}, background[3] = {255, 255, 255};
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const std::size_t q = static_cast<std::size_t>(y) * W + x;
      unsigned char* out = &res.image.rgb[3 * q];
      if (!res.covered[q]) {
        for (int a = 0; a < 3; ++a) out[a] = static_cast<unsigned char>(background[a]);
        continue;
      }
      // Pixel footprint of the stripe function: the largest difference to a covered neighbour.
      double foot = 0;
      const int nb[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
      for (const auto& d : nb) {
        const int xx = x + d[0], yy = y + d[1];
        if (xx < 0 || yy < 0 || xx >= W || yy >= H) continue;
        const std::size_t p = static_cast<std::size_t>(yy) * W + xx;
        if (res.covered[p]) foot = std::max(foot, std::fabs(phase_difference(f[p], f[q], o.stripes)));
      }
      foot = std::min(std::max(foot, 1e-6), 0.5);
      const double dist = 0.5 * o.stripe_width - std::fabs(f[q] - std::round(f[q]));
      const double darkness = std::min(std::max(0.5 + dist / foot, 0.0), 1.0);
      const V3 N{{res.normal[3 * q], res.normal[3 * q + 1], res.normal[3 * q + 2]}};
      const double shade = (1 - o.diffuse) + o.diffuse * std::max(0.0, dot(N, light));
      for (int a = 0; a < 3; ++a) {
        const double v = (darkness * dark[a] + (1 - darkness) * bright[a]) * shade;
        out[a] = static_cast<unsigned char>(std::min(std::max(std::lround(v), 0L), 255L));
      }
    }
}

} // namespace render
} // namespace internal
} // namespace io
} // namespace fair

#endif // FAIR_IO_INTERNAL_RENDER_RASTER_H
