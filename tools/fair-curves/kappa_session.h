// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The kappa command's options, and the kappa-curve that `fair-curves serve` keeps between the
// requests of a kappa session (serve/kappa_sessions.h), behind an interface that needs none of
// the library's headers: its functions are defined in kappa_command.cpp, the translation unit
// that instantiates the solver (fair::Kappa_curve_2<Kernel>) and the JSON writer for the command
// already, so that the server's translation unit compiles neither (doc/editor_api.md, "kappa
// sessions"; measured: including the solver's headers alone costs 20 s of compile time).

#ifndef FAIR_CURVES_KAPPA_SESSION_H
#define FAIR_CURVES_KAPPA_SESSION_H

#include <cstddef>
#include <memory>
#include <string>

namespace fair_curves {
namespace kappa {

/// The options of `fair-curves kappa` as parsed from its command line.
struct Kappa_command_options {
  std::string input, weights = "1", tension_file, clamp, json_out, svg_out, max_iterations;
  bool closed = false;
  bool allow_unsolved = false;
  bool clamp_given = false; // --clamp appeared (even with an empty value, which is then rejected)
};

/// A kappa-curve solved as `fair-curves kappa` solves it, kept to be re-solved warm.
class Kappa_session_curve {
 public:
  /// Solves the point file text `points` (read as the command reads its JSON point file, named
  /// `o.input` in messages) with the options `o`; `tensions` is the text of the tension file
  /// `o.tension_file` when that is not empty. Throws what the command throws (CLI::ValidationError,
  /// fair::Error) for what the command refuses.
  Kappa_session_curve(const Kappa_command_options& o, const std::string& points, const std::string& tensions);
  ~Kappa_session_curve();
  Kappa_session_curve(const Kappa_session_curve&) = delete;
  Kappa_session_curve& operator=(const Kappa_session_curve&) = delete;

  /// The point file text `points` differs from the curve's in point `i` only: the command's
  /// checks of the new points, then Kappa_curve_2::move_point (warm; strong guarantee: the curve
  /// is unchanged if it throws).
  void move_point(const std::string& points, std::size_t i);

  /// The JSON that `fair-curves kappa ... -o -` writes for the curve.
  std::string json() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace kappa
} // namespace fair_curves

#endif // FAIR_CURVES_KAPPA_SESSION_H
