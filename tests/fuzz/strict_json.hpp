// A strict JSON validator (RFC 8259 grammar, UTF-8 strings, numbers that parse to finite doubles): what
// Python's json module reads without surprises, so what the IR writer must produce.
#pragma once

#include <string>

namespace rbdc_fuzz {

/// Empty when `text` is one strict JSON value (surrounded by whitespace at most), else
/// "byte <offset>: <problem>".
std::string strict_json_error(const std::string& text);

}  // namespace rbdc_fuzz
