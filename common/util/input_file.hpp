// The text files read whole: scenes, stroke files, stroke styles, SVG drawings. Each is
// checked before it is opened: a regular file (not a folder, a FIFO or a device such as
// /dev/zero, which would be read without end) of at most kMaxInputFileBytes; and it is
// read no further than that, should it grow meanwhile (docs/bad-input.md, "Input files").
#pragma once

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace plumbago {

// 32 MiB: 250 times the largest stroke file and SVG in scenes/drawn (120 KB), and small
// enough that a JSON document of that size is held in under a GB (measured: 0.81 GB for
// a stroke file of 32 MiB of small numbers, nlohmann's DOM).
constexpr uint64_t kMaxInputFileBytes = 32ull << 20;

// The refusal of a reader that several file kinds share (this one, parse_json_text of
// common/scene/json_position.hpp): the message names the file; the caller rethrows it as
// its own error type (rethrown_as).
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// read() (a shared reader's result), its InputError rethrown as an `Error`.
template <class Error, class Read>
auto rethrown_as(Read read) {
  try {
    return read();
  } catch (const InputError& e) {
    throw Error(e.what());
  }
}

// The longest file name (one component of a path) and whole path the system takes
// (Linux's NAME_MAX and PATH_MAX, with its NUL).
constexpr size_t kMaxFileNameBytes = 255, kMaxPathBytes = 4095;

// `path` for a message: itself, or its first and last 40 bytes around "..." when it is
// longer than 100.
std::string shortened_path(const std::string& path);

// Why the system would refuse `path` as too long ("File name too long"): the length and
// the limit, and the name over it; empty when it is not too long. The caller names the
// path (shortened_path).
std::string path_length_fault(const std::string& path);

// The bytes of the file at `path`; `what` names its kind in a refusal, which is an
// InputError such as "PATH: cannot read the stroke file: it is a character device,
// not a regular file" or "PATH: the SVG drawing is 40000000 bytes, over the limit of
// 33554432 bytes (32 MiB) on an input file".
std::string read_input_file(const std::string& path, const std::string& what);

// read_input_file, its refusal thrown as an `Error` (the reader's own error type).
template <class Error>
std::string read_input_file_as(const std::string& path, const std::string& what) {
  return rethrown_as<Error>([&] { return read_input_file(path, what); });
}

}  // namespace plumbago
