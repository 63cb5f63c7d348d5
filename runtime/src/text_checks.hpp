// Names travel into the IR (JSON, read as UTF-8 by the generator) and into comments and strings of
// generated C++, so the model builder accepts only plain text: valid UTF-8, no control characters.
#pragma once

#include <string>

namespace rbdc {

/// True when `s` is valid UTF-8 (shortest forms, no surrogates, at most U+10FFFF).
inline bool is_utf8(const std::string& s) {
  size_t at = 0;
  const auto byte = [&](size_t k) { return at + k < s.size() ? static_cast<unsigned char>(s[at + k]) : 0u; };
  while (at < s.size()) {
    const unsigned c = byte(0);
    size_t n = 0;
    unsigned lo = 0x80, hi = 0xBF;  // range of the second byte
    if (c < 0x80) {
      n = 1;
    } else if (c >= 0xC2 && c <= 0xDF) {
      n = 2;
    } else if (c >= 0xE0 && c <= 0xEF) {
      n = 3;
      if (c == 0xE0) lo = 0xA0;
      if (c == 0xED) hi = 0x9F;
    } else if (c >= 0xF0 && c <= 0xF4) {
      n = 4;
      if (c == 0xF0) lo = 0x90;
      if (c == 0xF4) hi = 0x8F;
    } else {
      return false;
    }
    for (size_t k = 1; k < n; ++k) {
      const unsigned b = byte(k);
      if (k == 1 ? (b < lo || b > hi) : (b < 0x80 || b > 0xBF)) return false;
    }
    at += n;
  }
  return true;
}

/// Valid UTF-8 without control characters (U+0000 … U+001F, U+007F).
inline bool is_plain_text(const std::string& s) {
  for (const char ch : s) {
    const unsigned char c = static_cast<unsigned char>(ch);
    if (c < 0x20 || c == 0x7F) return false;
  }
  return is_utf8(s);
}

/// `s` with every byte outside printable ASCII written as \xNN, for messages about bad names.
inline std::string escaped(const std::string& s) {
  static const char* const hex = "0123456789abcdef";
  std::string out;
  for (const char ch : s) {
    const unsigned char c = static_cast<unsigned char>(ch);
    if (c >= 0x20 && c < 0x7F) {
      out += ch;
    } else {
      out += "\\x";
      out += hex[c >> 4];
      out += hex[c & 15];
    }
  }
  return out;
}

}  // namespace rbdc
