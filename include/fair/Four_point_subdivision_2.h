// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair::Four_point_subdivision_2<Kernel>: the interpolatory 4-point subdivision scheme of
// N. Dyn, D. Levin, J. A. Gregory ("A 4-point interpolatory subdivision scheme for curve design",
// CAGD 4(4), 1987; reference [7] of Yan, Schiller & Schaefer), and a relaxed (approximating)
// variant, as refined polylines after k rounds. As a curve of the family contract
// (doc/concepts.md) its pieces() are the segments (degree-1 Bezier_2 pieces) of the polyline
// after options.rounds rounds; refine(k) gives the polyline after any other number of rounds.
//
// Interpolatory scheme (DLG 1987). Each round keeps the old points and inserts on every edge
//   p'_{2i}   = p_i,
//   p'_{2i+1} = (1/2 + w)(p_i + p_{i+1}) - w (p_{i-1} + p_{i+2}),
// tension w, default 1/16. The limit is C1 for 0 < w < (sqrt(5) - 1)/8 (DLG 1987); for w = 1/16
// the new point is the cubic through p_{i-1}..p_{i+2} evaluated halfway, so cubic data are
// reproduced: p_i = q(i) for a cubic q gives refined points q(j / 2^k) exactly.
//
// Relaxed variant. The same edge rule with w = 1/16, and the old points are moved by a
// multiple of their centred fourth difference:
//   p'_{2i}   = p_i + gamma Delta^4 p_{i-2}
//             = gamma p_{i-2} - 4 gamma p_{i-1} + (1 + 6 gamma) p_i - 4 gamma p_{i+1} + gamma p_{i+2}.
// Relaxing the old vertices to gain smoothness is the idea of the relaxed 4-point variants of
// U. H. Augsdorfer, N. A. Dodgson, M. A. Sabin, "Variations on the four-point subdivision scheme",
// CAGD 27(1), 2010 ([ADS10], used with alpha = 0.634 in Fig. 2d of Karciauskas & Peters). We do
// NOT claim that our gamma is their alpha: the family, its default and its smoothness below are
// derived here. Since Delta^4 annihilates cubics, the variant still reproduces cubics (with the
// primal parametrisation: q(i) -> q(j / 2^k)). Its symbol is
//   a(z) = a_DLG(z) + gamma z^-4 (1 - z)^4 (1 + z)^4,
// always divisible by (1 + z)^4; it is divisible by (1 + z)^5 exactly when gamma = -3/128, our
// default. The difference-scheme test (N. Dyn, "Subdivision schemes in CAGD", 1992: S_a is C^m if
// the scheme of 2^m a(z) / (1 + z)^(m+1) is contractive) gives, with at most 8 iterated steps,
// C2 at every gamma of the grid k/256 in [-1/16, -1/256] and C3 on the grid points of
// [-3/128, -9/256] (test_classic_approximants re-checks C2 at -1/16, -1/32, -3/128, -1/256 and
// C3 at -3/128, -1/32, -9/256 in exact arithmetic); gamma = 0 is the C1 DLG scheme. The relaxed scheme does not interpolate (old points move by gamma Delta^4).
//
// Open polylines, end handling (documented choice): each round extends the current polygon by
// phantom points on the cubic through its four end points (p_{-1} = 4 p_0 - 6 p_1 + 4 p_2 - p_3,
// and p_{-2} likewise for the relaxed rule). With w = 1/16 the end edges therefore use the end
// cubic, the end points stay fixed, and cubic reproduction holds up to the ends. Needs >= 4
// points (>= 3 when closed; closed polygons use indices mod n).
//
// Cost: round r produces about n 2^r points with O(1) work each. Exactness: only +, -, * by FT
// constants, so exact in EPECK and Simple_cartesian<Gmpq> (where the bit length of coordinates
// grows by about 4 bits per round: keep k small there).

#ifndef FAIR_FOUR_POINT_SUBDIVISION_2_H
#define FAIR_FOUR_POINT_SUBDIVISION_2_H

#include <fair/Bezier_2.h>
#include <fair/Errors.h>
#include <fair/internal/classic/common.h>
#include <fair/internal/common/input_checks.h>
#include <fair/internal/nurbs/assembly.h>

#include <CGAL/number_utils.h>

#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace fair {

/// Which rule Four_point_subdivision_2 applies.
enum class Four_point_variant { INTERPOLATORY, RELAXED };

/// The options of a Four_point_subdivision_2 (doc/concepts.md). The numbers are doubles,
/// converted exactly to the kernel's FT (1/16 and -3/128 are exact).
struct Four_point_subdivision_options {
  /// Closed: the polygon p_0..p_{n-1} closes back to p_0 (>= 3 points; open: >= 4).
  bool closed = false;
  Four_point_variant variant = Four_point_variant::INTERPOLATORY;
  /// The tension w of the edge rule, 0 < w < (sqrt(5) - 1)/8 (the C1 range of DLG 1987). The
  /// relaxed variant is derived for w = 1/16 only (its smoothness below): it requires the default.
  double tension = 1.0 / 16;
  /// RELAXED: the vertex relaxation gamma in [-1/16, 0]; ignored by INTERPOLATORY.
  double relaxation = -3.0 / 128;
  /// The rounds behind pieces() (at most max_rounds, and the polyline at most max_points).
  std::size_t rounds = 5;
};

template <class K>
class Four_point_subdivision_2 {
public:
  typedef K Kernel;
  typedef Four_point_subdivision_options Options;
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  typedef typename K::Vector_2 Vector_2;
  typedef Bezier_2<K> Piece;

  /// The largest number of rounds refine() accepts.
  static constexpr std::size_t max_rounds = 20;
  /// The largest polyline refine() produces.
  static constexpr std::size_t max_points = std::size_t(1) << 24;
  /// (sqrt(5) - 1) / 8, the upper end of the tension range in which the DLG scheme is C1 (DLG 1987).
  static constexpr double max_c1_tension = 0.15450849718747373;

  /// The scheme of options.variant on `points`, refined options.rounds times for pieces().
  /// Throws Invalid_input_error for too few points (4 open, 3 closed), non-finite coordinates or
  /// coincident consecutive points; Precondition_error unless 0 < tension < (sqrt(5) - 1)/8, for a
  /// RELAXED scheme with a tension other than 1/16 or a relaxation outside [-1/16, 0], and for
  /// rounds above max_rounds or a polyline above max_points.
  explicit Four_point_subdivision_2(std::vector<Point_2> points, const Four_point_subdivision_options& options = {})
    : points_(std::move(points)), options_(checked(options)), w_(options.tension),
      gamma_(options.variant == Four_point_variant::RELAXED ? FT(options.relaxation) : FT(0)) {
    internal::common::check_interpolation_input(points_, options_.closed ? 3 : 4, options_.closed,
                                                "Four_point_subdivision_2");
    const double wd = options_.tension;
    internal::require(wd > 0 && wd < max_c1_tension, "Four_point_subdivision_2: tension w = ", wd,
                      " is outside the C1 range (0, (sqrt(5)-1)/8 = 0.1545...)");
    if (options_.variant == Four_point_variant::RELAXED) {
      internal::require(wd == 1.0 / 16, "Four_point_subdivision_2: the relaxed scheme uses tension 1/16, got ", wd);
      internal::require(options_.relaxation >= -1.0 / 16 && options_.relaxation <= 0,
                        "Four_point_subdivision_2: relaxation gamma = ", options_.relaxation, " is outside [-1/16, 0]");
    }
    polyline_ = refine(options_.rounds);
    const std::size_t m = polyline_.size(), segments = options_.closed ? m : m - 1;
    pieces_.reserve(segments);
    for (std::size_t i = 0; i < segments; ++i)
      pieces_.push_back(Piece(std::vector<Point_2>{polyline_[i], polyline_[(i + 1) % m]}));
  }

  /// The number of points after `rounds` rounds: n 2^k closed, (n - 1) 2^k + 1 open.
  std::size_t size_after(std::size_t rounds) const {
    const std::size_t n = points_.size();
    if (rounds > max_rounds) return max_points + 1;
    const std::size_t f = std::size_t(1) << rounds;
    return options_.closed ? n * f : (n - 1) * f + 1;
  }

  /// The polyline after `rounds` rounds (rounds = 0 returns the input). For a closed polygon the
  /// first point is not repeated at the end. Throws Precondition_error when rounds > max_rounds
  /// or the result would exceed max_points.
  std::vector<Point_2> refine(std::size_t rounds) const {
    internal::require(rounds <= max_rounds, "Four_point_subdivision_2::refine: ", rounds,
                      " rounds requested, at most ", max_rounds, " allowed");
    internal::require(size_after(rounds) <= max_points, "Four_point_subdivision_2::refine: ", rounds,
                      " rounds of ", points_.size(), " points would give ", size_after(rounds),
                      " points, more than ", max_points);
    std::vector<Point_2> p = points_;
    for (std::size_t r = 0; r < rounds; ++r) p = round(p);
    internal::classic::classic_check_finite_output(p, "Four_point_subdivision_2::refine");
    return p;
  }

  /// One round applied to an arbitrary polyline q of at least 4 (open) / 3 (closed) points,
  /// with this scheme's rule and end handling.
  std::vector<Point_2> round(const std::vector<Point_2>& q) const {
    const std::size_t n = q.size();
    internal::require(n >= (options_.closed ? 3u : 4u), "Four_point_subdivision_2::round: ", n, " points are too few");
    // Extended polygon e with two leading and two trailing neighbours: e[i + 2] = q[i].
    std::vector<Point_2> e;
    e.reserve(n + 4);
    if (options_.closed) {
      e.push_back(q[(n - 2 + n) % n]);
      e.push_back(q[n - 1]);
      e.insert(e.end(), q.begin(), q.end());
      e.push_back(q[0]);
      e.push_back(q[1 % n]);
    } else {
      const Point_2 a1 = internal::classic::classic_cubic_extrapolation<K>(q[0], q[1], q[2], q[3]);
      const Point_2 a2 = internal::classic::classic_cubic_extrapolation<K>(a1, q[0], q[1], q[2]);
      const Point_2 b1 = internal::classic::classic_cubic_extrapolation<K>(q[n - 1], q[n - 2], q[n - 3], q[n - 4]);
      const Point_2 b2 = internal::classic::classic_cubic_extrapolation<K>(b1, q[n - 1], q[n - 2], q[n - 3]);
      e.push_back(a2);
      e.push_back(a1);
      e.insert(e.end(), q.begin(), q.end());
      e.push_back(b1);
      e.push_back(b2);
    }
    const FT half_w = FT(1) / FT(2) + w_, minus_w = -w_;
    const bool relaxed = options_.variant == Four_point_variant::RELAXED;
    const FT g = gamma_, g4 = FT(-4) * gamma_, g6 = FT(1) + FT(6) * gamma_;
    const std::size_t edges = options_.closed ? n : n - 1;
    std::vector<Point_2> out;
    out.reserve(n + edges);
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t k = i + 2;  // index of q[i] in e
      if (relaxed) {
        // p_i + gamma Delta^4 p_{i-2}
        const FT x = g * e[k - 2].x() + g4 * e[k - 1].x() + g6 * e[k].x() + g4 * e[k + 1].x() + g * e[k + 2].x();
        const FT y = g * e[k - 2].y() + g4 * e[k - 1].y() + g6 * e[k].y() + g4 * e[k + 1].y() + g * e[k + 2].y();
        out.push_back(Point_2(x, y));
      } else {
        out.push_back(q[i]);
      }
      if (i < edges)
        out.push_back(internal::common::combine<K>(minus_w, e[k - 1], half_w, e[k], half_w, e[k + 1], minus_w, e[k + 2]));
    }
    return out;
  }

  /// The input points, as given.
  const std::vector<Point_2>& points() const { return points_; }
  /// The segments of polyline() as degree-1 Bezier pieces (closed: the last one closes it).
  const std::vector<Piece>& pieces() const { return pieces_; }
  std::size_t number_of_pieces() const { return pieces_.size(); }
  /// The polyline of pieces() in the exchange form (fair/Nurbs_curve_2.h; doc/nurbs.md): degree 1,
  /// segment j on [j, j + 1] (knots at the segment indices, single inside: C0), control points the
  /// polyline's vertices; closed: the periodic form. Exact in every kernel. O(n).
  Nurbs_curve_2<K> nurbs() const {
    return internal::nurbs::bezier_pieces_nurbs<K>(pieces_, options_.closed, "Four_point_subdivision_2::nurbs");
  }
  /// refine(options().rounds), computed once.
  const std::vector<Point_2>& polyline() const { return polyline_; }
  bool is_closed() const { return options_.closed; }
  const Four_point_subdivision_options& options() const { return options_; }
  /// The tension w in FT.
  const FT& tension() const { return w_; }
  /// The relaxation gamma in FT (0 for the interpolatory scheme).
  const FT& relaxation() const { return gamma_; }

private:
  /// The doubles are checked before FT(double) sees them: FT(NaN) is undefined in an exact FT.
  static const Four_point_subdivision_options& checked(const Four_point_subdivision_options& o) {
    internal::require(std::isfinite(o.tension) && std::isfinite(o.relaxation),
                      "Four_point_subdivision_2: tension ", o.tension, " and relaxation ", o.relaxation,
                      " must be finite");
    return o;
  }

  std::vector<Point_2> points_;
  Four_point_subdivision_options options_;
  FT w_, gamma_;
  std::vector<Point_2> polyline_;
  std::vector<Piece> pieces_;
};

} // namespace fair

#endif // FAIR_FOUR_POINT_SUBDIVISION_2_H
