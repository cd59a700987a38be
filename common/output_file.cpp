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
  std::string name = p.stem().string();
  name.insert(0, 1, '.');
  name.append(".partial-").append(std::to_string(::getpid())).append(p.extension().string());
  temporary_ = (dir / name).string();
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
