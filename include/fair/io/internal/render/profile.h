// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The profile of a surface of revolution in the frame of its axis (doc/surfaces_of_revolution.md):
// a point p of the profile plane has the axial coordinate h = (p - A).D and the radius
// r = (p - A).D_perp, D the unit axis direction, D_perp = (D.y, -D.x). The surface is
// S(s, phi) = (r cos phi, h, r sin phi); its unit normal is the profile's unit normal
// (h', -r') / |(r', h')| rotated by phi -- computed from the piece's exact derivative, never from
// differences of sampled points.
//
// Everything here is double: the pieces are evaluated in their own FT and converted once per
// evaluation. Coordinates are taken relative to the axis point and divided by the extent of the
// surface (`Profile_frame::scale`), so that huge or tiny profiles (1e300, 1e-300) map to the unit
// ball without overflow or underflow; tangents are normalised component-wise before hypot.

#ifndef FAIR_IO_INTERNAL_RENDER_PROFILE_H
#define FAIR_IO_INTERNAL_RENDER_PROFILE_H

#include <fair/Errors.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <vector>

namespace fair {
namespace io {
namespace internal {
namespace render {

/// A profile point in the axis frame, normalised: radius r >= 0, axial coordinate h, and the
/// unit tangent (tr, th) in the direction of increasing parameter.
struct Profile_jet {
  double r = 0, h = 0;     // normalised position (divided by Profile_frame::scale)
  double dr = 0, dh = 0;   // derivative d(r, h)/du, normalised the same way
  double tr = 0, th = 0;   // unit tangent
};

/// The axis frame and the normalisation of one profile.
struct Profile_frame {
  double ax = 0, ay = 0;       // the axis point A
  double dx = 0, dy = 1;       // the unit axis direction D
  double sign = 1;             // +1 if the profile lies on the side D_perp of the axis, else -1
  double h_center = 0;         // the middle of the axial extent (un-normalised)
  double scale = 1;            // the radius of the bounding sphere about (0, h_center, 0)
};

/// Evaluation of a range of CurvePiece_2 pieces in double in the axis frame.
template <class Piece>
class Profile {
public:
  typedef typename Piece::FT FT;

  Profile(std::vector<Piece> pieces, double ax, double ay, double dx, double dy)
    : pieces_(std::move(pieces)) {
    frame_.ax = ax;
    frame_.ay = ay;
    const double n = std::hypot(dx, dy);
    frame_.dx = dx / n;
    frame_.dy = dy / n;
  }

  std::size_t size() const { return pieces_.size(); }
  const Profile_frame& frame() const { return frame_; }
  void set_frame(const Profile_frame& f) { frame_ = f; }

  /// Un-normalised radius (with sign) and axial coordinate of piece i at u, and their
  /// derivatives; throws Invalid_input_error on a non-finite value.
  void raw(std::size_t i, double u, double& r, double& h, double& dr, double& dh) const {
    const FT t(u);
    const auto p = pieces_[i].point(t);
    const auto d = pieces_[i].derivative(t);
    const double px = CGAL::to_double(p.x()) - frame_.ax, py = CGAL::to_double(p.y()) - frame_.ay;
    const double vx = CGAL::to_double(d.x()), vy = CGAL::to_double(d.y());
    if (!std::isfinite(px) || !std::isfinite(py) || !std::isfinite(vx) || !std::isfinite(vy))
      throw Invalid_input_error(fair::internal::message(
          "surface_of_revolution: piece ", i, " at u = ", u, " has a non-finite point (", px + frame_.ax, ", ",
          py + frame_.ay, ") or derivative (", vx, ", ", vy, ")"));
    h = px * frame_.dx + py * frame_.dy;
    r = px * frame_.dy - py * frame_.dx;
    dh = vx * frame_.dx + vy * frame_.dy;
    dr = vx * frame_.dy - vy * frame_.dx;
  }

  /// The normalised jet of piece i at u (after the frame is set). Throws Invalid_input_error
  /// where the tangent vanishes: the surface normal is undefined there.
  Profile_jet jet(std::size_t i, double u) const {
    double r, h, dr, dh;
    raw(i, u, r, h, dr, dh);
    Profile_jet j;
    j.r = frame_.sign * r / frame_.scale;
    j.h = (h - frame_.h_center) / frame_.scale;
    j.dr = frame_.sign * dr / frame_.scale;
    j.dh = dh / frame_.scale;
    const double m = std::max(std::fabs(dr), std::fabs(dh));
    if (!(m > 0))
      throw Invalid_input_error(fair::internal::message("surface_of_revolution: the tangent of piece ", i,
                                                        " vanishes at u = ", u, " (the surface normal is undefined)"));
    const double a = frame_.sign * dr / m, b = dh / m, n = std::hypot(a, b);
    j.tr = a / n;
    j.th = b / n;
    return j;
  }

  /// Global parameter s in [0, size()]: piece floor(s) at u = s - floor(s) (the last piece at u = 1
  /// for s = size()).
  void locate(double s, std::size_t& i, double& u) const {
    const double n = static_cast<double>(pieces_.size());
    s = std::min(std::max(s, 0.0), n);
    double f = std::floor(s);
    if (f >= n) f = n - 1;
    i = static_cast<std::size_t>(f);
    u = std::min(std::max(s - f, 0.0), 1.0);
  }

  Profile_jet jet_at(double s) const {
    std::size_t i;
    double u;
    locate(s, i, u);
    return jet(i, u);
  }

private:
  std::vector<Piece> pieces_;
  Profile_frame frame_;
};

/// Fixes the frame of `profile` from samples (`per_piece` + 1 per piece): the side of the axis,
/// the axial extent and the scale. Throws Invalid_input_error if the profile crosses the axis
/// (radii of both signs beyond a relative 1e-12 of the extent) or lies on it.
template <class Piece>
void fit_frame(Profile<Piece>& profile, int per_piece) {
  constexpr double axis_tolerance = 1e-12;  // relative: radii this small count as on the axis
  double rmin = HUGE_VAL, rmax = -HUGE_VAL, hmin = HUGE_VAL, hmax = -HUGE_VAL;
  std::size_t imin = 0, imax = 0;
  double umin = 0, umax = 0;
  for (std::size_t i = 0; i < profile.size(); ++i)
    for (int k = 0; k <= per_piece; ++k) {
      const double u = static_cast<double>(k) / per_piece;
      double r, h, dr, dh;
      profile.raw(i, u, r, h, dr, dh);
      if (r < rmin) { rmin = r; imin = i; umin = u; }
      if (r > rmax) { rmax = r; imax = i; umax = u; }
      hmin = std::min(hmin, h);
      hmax = std::max(hmax, h);
    }
  Profile_frame f = profile.frame();
  const double rext = std::max(std::fabs(rmin), std::fabs(rmax));
  const double hhalf = 0.5 * hmax - 0.5 * hmin;
  const double extent = std::max(rext, hhalf);
  if (!(rext > 0) || !(rext > axis_tolerance * extent))
    throw Invalid_input_error(fair::internal::message("surface_of_revolution: the profile lies on the axis (largest "
                                                      "distance from the axis ", rext, ")"));
  const double tol = axis_tolerance * extent;
  if (rmin < -tol && rmax > tol)
    throw Invalid_input_error(fair::internal::message(
        "surface_of_revolution: the profile crosses the axis: signed distance ", rmin, " at piece ", imin, ", u = ",
        umin, " and ", rmax, " at piece ", imax, ", u = ", umax));
  f.sign = rmax > tol ? 1.0 : -1.0;
  f.h_center = 0.5 * hmin + 0.5 * hmax;
  // The bounding sphere about (0, h_center, 0): radius hypot(rext, hhalf), computed scaled.
  f.scale = extent * std::hypot(rext / extent, hhalf / extent);
  profile.set_frame(f);
}

} // namespace render
} // namespace internal
} // namespace io
} // namespace fair

#endif // FAIR_IO_INTERNAL_RENDER_PROFILE_H
