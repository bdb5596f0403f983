// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// What every fuzz target shares (doc/fuzzing.md):
//  - FAIR_FUZZ_ENTRY(target), the name of the entry point: LLVMFuzzerTestOneInput under
//    libFuzzer, fuzz_<target> in the plain replay driver (fuzz/replay_main.cpp, compiled with
//    FAIR_FUZZ_REPLAY by fuzz/CMakeLists.txt), so that one executable links every target;
//  - Fuzz_input, the byte-driven decoder of point sets and options (its grammar is in
//    doc/fuzzing.md): every byte string decodes to some input, and the decoder makes the
//    inputs that break numerical code frequent: duplicates, near-coincident and near-collinear
//    points, huge (1e300) and tiny (1e-300) coordinates, subnormals, NaN and infinities;
//  - the oracle: fuzz_fail() aborts (so libFuzzer records a crash) on NaN/inf in an output, an
//    exception outside the typed errors of include/fair/Errors.h, or fair::Internal_error (a
//    broken invariant is a library bug, not an answer); run_guarded() wraps a target's body.

#ifndef FAIR_FUZZ_COMMON_H
#define FAIR_FUZZ_COMMON_H

#include <fair/Errors.h>

#include <CGAL/number_utils.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <limits>
#include <string>
#include <vector>

#ifdef FAIR_FUZZ_REPLAY
#define FAIR_FUZZ_ENTRY(target) fuzz_##target
#else
#define FAIR_FUZZ_ENTRY(target) LLVMFuzzerTestOneInput
#endif

namespace fair_fuzz {

/// Reports a violated oracle and aborts (libFuzzer turns the abort into a crash artifact; the
/// replay driver dies with the message).
[[noreturn]] inline void fuzz_fail(const std::string& what) {
  std::fprintf(stderr, "FUZZ ORACLE VIOLATED: %s\n", what.c_str());
  std::fflush(stderr);
  std::abort();
}

/// The readers' oracle: runs `parse`; true when it returned, false when it refused the input with
/// a fair::Parse_error that names its file (one without a file name violates the oracle); any
/// other exception propagates (fair::Internal_error included: run_guarded judges it).
template <class Parse>
bool parsed_or_refused(Parse&& parse) {
  try {
    parse();
    return true;
  } catch (const fair::Internal_error&) {
    throw;
  } catch (const fair::Parse_error& e) {
    if (e.file().empty()) fuzz_fail("Parse_error without a file name");
    return false;
  }
}

/// Aborts unless `v` is finite; `what` says which output it is.
inline void require_finite(double v, const char* what) {
  if (!std::isfinite(v)) fuzz_fail(std::string(what) + " is " + std::to_string(v));
}

template <class Point_2>
void require_finite_point(const Point_2& p, const char* what) {
  require_finite(CGAL::to_double(p.x()), what);
  require_finite(CGAL::to_double(p.y()), what);
}

template <class Vector_2>
void require_finite_vector(const Vector_2& v, const char* what) {
  require_finite(CGAL::to_double(v.x()), what);
  require_finite(CGAL::to_double(v.y()), what);
}

/// Evaluates a CurvePiece_2 at a few parameters: every point and derivative must be finite;
/// the curvature too when it is returned (Bezier_2 and the conic pieces throw Precondition_error
/// at a singular point or when |kappa| is not representable in double: a typed answer).
template <class Piece>
void check_piece(const Piece& piece) {
  typedef typename Piece::FT FT;
  for (const auto& c : piece.control_points()) require_finite_point(c, "control point");
  static const double ts[] = {0.0, 0.25, 0.5, 0.75, 1.0};
  for (const double t : ts) {
    require_finite_point(piece.point(FT(t)), "piece point");
    try {
      require_finite_vector(piece.derivative(FT(t)), "piece derivative");
    } catch (const fair::Internal_error&) {
      throw;
    } catch (const fair::Error&) {
      // a typed refusal (a conic piece whose c'(t) is beyond double)
    }
    try {
      require_finite(piece.curvature(t), "piece curvature");
    } catch (const fair::Internal_error&) {
      throw;
    } catch (const fair::Error&) {
      // a typed refusal (singular point, |kappa| beyond double)
    }
  }
}

template <class Pieces>
void check_pieces(const Pieces& pieces) {
  for (const auto& piece : pieces) check_piece(piece);
}

/// Runs a target's body: typed errors other than Internal_error are answers; anything else is a
/// finding.
template <class F>
int run_guarded(F&& body) {
  try {
    body();
  } catch (const fair::Internal_error& e) {
    fuzz_fail(std::string("fair::Internal_error: ") + e.what());
  } catch (const fair::Error&) {
    // Precondition_error, Invalid_input_error, Parse_error, Non_convergence_error: typed answers
  } catch (const std::exception& e) {
    fuzz_fail(std::string("untyped exception: ") + e.what());
  } catch (...) {
    fuzz_fail("exception of unknown type");
  }
  return 0;
}

/// The byte-driven decoder (grammar: doc/fuzzing.md, "The decoder"). Reading past the end
/// yields zeros, so every byte string is a valid input.
class Fuzz_input {
public:
  /// At most this many points are decoded: the hang oracle (-timeout=1) is for <= 100 points.
  static constexpr std::size_t max_points = 100;

  Fuzz_input(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

  bool empty() const { return pos_ >= size_; }
  std::size_t remaining() const { return pos_ < size_ ? size_ - pos_ : 0; }

  std::uint8_t byte() { return pos_ < size_ ? data_[pos_++] : 0; }
  bool flag() { return byte() & 1; }
  /// One of `count` choices.
  std::size_t choice(std::size_t count) { return byte() % count; }
  std::int16_t int16() {
    const std::uint16_t lo = byte(), hi = byte();
    return static_cast<std::int16_t>(static_cast<std::uint16_t>(lo | (hi << 8)));
  }
  /// Eight raw bytes as a double: every bit pattern, NaN, infinities and subnormals included.
  double raw_double() {
    std::uint64_t bits = 0;
    for (int k = 0; k < 8; ++k) bits |= static_cast<std::uint64_t>(byte()) << (8 * k);
    double d;
    std::memcpy(&d, &bits, sizeof d);
    return d;
  }
  /// A value from the table of troublesome numbers.
  double special() {
    static const double table[] = {0.0,
                                   -0.0,
                                   1.0,
                                   -1.0,
                                   0.5,
                                   1e300,
                                   -1e300,
                                   1e-300,
                                   -1e-300,
                                   std::numeric_limits<double>::max(),
                                   -std::numeric_limits<double>::max(),
                                   std::numeric_limits<double>::min(),
                                   std::numeric_limits<double>::denorm_min(),
                                   1e154,
                                   1e-154,
                                   1e16,
                                   1.0 + std::numeric_limits<double>::epsilon(),
                                   std::numeric_limits<double>::quiet_NaN(),
                                   std::numeric_limits<double>::infinity(),
                                   -std::numeric_limits<double>::infinity()};
    return table[choice(sizeof table / sizeof table[0])];
  }
  /// A scale factor 10^e, e in {-300, -150, -20, -8, 0, 8, 20, 150, 300}.
  double scale() {
    static const double table[] = {1e-300, 1e-150, 1e-20, 1e-8, 1.0, 1e8, 1e20, 1e150, 1e300};
    return table[choice(sizeof table / sizeof table[0])];
  }
  /// A general number: a small integer, a scaled integer, a special value or a raw double.
  double number() {
    switch (choice(4)) {
      case 0: return static_cast<double>(static_cast<std::int8_t>(byte()));
      case 1: return static_cast<double>(int16()) * scale();
      case 2: return special();
      default: return raw_double();
    }
  }

  /// A point set of up to max_points points (possibly fewer than any method needs). Each point
  /// starts with an opcode byte (see doc/fuzzing.md):
  ///   0 grid point (small integers: exact duplicates and collinear triples are frequent);
  ///   1 repeat of an earlier point;
  ///   2 an earlier point moved by a tiny offset (relative 2^-52 .. 2^-1074 or absolute 1e-300);
  ///   3 an affine combination of two earlier points (collinear), optionally nudged by 1 ulp;
  ///   4 raw doubles;  5 special values;  6 a grid point times a scale 1e-300 .. 1e300;
  ///   7 a point on a circle of radius r at an angle from one byte (smooth data).
  /// Then the whole set may be translated and scaled (the last two opcodes of the header byte).
  std::vector<std::pair<double, double>> points() {
    std::vector<std::pair<double, double>> p;
    const std::size_t n = choice(max_points + 1);
    const double radius = std::ldexp(1.0, static_cast<int>(choice(64)) - 32);
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint8_t op = byte();
      switch (op % 8) {
        case 0: {
          const double x = static_cast<std::int8_t>(byte()), y = static_cast<std::int8_t>(byte());
          p.emplace_back(x, y);
          break;
        }
        case 1:
          p.push_back(p.empty() ? std::make_pair(0.0, 0.0) : p[choice(p.size())]);
          break;
        case 2: {
          std::pair<double, double> q = p.empty() ? std::make_pair(1.0, 1.0) : p[choice(p.size())];
          const std::uint8_t how = byte();
          const double e = (how & 1) ? std::ldexp(1.0, -52 - static_cast<int>(how >> 1) * 4) * std::fabs(q.first)
                                     : 1e-300 * static_cast<double>(how >> 1);
          if (how & 2) q.first += e; else q.second -= e;
          p.push_back(q);
          break;
        }
        case 3: {
          if (p.size() < 2) { p.emplace_back(static_cast<double>(i), 0.0); break; }
          const std::pair<double, double> a = p[choice(p.size())], b = p[choice(p.size())];
          const double s = static_cast<double>(static_cast<std::int8_t>(byte())) / 16.0;
          std::pair<double, double> q(a.first + s * (b.first - a.first), a.second + s * (b.second - a.second));
          if (op & 8) q.second = std::nextafter(q.second, std::numeric_limits<double>::infinity());
          p.push_back(q);
          break;
        }
        case 4: {
          const double x = raw_double(), y = raw_double();
          p.emplace_back(x, y);
          break;
        }
        case 5: {
          const double x = special(), y = special();
          p.emplace_back(x, y);
          break;
        }
        case 6: {
          const double s = scale();
          p.emplace_back(static_cast<std::int8_t>(byte()) * s, static_cast<std::int8_t>(byte()) * s);
          break;
        }
        default: {
          const double a = 2.0 * M_PI * static_cast<double>(byte()) / 256.0;
          p.emplace_back(radius * std::cos(a), radius * std::sin(a));
          break;
        }
      }
    }
    const std::uint8_t global = byte();
    if (global & 1) {
      const double s = scale();
      for (auto& q : p) { q.first *= s; q.second *= s; }
    }
    if (global & 2) {
      const double dx = number(), dy = number();
      for (auto& q : p) { q.first += dx; q.second += dy; }
    }
    return p;
  }

  template <class Point_2>
  std::vector<Point_2> kernel_points() {
    std::vector<Point_2> out;
    for (const auto& q : points()) out.emplace_back(q.first, q.second);
    return out;
  }

private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

} // namespace fair_fuzz

#endif // FAIR_FUZZ_COMMON_H
