// Output files written under a temporary name beside the target and renamed into place
// only by commit(). If the writer throws, the destructor removes the temporary file, so
// a failed run never leaves a partial output behind (docs/design.md, principle 7); where
// remove_outputs_on_interrupt() was called, neither does a run stopped by SIGINT or SIGTERM.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace plumbago {

class OutputFile {
 public:
  // Refuses a target whose folder is missing or not writable, or that is a folder itself;
  // nothing is written yet.
  explicit OutputFile(std::string path);
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  const std::string& path() const { return path_; }
  // Same extension as the target, so format-sniffing writers pick the right format.
  const std::string& temporary_path() const { return temporary_; }
  void commit();

 private:
  std::string path_, temporary_;
  bool committed_ = false;
};

// The files of one command, which succeed or fail together: each location is checked when
// added (before anything is written), each file is written under its temporary name, and
// commit() renames them all. Without commit() the temporary files are removed, and so
// are the folders folder() made (when empty).
class OutputFiles {
 public:
  OutputFiles() = default;
  ~OutputFiles();
  OutputFiles(const OutputFiles&) = delete;
  OutputFiles& operator=(const OutputFiles&) = delete;

  // Makes `dir` and its missing parents; refuses a file in the way or a folder not writable.
  void folder(const std::string& dir);
  // Checks `path` (as OutputFile does) and reserves its temporary name; a path added
  // again gives the same file.
  OutputFile& add(const std::string& path);
  void commit();

 private:
  std::vector<std::unique_ptr<OutputFile>> files_;
  std::vector<std::filesystem::path> made_;  // folders made by folder(), outermost first
  bool committed_ = false;
};

// From now on, SIGINT and SIGTERM remove every temporary file not yet committed and every
// folder OutputFiles::folder made that is left empty, then end the process with 128 + the
// signal's number (130, 143). Call it first thing in main, before any thread starts: the
// signals are blocked in every thread and taken by one watcher thread, so the removal runs
// outside a signal handler and cannot find the list of files half-changed.
void remove_outputs_on_interrupt();

}  // namespace plumbago
