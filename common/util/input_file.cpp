// Text files read whole, checked first: see common/util/input_file.hpp.
#include "common/util/input_file.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>

namespace plumbago {

namespace {

namespace fs = std::filesystem;

// What a file that is not a regular file is, for the refusal.
std::string kind_of(fs::file_type type) {
  static const std::map<fs::file_type, std::string> devices = {{fs::file_type::character, "a character device"},
                                                               {fs::file_type::block, "a block device"},
                                                               {fs::file_type::fifo, "a FIFO"},
                                                               {fs::file_type::socket, "a socket"}};
  if (type == fs::file_type::not_found) return "there is no such file";
  if (type == fs::file_type::directory) return "it is a folder";
  auto it = devices.find(type);
  return it == devices.end() ? "it is not a regular file" : "it is " + it->second + ", not a regular file";
}

// `size` says how large the file is ("70000000 bytes").
std::string over_the_limit(const std::string& path, const std::string& what, const std::string& size) {
  return path + ": the " + what + " is " + size + ", over the limit of " + std::to_string(kMaxInputFileBytes) +
         " bytes (" + std::to_string(kMaxInputFileBytes >> 20) + " MiB) on an input file";
}

}  // namespace

std::string shortened_path(const std::string& path) {
  return path.size() <= 100 ? path : path.substr(0, 40) + "..." + path.substr(path.size() - 40);
}

std::string path_length_fault(const std::string& path) {
  if (path.size() > kMaxPathBytes)
    return "the path is " + std::to_string(path.size()) + " bytes long, over the " + std::to_string(kMaxPathBytes) +
           " the system takes (PATH_MAX)";
  for (size_t begin = 0; begin <= path.size();) {
    const size_t end = std::min(path.find('/', begin), path.size());
    const std::string over = std::to_string(end - begin) + " bytes long, over the " +
                             std::to_string(kMaxFileNameBytes) + " the system takes (NAME_MAX)";
    if (end - begin > kMaxFileNameBytes)
      return end == path.size()
                 ? "its file name is " + over
                 : "the folder name '" + shortened_path(path.substr(begin, end - begin)) + "' in it is " + over;
    begin = end + 1;
  }
  return {};
}

std::string read_input_file(const std::string& path, const std::string& what) {
  if (std::string why = path_length_fault(path); !why.empty())
    throw InputError(shortened_path(path) + ": cannot read the " + what + ": " + why);
  std::error_code error;
  const fs::file_status status = fs::status(path, error);  // follows links; opens nothing
  if (status.type() != fs::file_type::regular)
    throw InputError(path + ": cannot read the " + what + ": " +
                     (error && status.type() != fs::file_type::not_found ? error.message() : kind_of(status.type())));
  const uint64_t size = fs::file_size(path, error);
  if (!error && size > kMaxInputFileBytes)
    throw InputError(over_the_limit(path, what, std::to_string(size) + " bytes"));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open the " + what);
  std::string text;
  text.reserve(size_t(error ? 0 : size));
  char chunk[1 << 16];
  while (in.read(chunk, sizeof chunk) || in.gcount() > 0) {
    text.append(chunk, size_t(in.gcount()));
    if (text.size() > kMaxInputFileBytes)  // it grew since its size was read
      throw InputError(over_the_limit(path, what, "over " + std::to_string(kMaxInputFileBytes) + " bytes"));
  }
  return text;
}

}  // namespace plumbago
