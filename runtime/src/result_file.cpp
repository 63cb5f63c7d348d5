#include "rbdc/result_file.hpp"

#include <unistd.h>

#include <cstdio>
#include <stdexcept>

namespace rbdc {

ResultFile::ResultFile(std::string path)
    : path_(std::move(path)), partial_(path_ + "." + std::to_string(::getpid()) + ".partial"), out_(partial_) {
  if (!out_) throw std::runtime_error("cannot write '" + path_ + "' (temporary file '" + partial_ + "')");
}

ResultFile::~ResultFile() {
  if (!committed_) std::remove(partial_.c_str());
}

void ResultFile::commit() {
  out_.close();
  if (!out_) throw std::runtime_error("writing '" + path_ + "' failed (temporary file '" + partial_ + "')");
  if (std::rename(partial_.c_str(), path_.c_str()) != 0) {
    throw std::runtime_error("cannot rename '" + partial_ + "' to '" + path_ + "'");
  }
  committed_ = true;
}

void write_result_file(const std::string& path, const std::string& text) {
  ResultFile file(path);
  file.stream() << text;
  file.commit();
}

}  // namespace rbdc
