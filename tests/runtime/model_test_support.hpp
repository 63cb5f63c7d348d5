// Helpers shared by the model-loading tests: fixture paths and capturing a ModelError's message.
#pragma once

#include <functional>
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

}  // namespace rbdc::test
