// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Glyph outlines of installed TrueType fonts, read with FreeType at test time, as closed point
// sets for the real-data tests (test/data/real/SOURCES.md names the fonts and their licence).
// A TrueType contour is a cyclic list of on-curve points and off-curve (quadratic) control
// points; two consecutive off-curve points imply the on-curve point at their midpoint. From
// each contour this makes, in font units:
//  - ON_CURVE: the on-curve points (given and implied), the designer's own points;
//  - MIDPOINTS: the same plus the midpoint c(1/2) of every quadratic piece;
//  - DENSE: the on-curve points plus every quadratic piece at `dense_samples - 1` interior
//    parameters (a large set of points on a designed outline).
// Straight segments get no extra points (three collinear points on a line would ask a
// kappa-curve for a straight piece). Consecutive coincident points are merged; contours with
// fewer than 3 points are skipped.

#ifndef FAIR_TEST_KAPPA_REAL_GLYPH_OUTLINES_H
#define FAIR_TEST_KAPPA_REAL_GLYPH_OUTLINES_H

#include <cstddef>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#ifndef FAIR_NO_FREETYPE
#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H
#endif

namespace kappa_real {

struct Xy { double x = 0, y = 0; };
inline bool operator==(const Xy& a, const Xy& b) { return a.x == b.x && a.y == b.y; }

enum class Glyph_sampling { ON_CURVE, MIDPOINTS, DENSE };
inline const char* to_string(Glyph_sampling s) {
  return s == Glyph_sampling::ON_CURVE ? "on-curve" : s == Glyph_sampling::MIDPOINTS ? "midpoints" : "dense";
}

/// One closed point set from one contour of one glyph.
struct Glyph_contour {
  std::string name;         ///< e.g. "DejaVuSans 'a' contour 0 midpoints"
  std::vector<Xy> points;   ///< closed: the last point is joined back to the first (not repeated)
};

/// The directory of the DejaVu fonts: $FAIR_DEJAVU_DIR or Debian's fonts-dejavu-core location.
inline std::string dejavu_directory() {
  const char* env = std::getenv("FAIR_DEJAVU_DIR");
  return env && *env ? std::string(env) : std::string("/usr/share/fonts/truetype/dejavu");
}

/// Removes consecutive coincident points, cyclically.
inline std::vector<Xy> without_repeats_cyclic(const std::vector<Xy>& p) {
  std::vector<Xy> out;
  for (const Xy& q : p)
    if (out.empty() || !(out.back() == q)) out.push_back(q);
  while (out.size() > 1 && out.back() == out.front()) out.pop_back();
  return out;
}

/// The contour as on-curve points, each followed by the control point of the quadratic piece
/// that starts there (has_control false for a straight segment). `raw` with `on` flags as
/// TrueType stores them; implied on-curve points are inserted.
struct Outline_vertex { Xy p; bool has_control = false; Xy control; };
inline std::vector<Outline_vertex> contour_vertices(const std::vector<Xy>& raw, const std::vector<bool>& on) {
  const std::size_t n = raw.size();
  std::vector<std::pair<Xy, bool>> expanded;  // (point, on-curve) with implied points inserted
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    expanded.push_back({raw[i], on[i]});
    if (!on[i] && !on[j]) expanded.push_back({Xy{(raw[i].x + raw[j].x) / 2, (raw[i].y + raw[j].y) / 2}, true});
  }
  std::size_t start = 0;
  while (start < expanded.size() && !expanded[start].second) ++start;
  std::vector<Outline_vertex> v;
  if (start == expanded.size()) return v;  // no on-curve point at all (cannot happen after insertion)
  const std::size_t m = expanded.size();
  for (std::size_t k = 0; k < m; ++k) {
    const std::pair<Xy, bool>& e = expanded[(start + k) % m];
    if (e.second) {
      Outline_vertex ov;
      ov.p = e.first;
      v.push_back(ov);
    } else if (!v.empty()) {
      v.back().has_control = true;
      v.back().control = e.first;
    }
  }
  return v;
}

/// The point set of `sampling` from the vertices of contour_vertices().
inline std::vector<Xy> sample_contour(const std::vector<Outline_vertex>& v, Glyph_sampling sampling,
                                      std::size_t dense_samples) {
  std::vector<Xy> out;
  const std::size_t k = sampling == Glyph_sampling::ON_CURVE ? 1 : sampling == Glyph_sampling::MIDPOINTS ? 2 : dense_samples;
  for (std::size_t i = 0; i < v.size(); ++i) {
    out.push_back(v[i].p);
    if (!v[i].has_control || k < 2) continue;
    const Xy& a = v[i].p;
    const Xy& c = v[i].control;
    const Xy& b = v[(i + 1) % v.size()].p;
    for (std::size_t s = 1; s < k; ++s) {
      const double t = double(s) / double(k), u = 1 - t;
      out.push_back(Xy{u * u * a.x + 2 * u * t * c.x + t * t * b.x, u * u * a.y + 2 * u * t * c.y + t * t * b.y});
    }
  }
  return without_repeats_cyclic(out);
}

/// The contours of the glyphs of `characters` in the font file `font` (a path), each sampled
/// as `sampling`. \throws std::runtime_error naming the file if it is missing or FreeType fails
/// (the fonts are a declared dependency of the test: a missing font is a failure, not a skip).
inline std::vector<Glyph_contour> glyph_contours(const std::string& font, const std::string& characters,
                                                 Glyph_sampling sampling, std::size_t dense_samples = 8) {
  if (!std::ifstream(font).good())
    throw std::runtime_error("glyph_contours: font file " + font +
                             " not found (install the Debian package fonts-dejavu-core or set FAIR_DEJAVU_DIR)");
#ifdef FAIR_NO_FREETYPE
  (void)characters; (void)sampling; (void)dense_samples;
  throw std::runtime_error("glyph_contours: built without FreeType (install libfreetype-dev and re-run cmake)");
#else
  FT_Library library = nullptr;
  if (FT_Init_FreeType(&library)) throw std::runtime_error("glyph_contours: FT_Init_FreeType failed");
  FT_Face face = nullptr;
  if (FT_New_Face(library, font.c_str(), 0, &face)) {
    FT_Done_FreeType(library);
    throw std::runtime_error("glyph_contours: FreeType cannot open " + font);
  }
  const std::string base = font.substr(font.find_last_of('/') + 1);
  const std::string family = base.substr(0, base.find('.'));
  std::vector<Glyph_contour> out;
  for (const char ch : characters) {
    if (FT_Load_Char(face, static_cast<FT_ULong>(static_cast<unsigned char>(ch)),
                     FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP)) {
      FT_Done_Face(face);
      FT_Done_FreeType(library);
      throw std::runtime_error(std::string("glyph_contours: FreeType cannot load '") + ch + "' of " + font);
    }
    const FT_Outline& o = face->glyph->outline;
    int first = 0;
    for (int c = 0; c < o.n_contours; ++c) {
      const int last = o.contours[c];
      std::vector<Xy> raw;
      std::vector<bool> on;
      for (int i = first; i <= last; ++i) {
        raw.push_back(Xy{double(o.points[i].x), double(o.points[i].y)});
        on.push_back((FT_CURVE_TAG(o.tags[i]) & FT_CURVE_TAG_ON) != 0);
      }
      first = last + 1;
      std::vector<Xy> pts = sample_contour(contour_vertices(raw, on), sampling, dense_samples);
      if (pts.size() < 3) continue;
      out.push_back(Glyph_contour{family + " '" + ch + "' contour " + std::to_string(c) + " " + to_string(sampling),
                                  std::move(pts)});
    }
  }
  FT_Done_Face(face);
  FT_Done_FreeType(library);
  return out;
#endif
}

} // namespace kappa_real

#endif // FAIR_TEST_KAPPA_REAL_GLYPH_OUTLINES_H
