// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Re-anchoring of a level of the optimal-curve solver. The lines of motion are fixed for the level
// (Newton then minimises one fixed function), but where the curve moves towards its centres of
// curvature by more than the local radius of the start polygon, the fixed normals of neighbouring
// vertices converge and the vertices crowd together on them: the restricted minimiser has a
// collapsing edge (the level creeps, step-capped, towards it, and the collapse looked like a
// degenerating curve). Seen on hand-drawn strokes that double back. Then the free vertices are slid
// back along the current polygon to the level's spacing and the normals recomputed: a new fixed
// function, from which Newton continues (capped: max_reanchors).

#ifndef FAIR_INTERNAL_OPTIMAL_REANCHORING_H
#define FAIR_INTERNAL_OPTIMAL_REANCHORING_H

#include <fair/internal/optimal/constraints.h>
#include <fair/internal/optimal/vec2.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace fair {
namespace internal {
namespace optimal {

/// Re-anchoring (see solve_level): an edge shorter than this fraction of its length at the last
/// anchor means the fixed lines of motion have crowded its vertices together.
constexpr double anchor_shrink = 0.5;
/// Most re-anchorings of one level.
constexpr int max_reanchors = 50;

inline std::vector<double> edge_lengths(const std::vector<Vec2>& c, bool closed) {
  const std::size_t n = c.size(), e = closed ? n : n - 1;
  std::vector<double> l(e);
  for (std::size_t j = 0; j < e; ++j) l[j] = vec::norm(vec::sub(c[(j + 1) % n], c[j]));
  return l;
}

/// True if some edge of `c` is shorter than anchor_shrink times its length `anchor[j]` at the last anchor.
inline bool crowded(const std::vector<Vec2>& c, bool closed, const std::vector<double>& anchor) {
  const std::vector<double> l = edge_lengths(c, closed);
  for (std::size_t j = 0; j < l.size(); ++j)
    if (l[j] < anchor_shrink * anchor[j]) return true;
  return false;
}

/// Slides the free vertices of every chain between two consecutive FIXED vertices along the current
/// polygon (linear interpolation in arc length) so that the chain's edges have the length fractions
/// `fractions` had (the level's start: the adaptive spacing the subdivision chose), then restores the
/// ties. A tangential move: the polygon's shape is kept up to O(h^2) chord errors.
inline void redistribute(std::vector<Vec2>& c, bool closed, const std::vector<double>& fractions, const Vertex_roles& roles) {
  const std::size_t n = c.size(), edges = closed ? n : n - 1;
  std::size_t first = n;
  for (std::size_t v = 0; v < n && first == n; ++v)
    if (roles.role[v] == Vertex_role::FIXED) first = v;
  if (first == n) return;
  const std::vector<Vec2> old = c;
  std::size_t a = first;
  for (std::size_t done = 0; done < edges;) {
    std::size_t m = 1;  // edges of the chain a -> a + m
    while (roles.role[(a + m) % n] != Vertex_role::FIXED && done + m < edges) ++m;
    if (m > 1) {
      double total = 0, target = 0;
      for (std::size_t k = 0; k < m; ++k) { total += vec::norm(vec::sub(old[(a + k + 1) % n], old[(a + k) % n])); target += fractions[(a + k) % n]; }
      double along = 0, walked = 0;
      std::size_t e = 0;  // current old edge of the chain
      for (std::size_t k = 1; k < m; ++k) {
        along += fractions[(a + k - 1) % n] / target * total;
        for (;;) {
          const double l = vec::norm(vec::sub(old[(a + e + 1) % n], old[(a + e) % n]));
          if (walked + l >= along || e + 1 == m) {
            const double t = l > 0 ? std::min(1.0, std::max(0.0, (along - walked) / l)) : 0.0;
            const Vec2& p = old[(a + e) % n];
            const Vec2& q = old[(a + e + 1) % n];
            c[(a + k) % n] = {{p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])}};
            break;
          }
          walked += l;
          ++e;
        }
      }
    }
    done += m;
    a = (a + m) % n;
  }
  restore_ties(roles, c);
}

/// The spacing of a level's start polygon and the edge lengths at the last anchor.
class Anchoring {
public:
  Anchoring(const std::vector<Vec2>& start, bool closed) : fractions_(edge_lengths(start, closed)), anchor_(fractions_) {}
  /// Re-anchors c (redistribute) when its vertices have crowded together since the last anchor and
  /// the cap allows; returns whether it did (the normals are then to be recomputed).
  bool reanchor(std::vector<Vec2>& c, bool closed, const Vertex_roles& roles) {
    if (!(reanchors_ < max_reanchors && crowded(c, closed, anchor_))) return false;
    redistribute(c, closed, fractions_, roles);
    anchor_ = edge_lengths(c, closed);
    ++reanchors_;
    return true;
  }

private:
  std::vector<double> fractions_, anchor_;
  int reanchors_ = 0;
};

}  // namespace optimal
}  // namespace internal
}  // namespace fair

#endif  // FAIR_INTERNAL_OPTIMAL_REANCHORING_H
