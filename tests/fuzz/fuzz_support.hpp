// What every rbdc fuzz target does with an input (docs/fuzzing.md): the readers take paths, so the
// input is written to a file first; the reader must then return a result or throw a ModelError whose
// message names that file. Anything else (another exception, a sanitizer report, a leak, a hang)
// ends the run as a failure.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "rbdc/model_builder.hpp"

namespace rbdc_fuzz {

/// A file of this process (in the temporary folder, removed at exit) that holds the current input.
class InputFile {
 public:
  explicit InputFile(const std::string& extension);
  ~InputFile();
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;
  /// Replaces the file's content with the input and returns its path.
  const std::string& write(const uint8_t* data, size_t size) const;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

/// Aborts (a libFuzzer crash) when `message` does not contain `path`.
void check_error_names_file(const std::string& message, const std::string& path);

/// Runs `read`; a ModelError must name `path`, any other exception propagates (a libFuzzer crash).
template <class Read>
void expect_result_or_error(const std::string& path, Read&& read) {
  try {
    read();
  } catch (const rbdc::ModelError& e) {
    check_error_names_file(e.what(), path);
  }
}

/// The model's IR (to_ir_json) must be strict JSON (RFC 8259, UTF-8, finite numbers) that the
/// generator can read; aborts with the offending position otherwise.
void check_ir(const rbdc::Model& model);

}  // namespace rbdc_fuzz
