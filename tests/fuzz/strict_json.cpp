// Recursive descent over the RFC 8259 grammar; the nesting depth is bounded so that the checker
// itself cannot overflow the stack.
#include "strict_json.hpp"

#include "text_checks.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>

namespace rbdc_fuzz {
namespace {

class Checker {
 public:
  explicit Checker(const std::string& text) : s_(text) {}

  std::string run() {
    if (!value(0)) return error_;
    space();
    if (at_ < s_.size()) fail("text after the value");
    return error_;
  }

 private:
  bool fail(const std::string& problem) {
    if (error_.empty()) error_ = "byte " + std::to_string(at_) + ": " + problem;
    return false;
  }
  char peek() const { return at_ < s_.size() ? s_[at_] : '\0'; }
  void space() {
    while (at_ < s_.size() && (s_[at_] == ' ' || s_[at_] == '\t' || s_[at_] == '\n' || s_[at_] == '\r')) ++at_;
  }
  bool literal(const char* word) {
    const std::string w(word);
    if (s_.compare(at_, w.size(), w) != 0) return fail("unknown literal");
    at_ += w.size();
    return true;
  }

  bool value(int depth) {
    if (depth > 64) return fail("nested too deeply");
    space();
    switch (peek()) {
      case '{': return object(depth);
      case '[': return array(depth);
      case '"': return string();
      case 't': return literal("true");
      case 'f': return literal("false");
      case 'n': return literal("null");
      default: return number();
    }
  }

  bool object(int depth) {
    ++at_;
    space();
    if (peek() == '}') return ++at_, true;
    for (;;) {
      space();
      if (peek() != '"') return fail("expected a key");
      if (!string()) return false;
      space();
      if (peek() != ':') return fail("expected ':'");
      ++at_;
      if (!value(depth + 1)) return false;
      space();
      if (peek() == ',') { ++at_; continue; }
      if (peek() == '}') return ++at_, true;
      return fail("expected ',' or '}'");
    }
  }

  bool array(int depth) {
    ++at_;
    space();
    if (peek() == ']') return ++at_, true;
    for (;;) {
      if (!value(depth + 1)) return false;
      space();
      if (peek() == ',') { ++at_; continue; }
      if (peek() == ']') return ++at_, true;
      return fail("expected ',' or ']'");
    }
  }

  bool hex4() {
    for (int k = 0; k < 4; ++k, ++at_) {
      if (!std::isxdigit(static_cast<unsigned char>(peek()))) return fail("bad \\u escape");
    }
    return true;
  }

  bool string() {
    const size_t start = ++at_;
    for (;;) {
      if (at_ >= s_.size()) return fail("unterminated string");
      const unsigned char c = static_cast<unsigned char>(s_[at_]);
      if (c == '"') {
        if (!rbdc::is_utf8(s_.substr(start, at_ - start))) return fail("string is not UTF-8");
        return ++at_, true;
      }
      if (c < 0x20) return fail("control character in a string");
      if (c != '\\') {
        ++at_;
        continue;
      }
      ++at_;
      const char e = peek();
      ++at_;
      if (e == 'u') {
        if (!hex4()) return false;
      } else if (std::string("\"\\/bfnrt").find(e) == std::string::npos || e == '\0') {
        return fail("bad escape");
      }
    }
  }

  bool digits() {
    const size_t start = at_;
    while (std::isdigit(static_cast<unsigned char>(peek()))) ++at_;
    return at_ > start;
  }

  bool number() {
    const size_t start = at_;
    if (peek() == '-') ++at_;
    if (peek() == '0') {
      ++at_;
    } else if (!digits()) {
      return fail("expected a value");
    }
    if (peek() == '.') {
      ++at_;
      if (!digits()) return fail("expected digits after '.'");
    }
    if (peek() == 'e' || peek() == 'E') {
      ++at_;
      if (peek() == '+' || peek() == '-') ++at_;
      if (!digits()) return fail("expected an exponent");
    }
    const double x = std::strtod(s_.substr(start, at_ - start).c_str(), nullptr);
    if (!std::isfinite(x)) return fail("number out of range");
    return true;
  }

  const std::string& s_;
  size_t at_ = 0;
  std::string error_;
};

}  // namespace

std::string strict_json_error(const std::string& text) { return Checker(text).run(); }

}  // namespace rbdc_fuzz
