// JSON documents parsed with the place of a refusal: see common/scene/json_position.hpp.
#include "common/scene/json_position.hpp"

namespace plumbago {

namespace {

using nlohmann::json;

// nlohmann's DOM parser, remembering where it stopped: it reports a number beyond double
// range (1e400) as out_of_range, an exception without the position.
struct PositionedParser : nlohmann::detail::json_sax_dom_parser<json> {
  using json_sax_dom_parser::json_sax_dom_parser;
  template <class Exception>
  bool parse_error(size_t position, const std::string& token, const Exception& e) {
    byte = position;
    return json_sax_dom_parser::parse_error(position, token, e);
  }
  size_t byte = 0;
};

}  // namespace

json parse_json_text(const std::string& text, const std::string& source) {
  json j;
  PositionedParser parser(j);
  try {
    json::sax_parse(text, &parser);
  } catch (const json::parse_error& e) {
    throw InputError(source + ": " + line_and_column(text, e.byte) + ": not valid JSON (" + e.what() + ")");
  } catch (const json::exception& e) {  // a number beyond double range: no position of its own
    throw InputError(source + ": " + line_and_column(text, parser.byte) + ": cannot read the JSON (" + e.what() + ")");
  }
  return j;
}

}  // namespace plumbago
