// The text files read whole: scenes, stroke files, stroke styles, SVG drawings. Each is
// checked before it is opened: a regular file (not a folder, a FIFO or a device such as
// /dev/zero, which would be read without end) of at most kMaxInputFileBytes; and it is
// read no further than that, should it grow meanwhile (docs/bad-input.md, "Input files").
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace plumbago {

// 64 MiB: 500 times the largest stroke file and SVG in scenes/drawn (120 KB), and small
// enough that a JSON or XML document of that size is held in well under a GB.
constexpr uint64_t kMaxInputFileBytes = 64ull << 20;

struct InputFileError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The bytes of the file at `path`; `what` names its kind in a refusal, which is an
// InputFileError such as "PATH: cannot read the stroke file: it is a character device,
// not a regular file" or "PATH: the SVG drawing is 70000000 bytes, over the limit of
// 67108864 bytes (64 MiB) on an input file".
std::string read_input_file(const std::string& path, const std::string& what);

// read_input_file, its refusal thrown as an `Error` (the reader's own error type).
template <class Error>
std::string read_input_file_as(const std::string& path, const std::string& what) {
  try {
    return read_input_file(path, what);
  } catch (const InputFileError& e) {
    throw Error(e.what());
  }
}

}  // namespace plumbago
