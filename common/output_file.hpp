// An output file written under a temporary name beside the target and renamed into place
// only by commit(). If the writer throws, the destructor removes the temporary file, so
// a failed run never leaves a partial output behind (DESIGN.md principle 7).
#pragma once

#include <filesystem>
#include <string>

namespace plumbago {

class OutputFile {
 public:
  explicit OutputFile(std::string path);
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  // Same extension as the target, so format-sniffing writers pick the right format.
  const std::string& temporary_path() const { return temporary_; }
  void commit();

 private:
  std::string path_, temporary_;
  bool committed_ = false;
};

}  // namespace plumbago
