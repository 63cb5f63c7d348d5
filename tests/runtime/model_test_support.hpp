// Helpers shared by the runtime tests: fixture paths and capturing a ModelError's or an
// std::invalid_argument's message.
#pragma once

#include <functional>
#include <stdexcept>
#include <string>

#include "rbdc/model_builder.hpp"

namespace rbdc::test {

inline std::string source_path(const std::string& relative) {
  return std::string(RBDC_SOURCE_DIR) + "/" + relative;
}

inline std::string data_path(const std::string& name) { return source_path("tests/data/" + name); }

/// The ModelError message thrown by `load`, or "no error".
inline std::string model_error(const std::function<void()>& load) {
  try {
    load();
  } catch (const ModelError& e) {
    return e.what();
  }
  return "no error";
}

/// The std::invalid_argument message thrown by `call` (a runtime function refusing its arguments or
/// its model), or "no error".
inline std::string argument_error(const std::function<void()>& call) {
  try {
    call();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace rbdc::test
