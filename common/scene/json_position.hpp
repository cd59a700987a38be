// Where a byte offset of a text lies, for the messages that refuse it (scene files,
// stroke files, stroke style files, SVG drawings); and JSON documents parsed so that a
// refusal names that place.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "common/util/input_file.hpp"

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

// The document of `text`; throws InputError naming `source` and the place:
// "SOURCE: line L, column C: not valid JSON (...)" for a syntax error, "...: cannot read
// the JSON (...)" for a number beyond double range (1e400).
nlohmann::json parse_json_text(const std::string& text, const std::string& source);

// parse_json_text, its refusal thrown as an `Error` (the reader's own error type).
template <class Error>
nlohmann::json parse_json_text_as(const std::string& text, const std::string& source) {
  return rethrown_as<Error>([&] { return parse_json_text(text, source); });
}

}  // namespace plumbago
