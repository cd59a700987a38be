#include "common/util/output_file.hpp"

#include "common/util/input_file.hpp"

#include <signal.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>

namespace plumbago {

namespace fs = std::filesystem;

namespace {

void check_writable_folder(const fs::path& dir, const std::string& what) {
  if (!fs::is_directory(dir)) throw std::runtime_error(what + ": folder '" + dir.string() + "' does not exist");
  if (::access(dir.c_str(), W_OK | X_OK) != 0)
    throw std::runtime_error(what + ": folder '" + dir.string() + "' is not writable");
}

// What a run stopped by a signal leaves to remove: the temporary files and the folders made
// for outputs, while they are not committed.
class Unfinished {
 public:
  static Unfinished& get() {
    static Unfinished* all = new Unfinished;  // never destroyed: the watcher may use it while main returns
    return *all;
  }
  void add(const fs::path& p, bool folder) {
    std::lock_guard lock(mutex_);
    (folder ? folders_ : files_).insert(p);
  }
  void remove(const fs::path& p, bool folder) {
    std::lock_guard lock(mutex_);
    (folder ? folders_ : files_).erase(p);
  }
  // Removes them all and never returns: the lock is held until the process ends, so no
  // thread registers a new file meanwhile.
  [[noreturn]] void remove_all_and_exit(int signal) {
    mutex_.lock();
    std::error_code ec;
    for (const fs::path& p : files_) fs::remove(p, ec);
    for (auto it = folders_.rbegin(); it != folders_.rend(); ++it) fs::remove(*it, ec);  // only when empty
    std::fprintf(stderr, "plumbago: stopped by %s: %zu unfinished output file(s) removed\n", strsignal(signal),
                 files_.size());
    std::fflush(stderr);
    ::_exit(128 + signal);
  }

 private:
  std::mutex mutex_;
  std::set<fs::path> files_, folders_;  // folders: a deeper one sorts after its parent
};

}  // namespace

void remove_outputs_on_interrupt() {
  sigset_t stop;
  sigemptyset(&stop);
  sigaddset(&stop, SIGINT);
  sigaddset(&stop, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stop, nullptr);  // threads started later inherit the mask
  std::thread([stop] {
    int signal = 0;
    sigwait(&stop, &signal);
    Unfinished::get().remove_all_and_exit(signal);
  }).detach();
}

OutputFile::OutputFile(std::string path) : path_(std::move(path)) {
  fs::path p(path_);
  fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
  check_writable_folder(dir, path_);
  if (fs::is_directory(p)) throw std::runtime_error(path_ + ": is a folder, not a file");
  std::string name = p.stem().string();
  name.insert(0, 1, '.');
  name.append(".partial-").append(std::to_string(::getpid())).append(p.extension().string());
  temporary_ = (dir / name).string();
  // Written first under its temporary name, 1 + 9 + the pid's digits bytes longer.
  if (std::string why = path_length_fault(temporary_); !why.empty())
    throw std::runtime_error(shortened_path(path_) + ": cannot be written: as its temporary file " +
                             shortened_path(temporary_) + ", " + why);
  Unfinished::get().add(temporary_, false);
}

OutputFile::~OutputFile() {
  if (!committed_) {
    std::error_code ec;
    fs::remove(temporary_, ec);
    Unfinished::get().remove(temporary_, false);
  }
}

void OutputFile::commit() {
  std::error_code ec;
  fs::rename(temporary_, path_, ec);
  if (ec) throw std::runtime_error(path_ + ": cannot move the finished file into place: " + ec.message());
  committed_ = true;
  Unfinished::get().remove(temporary_, false);
}

OutputFiles::~OutputFiles() {
  files_.clear();  // removes the temporary files first
  for (const fs::path& p : made_) Unfinished::get().remove(p, true);
  if (committed_) return;
  std::error_code ec;
  for (auto it = made_.rbegin(); it != made_.rend(); ++it) fs::remove(*it, ec);  // only when empty
}

void OutputFiles::folder(const std::string& dir) {
  if (std::string why = path_length_fault(dir); !why.empty())
    throw std::runtime_error(shortened_path(dir) + ": cannot be made: " + why);
  fs::path missing = fs::path(dir).lexically_normal();
  if (!missing.has_filename()) missing = missing.parent_path();  // "out/" -> "out"
  std::vector<fs::path> made;
  for (; !missing.empty() && !fs::exists(missing); missing = missing.parent_path()) made.insert(made.begin(), missing);
  if (!missing.empty() && !fs::is_directory(missing))
    throw std::runtime_error(dir + ": " + (made.empty() ? "" : "'" + missing.string() + "' ") +
                             "is a file, not a folder");
  check_writable_folder(missing.empty() ? fs::path(".") : missing, dir);
  for (const fs::path& p : made) {
    Unfinished::get().add(p, true);
    fs::create_directory(p);
    made_.push_back(p);
  }
}

OutputFile& OutputFiles::add(const std::string& path) {
  for (auto& f : files_)
    if (f->path() == path) return *f;  // written again: the last write wins
  files_.push_back(std::make_unique<OutputFile>(path));
  return *files_.back();
}

void OutputFiles::commit() {
  for (auto& f : files_) f->commit();
  committed_ = true;
}

}  // namespace plumbago
