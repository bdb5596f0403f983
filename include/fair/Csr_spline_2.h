// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair::Csr_spline_2<Kernel>: the curvature-sensitive relaxed spline (csr-spline) of
// Karciauskas & Peters, "Curvature-sensitive splines and design with basic curves", Sec. 4,
// eq. 6 with the corrected coefficients a_{-1}, a_1, a_2 of issue 10. From samples q_i of basic
// curves it builds a cubic C2 B-spline (fair::Cubic_spline_2) whose control point c_i of the
// breakpoint t_i is an average of the t_i-coefficients of the three quadratic interpolants
// f_{i-1}, f_i, f_{i+1}, weighed by their curvatures so that the less curved side counts more.
// Local, O(n), no solve. It does not interpolate: distances_to_samples() reports how far it stays.
// User manual and derivations: doc/csr_splines.md.
//
// Properties (tested in test/csr/):
//  - quadratic precision on any (non-uniform) knots: samples q_i = q(t_i) of a quadratic q with
//    the parameters t_i given give the spline q exactly (every piece, in an exact kernel);
//  - hence linear precision: collinear samples q_i = a + b t_i give the straight segment with that
//    parametrisation; collinear samples with chordal knots give the segment parametrised by
//    chord length (the curvature weights do not matter there, every candidate lies on the line);
//  - open curves start at q_0 and end at q_m (clamped end, see the construction notes);
//  - uniform knots: p_i is the (-1, 8, -1)/6 quasi-interpolation rule;
//  - invariant under translations (exactly in an exact kernel) and similarities (up to rounding).
// Exactness: with UNIFORM knots or given rational parameters every control point is an exact
// affine combination of the samples in an exact kernel; only the curvature weights mu, nu are
// computed in double (they need square roots) and converted exactly. Chordal/centripetal knots
// are rounded to double first (see Knot_spacing), then everything is exact for those knots.

#ifndef FAIR_CSR_SPLINE_2_H
#define FAIR_CSR_SPLINE_2_H

#include <fair/Bezier_2.h>
#include <fair/Cubic_spline_2.h>
#include <fair/internal/common/lazy_cache.h>
#include <fair/Errors.h>
#include <fair/Knot_spacing.h>
#include <fair/internal/csr/construction.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace fair {

/// How eq. 6 keeps the curvature ratios mu, nu defined when the curvatures vanish.
enum class Csr_epsilon_rule {
  CASE_SPLIT,        ///< kappa_a / (kappa_a + kappa_b) if the sum exceeds epsilon, else 1/2 (the paper's first form)
  ADD_TO_CURVATURES  ///< (kappa_a + epsilon) / (kappa_a + kappa_b + 2 epsilon) (the paper's alternative, continuous)
};

inline const char* to_string(Csr_epsilon_rule r) {
  return r == Csr_epsilon_rule::CASE_SPLIT ? "case_split" : "add_to_curvatures";
}

/// Options of the csr-spline.
struct Csr_spline_options {
  /// Closed: one piece per sample, the last closing back to the first (>= 4 samples).
  bool closed = false;
  /// Knots when no parameters are given; chordal is the paper's default.
  Knot_spacing knot_spacing = Knot_spacing::CHORDAL;
  Csr_epsilon_rule epsilon_rule = Csr_epsilon_rule::CASE_SPLIT;
  /// epsilon relative to the extent L of the samples (the diagonal of their bounding box): the
  /// curvatures are compared with epsilon = relative_epsilon / L, so the spline does not change
  /// when the data are scaled. The default 1e-9 treats two curvatures as "both zero" when their
  /// radii of curvature exceed 1e9 times the data's size. Must be >= 0 and finite.
  double relative_epsilon = 1e-9;
};

template <class K>
class Csr_spline_2 {
public:
  typedef K Kernel;
  typedef Csr_spline_options Options;
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  typedef typename K::Vector_2 Vector_2;
  typedef Bezier_2<K> Piece;
  typedef Cubic_spline_2<K> Spline;

  /// The csr-spline of the samples `points` with knots by options.knot_spacing. Open: >= 3
  /// samples, the curve runs from points.front() to points.back(). Closed (options.closed): >= 4
  /// samples, one piece per sample, the last piece closing back to the first sample (which must
  /// differ from the last). Throws Invalid_input_error for too few samples, a non-finite
  /// coordinate or two coincident consecutive samples (naming the indices), and
  /// Precondition_error for a negative or non-finite relative_epsilon. O(n).
  explicit Csr_spline_2(std::vector<Point_2> points, const Csr_spline_options& options = {})
    : Csr_spline_2(std::move(points), nullptr, options) {}

  /// Expert: the csr-spline with given parameters t_i of the samples (options.knot_spacing is
  /// ignored): one per sample for an open curve, one more for a closed one (the parameter at
  /// which the curve returns to points[0]). Throws Invalid_input_error also for a wrong count or
  /// parameters that are not finite and strictly increasing.
  Csr_spline_2(std::vector<Point_2> points, std::vector<FT> parameters, const Csr_spline_options& options = {})
    : Csr_spline_2(std::move(points), &parameters, options) {}

  /// The cubic C2 B-spline: breakpoints = parameters(); open: m + 3 control points
  /// q_0, b_1^0, c_1..c_{m-1}, b_2^{m-1}, q_m; closed: c_0..c_{m-1}.
  const Spline& spline() const { return spline_; }
  /// Its cubic Bezier pieces; piece i spans [t_i, t_{i+1}]. Built on the first call and kept
  /// (thread-safe): the spline is the representation, and building 10^6 pieces would cost more
  /// than constructing the spline.
  const std::vector<Piece>& pieces() const {
    return pieces_.get([this] { return spline_.polynomial_pieces(); });
  }
  std::size_t number_of_pieces() const { return spline_.number_of_pieces(); }
  /// spline().nurbs(): the C2 cubic in the exchange form (fair/Nurbs_curve_2.h): knots the
  /// breakpoints parameters(), single inside, clamped when open, periodic when closed.
  Nurbs_curve_2<K> nurbs() const { return spline_.nurbs(); }
  bool is_closed() const { return options_.closed; }
  /// The samples q_i, as given (the spline approximates them: distances_to_samples()).
  const std::vector<Point_2>& points() const { return samples_; }
  /// The breakpoints t_0 < ... < t_m: t_i belongs to sample i; closed curves have one more,
  /// t_m, where the curve is back at sample 0.
  const std::vector<FT>& parameters() const { return spline_.breakpoints(); }
  /// True when the parameters were given, false when they come from options().knot_spacing.
  bool has_given_parameters() const { return given_parameters_; }
  const Csr_spline_options& options() const { return options_; }
  /// kappa_i = |curvature at q_i of the quadratic interpolating q_{i-1}, q_i, q_{i+1}| (at the open
  /// ends: of the quadratic through the first / last three samples), in double, one per sample.
  const std::vector<double>& discrete_curvatures() const { return data_.curvatures; }
  /// The absolute epsilon compared with the curvatures: options().relative_epsilon / extent.
  double epsilon() const { return data_.epsilon; }

  /// s(t_i), the point of the spline at the parameter of sample i (exact: the first Bezier
  /// coefficient of piece i, or the end of the last piece for the last sample of an open curve).
  Point_2 point_at_sample(std::size_t i) const {
    internal::require(i < samples_.size(), "Csr_spline_2::point_at_sample: index ", i, " out of range (",
                      samples_.size(), " samples)");
    if (!options_.closed && i + 1 == samples_.size()) return samples_.back();  // the clamped end
    return spline_.polynomial_piece(i).control_points().front();
  }
  /// |s(t_i) - q_i|^2, exact in an exact kernel.
  FT squared_distance_to_sample(std::size_t i) const {
    const Point_2 s = point_at_sample(i);
    const FT dx = s.x() - samples_[i].x(), dy = s.y() - samples_[i].y();
    return dx * dx + dy * dy;
  }
  /// |s(t_i) - q_i| for every sample, in double: std::hypot of the differences (formed in FT,
  /// exact in an exact kernel), so that it does not overflow where the squared distance would
  /// (coordinates beyond 1e154).
  std::vector<double> distances_to_samples() const {
    std::vector<double> d(samples_.size());
    for (std::size_t i = 0; i < d.size(); ++i) {
      const Point_2 s = point_at_sample(i);
      d[i] = std::hypot(CGAL::to_double(s.x() - samples_[i].x()), CGAL::to_double(s.y() - samples_[i].y()));
    }
    return d;
  }
  /// max_i |s(t_i) - q_i|.
  double max_distance_to_samples() const {
    const std::vector<double> d = distances_to_samples();
    return *std::max_element(d.begin(), d.end());
  }

private:
  Csr_spline_2(std::vector<Point_2> samples, const std::vector<FT>* parameters, const Csr_spline_options& options)
    : samples_(std::move(samples)), given_parameters_(parameters != nullptr), options_(options),
      data_(construct(samples_, parameters, options)),
      spline_(std::move(data_.breakpoints), std::move(data_.control_points), options.closed) {
    // Finite control points can still give Bezier pieces (or their derivatives) that overflow,
    // e.g. coordinates near 1e308 or extreme knot ratios: refuse them rather than hand out NaN.
    spline_.check_finite_pieces("Csr_spline_2");
  }

  static internal::csr::Construction<K> construct(const std::vector<Point_2>& samples, const std::vector<FT>* parameters,
                                                  const Csr_spline_options& options) {
    internal::require(options.relative_epsilon >= 0 && std::isfinite(options.relative_epsilon),
                      "Csr_spline_2: relative_epsilon = ", options.relative_epsilon, " must be finite and >= 0");
    return internal::csr::construct<K>(samples, parameters, options.closed, options.knot_spacing,
                                       options.epsilon_rule == Csr_epsilon_rule::ADD_TO_CURVATURES,
                                       options.relative_epsilon, "Csr_spline_2");
  }

  std::vector<Point_2> samples_;
  bool given_parameters_;
  Csr_spline_options options_;
  internal::csr::Construction<K> data_;  // curvatures and epsilon (its knots and points moved into spline_)
  Spline spline_;
  internal::common::Lazy_cache<std::vector<Piece>> pieces_;
};

} // namespace fair

#endif // FAIR_CSR_SPLINE_2_H
