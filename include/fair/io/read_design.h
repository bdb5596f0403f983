// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Reading a design file: a JSON list of basic shapes with their marked points (format in
// doc/basic_shapes.md), for fair::basic_shape_design. Every number is a JSON number or an exact
// "p/q" string (exact in an exact kernel). Every problem throws fair::Parse_error naming the file,
// the line and the JSON path of the offending value (e.g. "shapes[2].radius").

#ifndef FAIR_IO_READ_DESIGN_H
#define FAIR_IO_READ_DESIGN_H

#include <fair/Basic_shape_design.h>
#include <fair/Design_marks.h>
#include <fair/Errors.h>
#include <fair/Parametric_curve_2.h>
#include <fair/io/parsing.h>

#include <CGAL/number_utils.h>

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace fair {
namespace io {

/// The contents of a design file.
template <class K>
struct Design_file {
  typedef typename K::Point_2 Point_2;
  std::string file;
  bool closed = false;                 ///< "closed", default false
  double merge_tolerance = 1e-9;       ///< "merge_tolerance", default 1e-9 (relative, see Basic_shape_design_options)
  double mark_tolerance = 1e-6;        ///< "mark_tolerance": how far a marked point may be off its curve (relative)
  std::vector<Basic_shape_2<K>> shapes;
  std::vector<std::string> types;      ///< the "type" of each shape
  std::vector<std::vector<Point_2>> marked_points;  ///< the marked points of each shape, on the curve

  Basic_shape_design_options options() const {
    Basic_shape_design_options o;
    o.closed = closed;
    o.merge_tolerance = merge_tolerance;
    return o;
  }
};

namespace internal {

template <class K>
class Design_reader {
public:
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;

  explicit Design_reader(const std::string& file) : file_(file) {}

  [[noreturn]] void fail(const Json_value& at, const std::string& path, const std::string& why) const {
    throw Parse_error(file_, at.line, path + ": " + why);
  }

  const Json_value& member(const Json_value& object, const std::string& path, const char* key) const {
    const Json_value* v = object.find(key);
    if (!v) fail(object, path, fair::internal::message("missing member \"", key, "\""));
    return *v;
  }

  Parsed_number number(const Json_value& v, const std::string& path) const {
    if (v.kind != Json_value::NUMBER && v.kind != Json_value::STRING)
      fail(v, path, fair::internal::message("expected a number or a \"p/q\" string, got ", Json_value::kind_name(v.kind)));
    try {
      return parse_number(v.text, file_, v.line, "the number");
    } catch (const Parse_error& e) {
      // Re-issued with the JSON path in front.
      const std::string prefix = file_ + ":" + std::to_string(v.line) + ": ";
      fail(v, path, std::string(e.what()).substr(prefix.size()));
    }
  }

  FT ft(const Json_value& v, const std::string& path) const { return to_ft<FT>(number(v, path)); }
  double real(const Json_value& v, const std::string& path) const { return number(v, path).value; }

  const Json_value& array(const Json_value& v, const std::string& path, std::size_t size = 0) const {
    if (v.kind != Json_value::ARRAY)
      fail(v, path, fair::internal::message("expected an array, got ", Json_value::kind_name(v.kind)));
    if (size && v.items.size() != size)
      fail(v, path, fair::internal::message("expected ", size, " entries, got ", v.items.size()));
    return v;
  }

  Point_2 point(const Json_value& v, const std::string& path) const {
    array(v, path, 2);
    return Point_2(ft(v.items[0], path + "[0]"), ft(v.items[1], path + "[1]"));
  }

  std::vector<Point_2> points(const Json_value& v, const std::string& path, std::size_t size) const {
    array(v, path, size);
    std::vector<Point_2> out;
    for (std::size_t i = 0; i < v.items.size(); ++i) out.push_back(point(v.items[i], item(path, i)));
    return out;
  }

  FT positive(const Json_value& v, const std::string& path, const char* what) const {
    const FT x = ft(v, path);
    if (!(x > FT(0))) fail(v, path, fair::internal::message("the ", what, " ", CGAL::to_double(x), " must be > 0"));
    return x;
  }

  static std::string item(const std::string& path, std::size_t i) { return path + "[" + std::to_string(i) + "]"; }

  /// The marks of a shape on [0,1]: numbers (parameters) or, when `locate` is given, points.
  template <class Locate>
  std::vector<FT> parameter_marks(const Json_value& shape, const std::string& path, Locate locate) const {
    std::vector<FT> marks;
    const Json_value* m = shape.find("marks");
    if (!m) return marks;
    array(*m, path + ".marks");
    for (std::size_t i = 0; i < m->items.size(); ++i) {
      const Json_value& v = m->items[i];
      const std::string p = item(path + ".marks", i);
      FT u;
      if (v.kind == Json_value::ARRAY) {
        const Point_2 q = point(v, p);
        try {
          u = locate(q);
        } catch (const Internal_error&) {
          throw;  // a bug of the library, not a problem of this mark
        } catch (const Error& e) {
          // Off the curve, or no point of the arc at all (the conic's P1): at this mark.
          fail(v, p, e.what());
        }
      } else {
        u = ft(v, p);
      }
      if (!(u > FT(0) && u < FT(1)))
        fail(v, p, fair::internal::message("the mark's parameter ", CGAL::to_double(u), " is not inside (0, 1)"));
      if (!marks.empty() && !(marks.back() < u))
        fail(v, p, fair::internal::message("marks must be strictly increasing: ", CGAL::to_double(u),
                                           " follows ", CGAL::to_double(marks.back())));
      marks.push_back(u);
    }
    return marks;
  }

  Design_file<K> read(const std::string& text) {
    Design_file<K> out;
    out.file = file_;
    const Json_value root = parse_json(text, file_);
    if (root.kind != Json_value::OBJECT)
      fail(root, "$", fair::internal::message("a design file is a JSON object, got ", Json_value::kind_name(root.kind)));
    if (const Json_value* c = root.find("closed")) {
      if (c->kind != Json_value::BOOLEAN) fail(*c, "closed", "expected true or false");
      out.closed = c->flag;
    }
    if (const Json_value* t = root.find("merge_tolerance")) {
      out.merge_tolerance = real(*t, "merge_tolerance");
      if (!(out.merge_tolerance >= 0)) fail(*t, "merge_tolerance", fair::internal::message("must be >= 0, got ", out.merge_tolerance));
    }
    if (const Json_value* t = root.find("mark_tolerance")) {
      out.mark_tolerance = real(*t, "mark_tolerance");
      if (!(out.mark_tolerance >= 0)) fail(*t, "mark_tolerance", fair::internal::message("must be >= 0, got ", out.mark_tolerance));
    }
    const Json_value& shapes = array(member(root, "$", "shapes"), "shapes");
    if (shapes.items.empty()) fail(shapes, "shapes", "the design has no shape");
    for (std::size_t i = 0; i < shapes.items.size(); ++i) {
      const Json_value& s = shapes.items[i];
      const std::string path = item("shapes", i);
      if (s.kind != Json_value::OBJECT) fail(s, path, fair::internal::message("expected an object, got ", Json_value::kind_name(s.kind)));
      const Json_value& type = member(s, path, "type");
      if (type.kind != Json_value::STRING) fail(type, path + ".type", "expected a string");
      try {
        read_shape(s, type.text, path, out);
      } catch (const Parse_error&) {
        throw;
      } catch (const Internal_error&) {
        throw;  // a bug of the library, not a problem of this shape
      } catch (const Error& e) {
        // The library's checks (zero-length segment, degenerate arc, weights...), at this shape.
        fail(s, path, e.what());
      }
      out.types.push_back(type.text);
    }
    if (out.closed && out.shapes.size() == 1 && out.types[0] == "segment")
      fail(shapes, "shapes", "a closed design of one segment has no interior");
    return out;
  }

  void read_shape(const Json_value& s, const std::string& t, const std::string& path, Design_file<K>& out) {
    const double tol = out.mark_tolerance;
    std::vector<Point_2> marked;
    if (t == "segment") {
      const Point_2 a = point(member(s, path, "from"), path + ".from"), b = point(member(s, path, "to"), path + ".to");
      if (a == b) out.shapes.push_back(Basic_shape_2<K>::segment(a, b));  // throws: zero-length, before any mark
      const std::vector<FT> marks = parameter_marks(s, path, [&](const Point_2& q) { return segment_mark_parameter<K>(a, b, q, tol); });
      for (const FT& u : marks) marked.push_back(a + (b - a) * u);
      out.shapes.push_back(Basic_shape_2<K>::segment(a, b, marks));
    } else if (t == "arc") {
      // The geometry (radius > 0, opening in (0, 2 pi], marks inside the arc and increasing) is
      // checked by Basic_shape_2::circle_arc, whose error is reported at this shape.
      const Point_2 c = point(member(s, path, "center"), path + ".center");
      const FT r = ft(member(s, path, "radius"), path + ".radius");
      const double a0 = real(member(s, path, "start_angle"), path + ".start_angle");
      const double a1 = real(member(s, path, "end_angle"), path + ".end_angle");
      std::vector<double> marks;
      if (const Json_value* m = s.find("marks")) {
        array(*m, path + ".marks");
        for (std::size_t k = 0; k < m->items.size(); ++k) marks.push_back(real(m->items[k], item(path + ".marks", k)));
      }
      out.shapes.push_back(Basic_shape_2<K>::circle_arc(c, r, a0, a1, marks));
      for (double a : marks) marked.push_back(Point_2(c.x() + r * FT(std::cos(a)), c.y() + r * FT(std::sin(a))));
    } else if (t == "conic") {
      const std::vector<Point_2> p = points(member(s, path, "control_points"), path + ".control_points", 3);
      const FT w = positive(member(s, path, "weight"), path + ".weight", "weight");
      const Rational_quadratic_bezier_2<K> conic(p[0], p[1], p[2], w);
      const std::vector<FT> marks = parameter_marks(s, path, [&](const Point_2& q) { return conic_mark_parameter<K>(conic, q, tol); });
      for (const FT& u : marks) marked.push_back(conic.point(u));
      out.shapes.push_back(Basic_shape_2<K>::conic(conic, marks));
    } else if (t == "cubic") {
      const std::vector<Point_2> p = points(member(s, path, "control_points"), path + ".control_points", 4);
      std::vector<FT> w(4, FT(1));
      if (const Json_value* wv = s.find("weights")) {
        array(*wv, path + ".weights", 4);
        for (std::size_t k = 0; k < 4; ++k) w[k] = positive(wv->items[k], item(path + ".weights", k), "weight");
      }
      const Rational_bezier_2<K> cubic(p, w);
      const std::vector<FT> marks = parameter_marks(s, path, [&](const Point_2& q) { return cubic_mark_parameter<K>(cubic, q, tol); });
      for (const FT& u : marks) marked.push_back(cubic.point(u));
      out.shapes.push_back(Basic_shape_2<K>::cubic(cubic, marks));
    } else if (t == "spiral") {
      const double a = real(member(s, path, "a"), path + ".a"), b = real(member(s, path, "b"), path + ".b");
      const double t0 = real(member(s, path, "theta0"), path + ".theta0"), t1 = real(member(s, path, "theta1"), path + ".theta1");
      const Xy c = optional_xy(s, path, "center", Xy{0, 0});
      parametric(s, path, Archimedean_spiral_2(a, b, t0, t1, c.x, c.y), t0, t1, "spiral", out, marked);
    } else if (t == "involute") {
      const double r = real(member(s, path, "radius"), path + ".radius");
      const double t0 = real(member(s, path, "t0"), path + ".t0"), t1 = real(member(s, path, "t1"), path + ".t1");
      const Xy c = optional_xy(s, path, "center", Xy{0, 0});
      parametric(s, path, Circle_involute_2(r, t0, t1, c.x, c.y), t0, t1, "involute", out, marked);
    } else if (t == "clothoid") {
      const double k0 = real(member(s, path, "kappa0"), path + ".kappa0"), c = real(member(s, path, "c"), path + ".c");
      const double s0 = real(member(s, path, "s0"), path + ".s0"), s1 = real(member(s, path, "s1"), path + ".s1");
      const double scale = s.find("scale") ? real(*s.find("scale"), path + ".scale") : 1.0;
      const double th0 = s.find("theta0") ? real(*s.find("theta0"), path + ".theta0") : 0.0;
      const Xy o = optional_xy(s, path, "origin", Xy{0, 0});
      parametric(s, path, Clothoid_2(k0, c, s0, s1, scale, o.x, o.y, th0), s0, s1, "clothoid", out, marked);
    } else {
      fail(s, path + ".type", "unknown shape type \"" + t +
                                  "\" (known: segment, arc, conic, cubic, spiral, involute, clothoid)");
    }
    out.marked_points.push_back(std::move(marked));
  }

private:
  struct Xy {
    double x, y;
  };

  Xy optional_xy(const Json_value& s, const std::string& path, const char* key, Xy fallback) const {
    const Json_value* v = s.find(key);
    if (!v) return fallback;
    const std::string p = path + "." + key;
    array(*v, p, 2);
    return Xy{real(v->items[0], p + "[0]"), real(v->items[1], p + "[1]")};
  }

  /// A parametric built-in on [u0, u1] with its interior marks (numbers in (u0, u1), increasing).
  template <class Curve>
  void parametric(const Json_value& s, const std::string& path, const Curve& f, double u0, double u1, const char* kind,
                  Design_file<K>& out, std::vector<Point_2>& marked) const {
    std::vector<double> marks = {u0};
    if (const Json_value* m = s.find("marks")) {
      array(*m, path + ".marks");
      for (std::size_t k = 0; k < m->items.size(); ++k) {
        const std::string p = item(path + ".marks", k);
        const double u = real(m->items[k], p);
        if (!(u > u0 && u < u1))
          fail(m->items[k], p, fair::internal::message("the mark ", u, " is not inside the curve's domain (", u0, ", ", u1, ")"));
        if (!(marks.back() < u))
          fail(m->items[k], p, fair::internal::message("marks must be strictly increasing: ", u, " follows ", marks.back()));
        marks.push_back(u);
        const Curve_jet_2 j = f.jet(u);
        marked.push_back(Point_2(FT(j.x), FT(j.y)));
      }
    }
    marks.push_back(u1);
    out.shapes.push_back(Basic_shape_2<K>::parametric(f, marks, kind));
  }

  std::string file_;
};

} // namespace internal

/// Parses the text of a design file; `file` names it in error messages.
template <class K>
Design_file<K> parse_design(const std::string& text, const std::string& file) {
  return internal::Design_reader<K>(file).read(text);
}

/// Reads a design file. \throws Parse_error (file, line, JSON path) for every problem.
template <class K>
Design_file<K> read_design(const std::string& file) {
  return parse_design<K>(read_text_file(file), file);
}

} // namespace io
} // namespace fair

#endif // FAIR_IO_READ_DESIGN_H
