#include "fuzz_support.hpp"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "rbdc/ir_json.hpp"
#include "strict_json.hpp"

namespace rbdc_fuzz {

InputFile::InputFile(const std::string& extension)
    : path_((std::filesystem::temp_directory_path() /
             ("rbdc-fuzz-" + std::to_string(::getpid()) + extension)).string()) {}

InputFile::~InputFile() {
  std::error_code ignored;
  std::filesystem::remove(path_, ignored);
}

const std::string& InputFile::write(const uint8_t* data, size_t size) const {
  std::ofstream out(path_, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  out.close();
  if (!out) {
    std::fprintf(stderr, "fuzz: cannot write %s\n", path_.c_str());
    std::abort();
  }
  return path_;
}

void check_error_names_file(const std::string& message, const std::string& path) {
  if (message.find(path) != std::string::npos) return;
  std::fprintf(stderr, "fuzz: the error does not name the file %s:\n%s\n", path.c_str(), message.c_str());
  std::abort();
}

void check_ir(const rbdc::Model& model) {
  const std::string ir = rbdc::to_ir_json(model);
  const std::string error = strict_json_error(ir);
  if (error.empty()) return;
  std::fprintf(stderr, "fuzz: the IR is not strict JSON (%s):\n%s\n", error.c_str(), ir.c_str());
  std::abort();
}

}  // namespace rbdc_fuzz
