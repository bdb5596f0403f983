// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The typed errors of the library. Every failure the library detects is reported by
// throwing one of these; none of its functions returns NaN or loops without a cap.

#ifndef FAIR_ERRORS_H
#define FAIR_ERRORS_H

#include <any>
#include <cstddef>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace fair {

/// Base of every error the library throws.
class Error : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// A function was called with arguments outside its documented domain
/// (a degenerate piece, a weight <= 0, a parameter outside [0,1], ...).
class Precondition_error : public Error {
public:
  using Error::Error;
};

/// User data that no method can work with: NaN or infinite coordinates, too few points,
/// duplicate consecutive points, collinear data where a method needs a turn, ...
class Invalid_input_error : public Error {
public:
  using Error::Error;
};

/// A file could not be read: it is missing, or a line of it is malformed.
class Parse_error : public Invalid_input_error {
public:
  Parse_error(std::string file, std::size_t line, const std::string& what)
    : Invalid_input_error(file + (line ? ":" + std::to_string(line) : std::string()) + ": " + what),
      file_(std::move(file)), line_(line) {}
  const std::string& file() const noexcept { return file_; }
  /// 1-based line number; 0 when the error concerns the whole file.
  std::size_t line() const noexcept { return line_; }

private:
  std::string file_;
  std::size_t line_;
};

/// A curve family's solve ended in a failure status (Kappa_curve_status::UNSOLVED,
/// Optimal_curve_status::DIVERGING or CAPPED, Cardinal_spline_status::NO_OPTIMUM) and its options
/// asked for an exception (`throw_on_failure`; doc/concepts.md, "One failure policy"). It carries
/// the family's report, the one the curve would have had: report<Kappa_curve_report>() returns it,
/// report<T>() of any other type T returns nullptr. Without throw_on_failure no family throws for
/// a failed solve: its status says it.
class Solve_error : public Error {
public:
  template <class Report>
  Solve_error(const std::string& what, const Report& report)
    : Error(what), report_(std::make_shared<const std::any>(report)) {}
  /// The carried report if it is a Report, else nullptr. Lives as long as this error.
  template <class Report>
  const Report* report() const noexcept {
    return std::any_cast<Report>(report_.get());
  }

private:
  // Shared, so that copying the error never allocates or throws (copies of an exception object
  // must not throw; std::runtime_error's own copy is noexcept for the same reason).
  std::shared_ptr<const std::any> report_;
};

/// A numerical routine that is not a family's solve (Bernstein root isolation, quadrature)
/// reached its iteration cap before its convergence criterion.
class Non_convergence_error : public Error {
public:
  Non_convergence_error(const std::string& what, std::size_t iterations, double residual)
    : Error(what), iterations_(iterations), residual_(residual) {}
  std::size_t iterations() const noexcept { return iterations_; }
  double residual() const noexcept { return residual_; }

private:
  std::size_t iterations_;
  double residual_;
};

/// A broken invariant inside the library: a bug in fair, never a problem of the caller's data.
/// Callers that catch Precondition_error or Invalid_input_error to repair their input do not
/// receive it. The message names the failed condition, the file and the line.
class Internal_error : public Error {
public:
  Internal_error(const std::string& what, const char* file, int line)
    : Error(std::string(file) + ":" + std::to_string(line) + ": internal error: " + what), file_(file), line_(line) {}
  const char* file() const noexcept { return file_; }
  int line() const noexcept { return line_; }

private:
  const char* file_;
  int line_;
};

} // namespace fair

// The message, precondition and invariant helpers every algorithm uses with these errors.
#include <fair/internal/common/checks.h>

/// FAIR_ASSERT(condition): an invariant of the library's own algorithms, not a check of user
/// input. Always on, also in release builds (a CAD kernel must not go on past a broken
/// invariant): throws fair::Internal_error naming the expression, the file and the line.
/// FAIR_ASSERT_MSG(condition, parts...) appends the parts (operator<<) to the message.
#define FAIR_ASSERT(condition) \
  ::fair::internal::check_invariant(static_cast<bool>(condition), #condition, __FILE__, __LINE__)
#define FAIR_ASSERT_MSG(condition, ...) \
  ::fair::internal::check_invariant(static_cast<bool>(condition), #condition, __FILE__, __LINE__, __VA_ARGS__)

#endif // FAIR_ERRORS_H
