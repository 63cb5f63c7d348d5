// Result files written in full or not at all (docs/runtime.md, "Result files"): the text goes to a
// temporary file beside the target, "<path>.<pid>.partial", renamed onto the target by commit(). A
// run that stops before (an exception, SIGINT, SIGTERM, a crash) leaves the previous result intact;
// a killed run may leave its .partial file behind (ignored by git).
#pragma once

#include <fstream>
#include <string>

namespace rbdc {

class ResultFile {
 public:
  /// Opens the temporary file; throws std::runtime_error naming `path` if it cannot be written.
  explicit ResultFile(std::string path);
  /// Removes the temporary file unless committed.
  ~ResultFile();
  ResultFile(const ResultFile&) = delete;
  ResultFile& operator=(const ResultFile&) = delete;

  std::ostream& stream() { return out_; }
  const std::string& path() const { return path_; }
  /// Flushes, closes and renames the temporary file onto path(); throws std::runtime_error naming
  /// path() if writing or renaming failed. Further writes are an error.
  void commit();

 private:
  std::string path_, partial_;
  std::ofstream out_;
  bool committed_ = false;
};

/// Writes `text` to `path` through a ResultFile.
void write_result_file(const std::string& path, const std::string& text);

}  // namespace rbdc
