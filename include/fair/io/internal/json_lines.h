// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Implementation of fair::io::parse_json (fair/io/parsing.h): a small strict JSON reader that
// remembers the 1-based line of every value, so that a point file's errors (a pair with three
// entries, a string where a number belongs, ...) can be reported at their line, which a
// general-purpose JSON library does not provide. Writing uses nlohmann-json
// (fair/io/write_json.h).
//
// Grammar: RFC 8259, strictly: a number token must match the RFC's grammar (no "01", "1.", ".5",
// "+1") and is then converted by fair::io::parse_decimal (so NaN, Infinity and out-of-range
// numbers get a precise message); duplicate member names in one object are refused; a UTF-8
// byte-order mark (which RFC 8259 forbids a writer to add) is refused by name, not reported as
// an invisible character inside a value. Nesting is capped at 64 levels so that hostile input
// cannot exhaust the stack.

#ifndef FAIR_IO_INTERNAL_JSON_LINES_H
#define FAIR_IO_INTERNAL_JSON_LINES_H

#include <fair/Errors.h>
#include <fair/io/internal/number_parsing.h>
#include <fair/io/parsing.h>

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace fair {
namespace io {
namespace internal {

// Deepest nesting accepted: far beyond any point or curve file, small enough that hostile
// input cannot exhaust the stack of the recursive descent.
constexpr int max_json_depth = 64;

/// Recursive-descent parser over an in-memory text.
class Json_line_parser {
public:
  Json_line_parser(const std::string& text, const std::string& file) : s_(text), file_(file) {}

  /// Parses the whole text as one JSON value; throws Parse_error on any problem.
  Json_value parse() {
    if (has_byte_order_mark(s_)) throw Parse_error(file_, 1, byte_order_mark_message);
    skip_space();
    if (i_ == s_.size()) throw Parse_error(file_, 0, "the file is empty, expected JSON");
    Json_value v = value(0);
    skip_space();
    if (i_ != s_.size())
      fail("trailing garbage " + quoted(s_.substr(i_, std::min<std::size_t>(20, s_.find('\n', i_) - i_))) +
           " after the JSON value");
    return v;
  }

private:
  [[noreturn]] void fail(const std::string& what) const {
    if (i_ >= s_.size()) {
      // At the end of the text, report the last line that has content.
      std::size_t line = 1;
      const std::size_t last = s_.find_last_not_of(" \t\r\n");
      for (std::size_t k = 0; last != std::string::npos && k < last; ++k)
        if (s_[k] == '\n') ++line;
      throw Parse_error(file_, line, "unexpected end of file: " + what);
    }
    throw Parse_error(file_, line_, what);
  }

  void skip_space() {
    while (i_ < s_.size()) {
      const char c = s_[i_];
      if (c == '\n') ++line_;
      if (c == ' ' || c == '\t' || c == '\n' || c == '\r') ++i_;
      else break;
    }
  }

  Json_value value(int depth) {
    if (depth > max_json_depth)
      fail("JSON nested more than " + std::to_string(max_json_depth) + " levels deep");
    skip_space();
    if (i_ == s_.size()) fail("expected a JSON value");
    Json_value v;
    v.line = line_;
    const char c = s_[i_];
    if (c == '{') {
      v.kind = Json_value::OBJECT;
      ++i_;
      skip_space();
      if (i_ < s_.size() && s_[i_] == '}') { ++i_; return v; }
      std::set<std::string> keys;
      for (;;) {
        skip_space();
        if (i_ == s_.size() || s_[i_] != '"') fail("expected a quoted member name in an object");
        const std::size_t key_line = line_;
        std::string key = string_contents();
        // RFC 8259 leaves duplicate names to the reader; two "points" would otherwise be read as
        // the first one silently (issue 29 #18), so they are refused.
        if (!keys.insert(key).second)
          throw Parse_error(file_, key_line, "duplicate member \"" + key + "\" in an object");
        skip_space();
        if (i_ == s_.size() || s_[i_] != ':') fail("expected ':' after member name \"" + key + "\"");
        ++i_;
        Json_value member = value(depth + 1);
        v.members.emplace_back(std::move(key), std::move(member));
        skip_space();
        if (i_ < s_.size() && s_[i_] == ',') { ++i_; continue; }
        if (i_ < s_.size() && s_[i_] == '}') { ++i_; return v; }
        fail("expected ',' or '}' in an object");
      }
    }
    if (c == '[') {
      v.kind = Json_value::ARRAY;
      ++i_;
      skip_space();
      if (i_ < s_.size() && s_[i_] == ']') { ++i_; return v; }
      for (;;) {
        v.items.push_back(value(depth + 1));
        skip_space();
        if (i_ < s_.size() && s_[i_] == ',') { ++i_; continue; }
        if (i_ < s_.size() && s_[i_] == ']') { ++i_; return v; }
        fail("expected ',' or ']' in an array");
      }
    }
    if (c == '"') {
      v.kind = Json_value::STRING;
      v.text = string_contents();
      return v;
    }
    // A number or a literal: take the whole token, so that "1.5abc" or "NaN" is reported whole.
    std::size_t j = i_;
    while (j < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[j])) || s_[j] == '+' ||
                             s_[j] == '-' || s_[j] == '.'))
      ++j;
    const std::string token = s_.substr(i_, j - i_);
    if (token.empty()) fail("unexpected character " + quoted(std::string(1, c)));
    i_ = j;
    if (token == "true" || token == "false") {
      v.kind = Json_value::BOOLEAN;
      v.flag = token == "true";
      return v;
    }
    if (token == "null") return v;
    // parse_decimal throws with the precise reason (NaN, infinite, garbage, range).
    parse_decimal(token, file_, line_, "number");
    if (!is_json_number_text(token))
      fail("number " + quoted(token) +
           " is not a JSON number (RFC 8259: no leading '+', no leading zeros, digits on both sides of '.')");
    v.kind = Json_value::NUMBER;
    v.text = token;
    return v;
  }

  // Reads a quoted string starting at s_[i_] == '"'; decodes the escapes (\uXXXX to UTF-8).
  std::string string_contents() {
    ++i_;
    std::string out;
    for (;;) {
      if (i_ == s_.size()) fail("unterminated string");
      const char c = s_[i_++];
      if (c == '"') return out;
      if (static_cast<unsigned char>(c) < 0x20) fail("control character inside a string");
      if (c != '\\') { out += c; continue; }
      if (i_ == s_.size()) fail("unterminated string");
      const char e = s_[i_++];
      switch (e) {
        case '"': out += '"'; break;
        case '\\': out += '\\'; break;
        case '/': out += '/'; break;
        case 'b': out += '\b'; break;
        case 'f': out += '\f'; break;
        case 'n': out += '\n'; break;
        case 'r': out += '\r'; break;
        case 't': out += '\t'; break;
        case 'u': {
          if (i_ + 4 > s_.size()) fail("truncated \\u escape");
          unsigned code = 0;
          for (int k = 0; k < 4; ++k) {
            const char h = s_[i_++];
            code <<= 4;
            if (h >= '0' && h <= '9') code |= unsigned(h - '0');
            else if (h >= 'a' && h <= 'f') code |= unsigned(h - 'a' + 10);
            else if (h >= 'A' && h <= 'F') code |= unsigned(h - 'A' + 10);
            else fail("bad hexadecimal digit in \\u escape");
          }
          // Surrogate halves are kept as their 3-byte encoding; keys and numbers are ASCII.
          if (code < 0x80) out += static_cast<char>(code);
          else if (code < 0x800) {
            out += static_cast<char>(0xC0 | (code >> 6));
            out += static_cast<char>(0x80 | (code & 0x3F));
          } else {
            out += static_cast<char>(0xE0 | (code >> 12));
            out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
            out += static_cast<char>(0x80 | (code & 0x3F));
          }
          break;
        }
        default: fail(std::string("unknown escape '\\") + e + "' in a string");
      }
    }
  }

  const std::string& s_;
  const std::string& file_;
  std::size_t i_ = 0;
  std::size_t line_ = 1;
};

} // namespace internal

// Declared, with its contract, in fair/io/parsing.h.
inline Json_value parse_json(const std::string& text, const std::string& file) {
  return internal::Json_line_parser(text, file).parse();
}

} // namespace io
} // namespace fair

#endif // FAIR_IO_INTERNAL_JSON_LINES_H
