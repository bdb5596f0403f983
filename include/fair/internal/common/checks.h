// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// How the library raises the errors of fair/Errors.h: one message from many parts, preconditions
// (Precondition_error) and invariants (Internal_error, through FAIR_ASSERT). Included by
// fair/Errors.h after the error classes; every algorithm gets it from there.

#ifndef FAIR_INTERNAL_COMMON_CHECKS_H
#define FAIR_INTERNAL_COMMON_CHECKS_H

#include <sstream>
#include <string>

namespace fair {

class Precondition_error;
class Internal_error;

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

/// Throws Internal_error recording the condition, file and line unless `condition` holds.
template <class... Args>
void check_invariant(bool condition, const char* expression, const char* file, int line, const Args&... args) {
  if (!condition) throw Internal_error(message(expression, " does not hold", (sizeof...(args) ? ": " : ""), args...), file, line);
}

} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_COMMON_CHECKS_H
