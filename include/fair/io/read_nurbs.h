// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Reading the "bspline" member of a curve JSON (doc/io.md, written by fair::io::nurbs_to_json)
// into the exchange form fair::Nurbs_curve_2<K>:
//
//   "bspline": {"degree": p, "closed": false | true, "knots": [u_0, ..., u_{n+p}],
//               "control_points": [[x, y], ... n ...], "weights": [w_0, ..., w_{n-1}]?}
//
// Numbers are JSON numbers (the nearest double) or exact "p/q" strings (exact in an exact
// kernel), as everywhere in the curve format. "closed" may be absent (false); "weights" may be
// absent (all 1, a polynomial curve). A closed curve is in the periodic form of
// fair/Nurbs_curve_2.h (the last p control points repeat the first p, the knot intervals repeat
// with period n - p).
//
// Every problem is a fair::Parse_error naming the file and the line of the offending value:
// a missing or malformed member, a degree that is not an integer >= 1, a wrong number of knots
// (n + p + 1 for n control points) or of weights, a knot smaller than its predecessor, a
// weight <= 0, a NaN, infinite or unreadable number (fair::io::parse_number), and whatever else
// Nurbs_curve_2 refuses (a knot of too high multiplicity, a closed curve that does not repeat),
// reported at the line of the member with the class's message.

#ifndef FAIR_IO_READ_NURBS_H
#define FAIR_IO_READ_NURBS_H

#include <fair/Errors.h>
#include <fair/Nurbs_curve_2.h>
#include <fair/io/parsing.h>

#include <cstddef>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace fair {
namespace io {

/// The NURBS of a parsed "bspline" member (see the file comment); `file` names the source in
/// messages. \throws Parse_error as the file comment lists.
template <class K>
Nurbs_curve_2<K> read_nurbs(const Json_value& bspline, const std::string& file = "<json>") {
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  const std::string who = "\"bspline\"";
  if (bspline.kind != Json_value::OBJECT)
    throw Parse_error(file, bspline.line, who + " must be an object, got " + Json_value::kind_name(bspline.kind));
  auto member = [&](const char* key) -> const Json_value& {
    const Json_value* v = bspline.find(key);
    if (!v) throw Parse_error(file, bspline.line, who + " has no \"" + key + "\"");
    return *v;
  };
  auto number = [&](const Json_value& v, const std::string& what) {
    if (v.kind != Json_value::NUMBER && v.kind != Json_value::STRING)
      throw Parse_error(file, v.line, who + ": " + what + " must be a number, got " + Json_value::kind_name(v.kind));
    return to_ft<FT>(parse_number(v.text, file, v.line, what.c_str()));
  };
  auto array = [&](const Json_value& v, const std::string& what) {
    if (v.kind != Json_value::ARRAY || v.items.empty())
      throw Parse_error(file, v.line, who + ": \"" + what + "\" must be a nonempty array");
  };

  const Json_value& dv = member("degree");
  std::size_t p = 0;
  bool integer = dv.kind == Json_value::NUMBER && !dv.text.empty() && dv.text.size() <= 9;
  for (char c : dv.text) integer = integer && c >= '0' && c <= '9';
  if (integer) p = static_cast<std::size_t>(std::stoul(dv.text));
  if (!integer || p < 1)
    throw Parse_error(file, dv.line, who + ": \"degree\" must be an integer >= 1, got " +
                                         (dv.kind == Json_value::NUMBER ? dv.text : Json_value::kind_name(dv.kind)));
  bool closed = false;
  if (const Json_value* c = bspline.find("closed")) {
    if (c->kind != Json_value::BOOLEAN) throw Parse_error(file, c->line, who + ": \"closed\" must be true or false");
    closed = c->flag;
  }

  const Json_value& cv = member("control_points");
  array(cv, "control_points");
  std::vector<Point_2> P;
  P.reserve(cv.items.size());
  for (std::size_t k = 0; k < cv.items.size(); ++k) {
    const Json_value& xy = cv.items[k];
    const std::string what = "control point " + std::to_string(k);
    if (xy.kind != Json_value::ARRAY || xy.items.size() != 2)
      throw Parse_error(file, xy.line, who + ": " + what + ": expected an [x, y] pair");
    P.push_back(Point_2(number(xy.items[0], what + " x"), number(xy.items[1], what + " y")));
  }
  const std::size_t n = P.size();

  const Json_value& kv = member("knots");
  array(kv, "knots");
  if (kv.items.size() != n + p + 1)
    throw Parse_error(file, kv.line,
                      fair::internal::message(who, ": ", kv.items.size(), " knots for ", n,
                                              " control points of degree ", p, " (expected n + p + 1 = ", n + p + 1,
                                              ")"));
  std::vector<FT> u;
  u.reserve(kv.items.size());
  for (std::size_t k = 0; k < kv.items.size(); ++k) {
    u.push_back(number(kv.items[k], "knot " + std::to_string(k)));
    if (k > 0 && u[k] < u[k - 1])
      throw Parse_error(file, kv.items[k].line,
                        fair::internal::message(who, ": knot ", k, " = ", kv.items[k].text, " is smaller than knot ",
                                                k - 1, " = ", kv.items[k - 1].text, " (knots must not decrease)"));
  }

  std::vector<FT> w;
  if (const Json_value* wv = bspline.find("weights")) {
    array(*wv, "weights");
    if (wv->items.size() != n)
      throw Parse_error(file, wv->line,
                        fair::internal::message(who, ": ", wv->items.size(), " weights for ", n, " control points"));
    for (std::size_t k = 0; k < n; ++k) {
      w.push_back(number(wv->items[k], "weight " + std::to_string(k)));
      if (!(w.back() > FT(0)))
        throw Parse_error(file, wv->items[k].line,
                          fair::internal::message(who, ": weight ", k, " = ", wv->items[k].text, " must be > 0"));
    }
  }
  try {
    return Nurbs_curve_2<K>(p, std::move(u), std::move(P), std::move(w), closed);
  } catch (const Precondition_error& e) {
    throw Parse_error(file, bspline.line, e.what());
  }
}

/// The "bspline" member of the curve JSON `text` (an object); `file` names it in messages.
/// \throws Parse_error for a JSON syntax error, a document that is not an object, a missing
/// "bspline" member, or a malformed one (read_nurbs).
template <class K>
Nurbs_curve_2<K> parse_nurbs_json(const std::string& text, const std::string& file) {
  const Json_value root = parse_json(text, file);
  if (root.kind != Json_value::OBJECT)
    throw Parse_error(file, root.line, "expected a curve JSON (an object with a \"bspline\" member)");
  const Json_value* b = root.find("bspline");
  if (!b) throw Parse_error(file, root.line, "this curve JSON has no \"bspline\" member");
  return read_nurbs<K>(*b, file);
}

/// Reads the "bspline" member of a curve JSON file (parse_nurbs_json).
template <class K>
Nurbs_curve_2<K> read_nurbs_json(const std::string& file) {
  return parse_nurbs_json<K>(read_text_file(file), file);
}

}  // namespace io
}  // namespace fair

#endif  // FAIR_IO_READ_NURBS_H
