// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Implementation of the number parsing and file reading of fair/io/parsing.h.
//
// A coordinate is either a decimal number (JSON number grammar, also accepting a leading '+'
// and a missing integer part such as ".5") or, for users of exact kernels, an exact rational
// "p/q" with integer p and q. Decimal numbers are converted to the nearest double (correct
// rounding, locale independent: std::from_chars), then to FT, so every kernel sees the same
// value. A rational is converted exactly when FT is an exact field type (Gmpq, EPECK's FT) and
// to the correctly rounded quotient of p and q otherwise (exact when |p|, |q| < 2^53).

#ifndef FAIR_IO_INTERNAL_NUMBER_PARSING_H
#define FAIR_IO_INTERNAL_NUMBER_PARSING_H

#include <fair/Errors.h>
#include <fair/io/parsing.h>

#include <CGAL/Algebraic_structure_traits.h>
#include <CGAL/number_utils.h>

#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>
#include <type_traits>
#include <utility>

namespace fair {
namespace io {
namespace internal {

/// Quotes `text` for an error message, shortening very long fields.
/// Control characters are shown escaped so that the message stays on one line.
inline std::string quoted(const std::string& text) {
  std::string shown;
  for (char c : text.size() <= 40 ? text : text.substr(0, 37)) {
    const unsigned char u = static_cast<unsigned char>(c);
    if (c == '\n') shown += "\\n";
    else if (c == '\r') shown += "\\r";
    else if (c == '\t') shown += "\\t";
    else if (u < 0x20 || u == 0x7f) shown += "\\x" + std::string(1, "0123456789abcdef"[u >> 4]) + "0123456789abcdef"[u & 15];
    else shown += c;
  }
  return "'" + shown + (text.size() <= 40 ? "'" : "...'");
}

inline bool is_digit(char c) { return c >= '0' && c <= '9'; }

/// Length of the longest prefix of `s` matching [+-]?(digits)?(.digits?)?([eE][+-]?digits)?
/// with at least one mantissa digit; 0 when there is none.
inline std::size_t decimal_prefix_length(const std::string& s) {
  std::size_t i = 0;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  std::size_t digits = 0;
  while (i < s.size() && is_digit(s[i])) ++i, ++digits;
  if (i < s.size() && s[i] == '.') {
    ++i;
    while (i < s.size() && is_digit(s[i])) ++i, ++digits;
  }
  if (digits == 0) return 0;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    std::size_t j = i + 1;
    if (j < s.size() && (s[j] == '+' || s[j] == '-')) ++j;
    std::size_t exp_digits = 0;
    while (j < s.size() && is_digit(s[j])) ++j, ++exp_digits;
    if (exp_digits > 0) i = j;
  }
  return i;
}

/// Checks that `s` is [+-]?digits (sign allowed only if `signed_ok`).
inline bool is_integer_text(const std::string& s, bool signed_ok) {
  std::size_t i = 0;
  if (signed_ok && i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  if (i == s.size()) return false;
  for (; i < s.size(); ++i)
    if (!is_digit(s[i])) return false;
  return true;
}

/// An FT holding the integer written in decimal `digits` (optional leading '-'), built by
/// Horner's rule in FT arithmetic: exact for an exact FT.
template <class FT>
FT integer_from_digits(const std::string& digits) {
  FT value(0);
  const FT ten(10);
  std::size_t i = digits[0] == '-' ? 1 : 0;
  for (; i < digits.size(); ++i) value = value * ten + FT(digits[i] - '0');
  return digits[0] == '-' ? -value : value;
}

template <class T, class = void>
struct Lazy_exact_type {
  typedef void type;
};
/// The exact number type behind a lazy FT (CGAL::Lazy_exact_nt<ET>, EPECK's FT): ET.
template <class T>
struct Lazy_exact_type<T, std::void_t<decltype(std::declval<const T&>().exact())>> {
  typedef std::decay_t<decltype(std::declval<const T&>().exact())> type;
};

} // namespace internal

// The functions of fair/io/parsing.h (their contracts are there).

inline double parse_decimal(const std::string& text, const std::string& file, std::size_t line,
                            const char* what) {
  using internal::quoted;
  auto fail = [&](const std::string& why) {
    throw Parse_error(file, line, std::string(what) + " " + quoted(text) + " " + why);
  };
  if (text.empty()) fail("is empty, expected a number");
  std::string lower;
  for (char c : text) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  std::size_t sign = (lower[0] == '+' || lower[0] == '-') ? 1 : 0;
  const std::string body = lower.substr(sign);
  if (body.rfind("nan", 0) == 0) fail("is NaN, expected a finite number");
  if (body.rfind("inf", 0) == 0) fail("is infinite, expected a finite number");
  if (body.rfind("0x", 0) == 0) fail("is hexadecimal, expected a decimal number");
  const std::size_t n = internal::decimal_prefix_length(text);
  if (n == 0) fail("is not a number");
  if (n != text.size())
    fail("has trailing garbage " + quoted(text.substr(n)) + " after the number");
  // std::from_chars does not accept a leading '+'.
  const std::size_t start = text[0] == '+' ? 1 : 0;
  double value = 0;
  const char* first = text.data() + start;
  const char* last = text.data() + text.size();
  const std::from_chars_result r = std::from_chars(first, last, value);
  if (r.ec == std::errc::result_out_of_range) {
    // from_chars leaves `value` untouched on range errors: decide by the exponent's sign
    // whether the magnitude is too large or too small.
    const std::size_t e = lower.find('e');
    const bool tiny = e != std::string::npos && e + 1 < lower.size() && lower[e + 1] == '-';
    if (tiny) fail("is too small: it underflows to zero in double precision");
    fail("is too large: it overflows double precision");
  }
  if (r.ec != std::errc() || r.ptr != last) fail("is not a number");
  if (!std::isfinite(value)) fail("is not finite");
  return value;
}

inline Parsed_number parse_number(const std::string& text, const std::string& file,
                                  std::size_t line, const char* what) {
  Parsed_number out;
  const std::size_t slash = text.find('/');
  if (slash == std::string::npos) {
    out.value = parse_decimal(text, file, line, what);
    return out;
  }
  using internal::quoted;
  const std::string p = text.substr(0, slash), q = text.substr(slash + 1);
  if (!internal::is_integer_text(p, true) || !internal::is_integer_text(q, false))
    throw Parse_error(file, line, std::string(what) + " " + quoted(text) +
                                      " is not a number (a rational must be written p/q with "
                                      "integers p and q > 0)");
  const bool zero_q = q.find_first_not_of('0') == std::string::npos;
  if (zero_q)
    throw Parse_error(file, line,
                      std::string(what) + " " + quoted(text) + " has a zero denominator");
  const double pd = parse_decimal(p, file, line, what), qd = parse_decimal(q, file, line, what);
  // IEEE division is correctly rounded, so the quotient is the nearest double whenever p and
  // q are exactly representable (|p|, |q| < 2^53).
  out.value = pd / qd;
  if (!std::isfinite(out.value) || (out.value == 0 && p.find_first_not_of("+-0") != std::string::npos))
    throw Parse_error(file, line, std::string(what) + " " + quoted(text) +
                                      " is outside the range of double precision");
  out.rational = true;
  out.numerator = p[0] == '+' ? p.substr(1) : p;
  out.denominator = q;
  return out;
}

template <class FT>
FT to_ft(const Parsed_number& n) {
  typedef typename CGAL::Algebraic_structure_traits<FT>::Is_exact Is_exact;
  if constexpr (Is_exact::value && !std::is_floating_point<FT>::value) {
    if (n.rational) {
      typedef typename internal::Lazy_exact_type<FT>::type ET;
      if constexpr (!std::is_void<ET>::value && std::is_constructible<FT, ET>::value) {
        // Compute in the exact type directly rather than building a lazy expression DAG.
        return FT(internal::integer_from_digits<ET>(n.numerator) / internal::integer_from_digits<ET>(n.denominator));
      } else {
        return internal::integer_from_digits<FT>(n.numerator) / internal::integer_from_digits<FT>(n.denominator);
      }
    }
  }
  return FT(n.value);
}

inline std::string read_text_file(const std::string& file) {
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec))
    throw Parse_error(file, 0, "cannot read: it is a directory");
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    const int e = errno;
    throw Parse_error(file, 0, std::string("cannot open file: ") +
                                   (e ? std::strerror(e) : "unknown error"));
  }
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) throw Parse_error(file, 0, "read error");
  return buffer.str();
}

} // namespace io
} // namespace fair

#endif // FAIR_IO_INTERNAL_NUMBER_PARSING_H
