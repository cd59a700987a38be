#include "common/output_file.hpp"

#include <unistd.h>

#include <stdexcept>

namespace plumbago {

namespace fs = std::filesystem;

OutputFile::OutputFile(std::string path) : path_(std::move(path)) {
  fs::path p(path_);
  fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
  if (!fs::is_directory(dir))
    throw std::runtime_error(path_ + ": folder '" + dir.string() + "' does not exist");
  temporary_ = (dir / ("." + p.stem().string() + ".partial-" + std::to_string(::getpid()) +
                       p.extension().string()))
                   .string();
}

OutputFile::~OutputFile() {
  if (!committed_) {
    std::error_code ec;
    fs::remove(temporary_, ec);
  }
}

void OutputFile::commit() {
  std::error_code ec;
  fs::rename(temporary_, path_, ec);
  if (ec) throw std::runtime_error(path_ + ": cannot move the finished file into place: " + ec.message());
  committed_ = true;
}

}  // namespace plumbago
