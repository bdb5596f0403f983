// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The typed errors of the library. Every failure the library detects is reported by
// throwing one of these; none of its functions returns NaN or loops without a cap.

#ifndef FAIR_ERRORS_H
#define FAIR_ERRORS_H

#include <cstddef>
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

/// An iterative method reached its iteration cap before its convergence criterion.
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

namespace internal {

/// Concatenates its arguments with operator<< into one message.
template <class... Args>
std::string message(const Args&... args) {
  std::ostringstream out;
  out.precision(17);
  (out << ... << args);
  return out.str();
}

/// Throws Precondition_error with the concatenated message unless `condition` holds.
template <class... Args>
void require(bool condition, const Args&... args) {
  if (!condition) throw Precondition_error(message(args...));
}

} // namespace internal
} // namespace fair

#endif // FAIR_ERRORS_H
