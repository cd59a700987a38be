// Where a byte offset of a JSON document lies, for the messages that refuse it (scene
// files, stroke style files).
#pragma once

#include <string>

namespace plumbago {

// "line L, column C" of byte `byte` (1-based, as nlohmann counts) of `text`.
inline std::string line_and_column(const std::string& text, size_t byte) {
  size_t line = 1, column = 1;
  for (size_t i = 0; i + 1 < byte && i < text.size(); ++i) {
    if (text[i] == '\n')
      ++line, column = 1;
    else
      ++column;
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

}  // namespace plumbago
