// SVG numbers and path data: see common/strokes/svg_numbers.hpp.
#include "common/strokes/svg_numbers.hpp"

#include <cmath>
#include <cstdlib>
#include <cstring>

namespace plumbago {

namespace {

bool is_separator(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == ','; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_path_command(char c) { return c != '\0' && std::strchr("MmLlHhVvZzCcSsQqTtAa", c) != nullptr; }

// A word for a message: quoted, at most its first 24 characters.
std::string quoted(std::string_view word) {
  std::string out(1, '\'');  // appended, not added: GCC 12 warns (-Wrestrict) on "'" + string
  out.append(word.substr(0, 24)).append(word.size() > 24 ? "...'" : "'");
  return out;
}

// Reads numbers (and, in path data, command letters) from the front of a text.
class Scanner {
 public:
  Scanner(std::string_view text, bool path_data) : s_(text), path_data_(path_data) {}

  // Skips separators; whether anything is left.
  bool more() {
    while (at_ < s_.size() && is_separator(s_[at_])) ++at_;
    return at_ < s_.size();
  }

  // The path command letter at the cursor, read; '\0' (nothing read) when there is none.
  char command() {
    if (!path_data_ || !is_path_command(s_[at_])) return '\0';
    return s_[at_++];
  }

  // The number at the cursor, read; refuses what is not one.
  double number() {
    const size_t start = at_, end = number_end(start);
    if (end == start || (end < s_.size() && !may_follow_a_number(s_[end])))
      throw SvgNumberError(word(start) + " is not a number");
    const std::string digits(s_.substr(start, end - start));
    const double value = std::strtod(digits.c_str(), nullptr);  // the grammar is strtod's: it reads all of it
    if (!std::isfinite(value)) throw SvgNumberError(word(start) + " is beyond double range");
    at_ = end;
    return value;
  }

 private:
  // Where the number that starts at `i` ends (by the grammar); `i` when none starts there.
  size_t number_end(size_t i) const {
    const size_t start = i;
    if (i < s_.size() && (s_[i] == '+' || s_[i] == '-')) ++i;
    size_t digits = 0;
    for (; i < s_.size() && is_digit(s_[i]); ++i) ++digits;
    if (i < s_.size() && s_[i] == '.')
      for (++i; i < s_.size() && is_digit(s_[i]); ++i) ++digits;
    if (digits == 0) return start;
    if (i < s_.size() && (s_[i] == 'e' || s_[i] == 'E')) {
      size_t j = i + 1;
      if (j < s_.size() && (s_[j] == '+' || s_[j] == '-')) ++j;
      const size_t exponent = j;
      while (j < s_.size() && is_digit(s_[j])) ++j;
      if (j > exponent) i = j;  // "1e" is no number: the 'e' is left to refuse
    }
    return i;
  }

  bool may_follow_a_number(char c) const {
    return is_separator(c) || c == '+' || c == '-' || c == '.' || (path_data_ && is_path_command(c));
  }

  // The word from `start` to the next separator, quoted.
  std::string word(size_t start) const {
    size_t end = start;
    while (end < s_.size() && !is_separator(s_[end])) ++end;
    return quoted(s_.substr(start, end - start));
  }

  std::string_view s_;
  bool path_data_;
  size_t at_ = 0;
};

}  // namespace

std::vector<double> svg_numbers(std::string_view text) {
  Scanner scan(text, false);
  std::vector<double> out;
  while (scan.more()) out.push_back(scan.number());
  return out;
}

double svg_length(std::string_view text) {
  std::string_view number = text.ends_with("px") ? text.substr(0, text.size() - 2) : text;
  std::vector<double> v = svg_numbers(number);
  if (v.size() != 1) throw SvgNumberError(quoted(text) + " is not one length (a number, in px or without a unit)");
  return v[0];
}

void svg_path_commands(std::string_view d, const SvgPathVisitor& visit) {
  Scanner scan(d, true);
  char letter = '\0';
  std::vector<double> numbers;
  while (scan.more()) {
    if (char next = scan.command()) {
      if (letter) visit(letter, numbers);
      letter = next, numbers.clear();
      continue;
    }
    const double value = scan.number();
    if (!letter) throw SvgNumberError("path data must start with a command (M), not a number");
    numbers.push_back(value);
  }
  if (letter) visit(letter, numbers);
}

}  // namespace plumbago
