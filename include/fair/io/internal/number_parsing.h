// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Implementation of the number parsing and file reading of fair/io/parsing.h.
//
// A coordinate is either a decimal number (JSON number grammar, also accepting a leading '+'
// and a missing integer part such as ".5") or, for users of exact kernels, an exact rational
// "p/q" with integer p and q. Decimal numbers are converted to the nearest double (correct
// rounding, locale independent: std::from_chars), then to FT, so every kernel sees the same
// value. A rational is converted exactly when FT is an exact field type (Gmpq, EPECK's FT); its
// double is the correctly rounded value of the exact quotient p/q (computed as a GMP rational,
// so that p and q beyond the double range, such as 10^310 / (3 10^310), are read as what they
// are: issue 29 #10, #11).
// Inside JSON, a number token follows RFC 8259 exactly (is_json_number_text); the looser
// decimal grammar above is for the fields of CSV and number files and for JSON strings.

#ifndef FAIR_IO_INTERNAL_NUMBER_PARSING_H
#define FAIR_IO_INTERNAL_NUMBER_PARSING_H

#include <fair/Errors.h>
#include <fair/io/parsing.h>

#include <CGAL/Algebraic_structure_traits.h>
#include <CGAL/Gmpq.h>
#include <CGAL/number_utils.h>

#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <limits>
#include <cstdint>
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

/// True when `text` starts with the UTF-8 byte-order mark EF BB BF.
inline bool has_byte_order_mark(const std::string& text) {
  return text.size() >= 3 && static_cast<unsigned char>(text[0]) == 0xEF &&
         static_cast<unsigned char>(text[1]) == 0xBB && static_cast<unsigned char>(text[2]) == 0xBF;
}

/// What a file starting with a byte-order mark is told (every reader refuses it by name: an
/// invisible mark would otherwise end up inside the first field, "'0' is not a number").
constexpr const char* byte_order_mark_message =
    "the file starts with a UTF-8 byte-order mark (bytes EF BB BF); save it as plain UTF-8 without the mark";

/// RFC 8259 number: -?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?. Refuses what the looser
/// decimal grammar of the other files accepts: "01", "1.", ".5", "+1".
inline bool is_json_number_text(const std::string& s) {
  std::size_t i = 0;
  if (i < s.size() && s[i] == '-') ++i;
  if (i == s.size()) return false;
  if (s[i] == '0') ++i;
  else if (s[i] >= '1' && s[i] <= '9') while (i < s.size() && is_digit(s[i])) ++i;
  else return false;
  if (i < s.size() && s[i] == '.') {
    ++i;
    const std::size_t start = i;
    while (i < s.size() && is_digit(s[i])) ++i;
    if (i == start) return false;
  }
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    const std::size_t start = i;
    while (i < s.size() && is_digit(s[i])) ++i;
    if (i == start) return false;
  }
  return i == s.size();
}

/// How a rational rounds to double.
enum class Rational_rounding { FINITE, OVERFLOW, UNDERFLOW };

/// The double nearest to q (ties to even), subnormals included. `status` is OVERFLOW when q
/// rounds beyond the largest double, UNDERFLOW when q != 0 rounds to zero (the value is then
/// +-inf or +-0). mpq_get_d truncates towards zero, so q lies between that double c and its
/// neighbour n away from zero; the exact midpoint of c and n decides.
inline double nearest_double(const CGAL::Gmpq& q, Rational_rounding& status) {
  status = Rational_rounding::FINITE;
  const int sign = mpq_sgn(q.mpq());
  if (sign == 0) return 0.0;
  const CGAL::Gmpq a = sign < 0 ? -q : q;
  const double c = mpq_get_d(a.mpq()); // truncated: c <= a
  double r;
  if (!std::isfinite(c)) {
    r = std::numeric_limits<double>::infinity();
  } else if (CGAL::Gmpq(c) == a) {
    r = c;
  } else {
    const double n = std::nextafter(c, std::numeric_limits<double>::infinity());
    // The midpoint of c and n; for c = DBL_MAX, n = inf: DBL_MAX + 2^970 (half an ulp).
    const CGAL::Gmpq upper = std::isfinite(n) ? CGAL::Gmpq(n) : CGAL::Gmpq(c) + CGAL::Gmpq(std::ldexp(1.0, 971));
    const CGAL::Gmpq mid = (CGAL::Gmpq(c) + upper) / 2;
    const int cmp = mpq_cmp(a.mpq(), mid.mpq());
    bool up = cmp > 0;
    if (cmp == 0) {
      // Ties to even: the neighbour whose last mantissa bit is 0 (inf counts as even).
      std::uint64_t bits;
      std::memcpy(&bits, &c, sizeof bits);
      up = (bits & 1) != 0;
    }
    r = up ? n : c;
  }
  if (!std::isfinite(r)) status = Rational_rounding::OVERFLOW;
  else if (r == 0) status = Rational_rounding::UNDERFLOW;
  return sign < 0 ? -r : r;
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

/// Cap on the digits of the numerator and of the denominator of a "p/q" number: far beyond what
/// the program writes (an exact curve of fair-curves has rationals of some hundreds of digits;
/// a cap of 10^5 digits keeps one number's GMP work and memory in the milliseconds and kB).
constexpr std::size_t max_rational_digits = 100000;

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
  if (p.size() > max_rational_digits || q.size() > max_rational_digits)
    throw Parse_error(file, line, fair::internal::message(what, " ", quoted(text), " has more than ",
                                                          max_rational_digits, " digits in its numerator or denominator"));
  out.rational = true;
  out.numerator = p[0] == '+' ? p.substr(1) : p;
  out.denominator = q;
  // The exact quotient, then its nearest double: p and q may each be far beyond the double range
  // while p/q is an ordinary number (the program's own exact output has such digits).
  CGAL::Gmpq exact;
  mpq_set_str(exact.mpq(), (out.numerator + "/" + out.denominator).c_str(), 10);
  mpq_canonicalize(exact.mpq());
  internal::Rational_rounding status;
  out.value = internal::nearest_double(exact, status);
  if (status == internal::Rational_rounding::OVERFLOW)
    throw Parse_error(file, line, std::string(what) + " " + quoted(text) +
                                      " is too large: it overflows double precision");
  if (status == internal::Rational_rounding::UNDERFLOW)
    throw Parse_error(file, line, std::string(what) + " " + quoted(text) +
                                      " is too small: it underflows to zero in double precision");
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
