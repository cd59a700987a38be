// The numbers of an SVG drawing, read by a scanner in one pass: linear in time and memory,
// no recursion, no regular expressions (std::regex recursed once a character per
// character of a long attribute, and overflowed the stack). The grammar is SVG 1.1's
// (§4.2 "number", §8.3.9 "The grammar for path data"):
//   number: [+-]? (digits ("." digits?)? | "." digits) ([eE] [+-]? digits)?
// Numbers are separated by white space and/or commas, or by nothing where the next one's
// sign or "." ends the last ("1-2" and "1.5.5" are two numbers each). A word that is no
// number ("nan", "inf", "1e", "x1") and a number beyond double range ("1e999") are
// refused, never dropped.
#pragma once

#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace plumbago {

// what(): the fault, e.g. "'x1' is not a number" (the caller names the file and attribute).
struct SvgNumberError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The numbers of a list: `points`, `viewBox`, `data-pressure`.
std::vector<double> svg_numbers(std::string_view text);

// A length (`width`, `height`, `stroke-width`): one number, in px or without a unit.
double svg_length(std::string_view text);

// Called for each command of path data: its letter as written (M m L l H h V v Z z, or a
// curve's C S Q T A, which the caller refuses) and the numbers that follow it (a buffer
// reused from command to command: a path holds no more than its points).
using SvgPathVisitor = std::function<void(char letter, const std::vector<double>& numbers)>;

// Visits the commands of path data (`d`) in order. Refuses numbers before the first command.
void svg_path_commands(std::string_view d, const SvgPathVisitor& visit);

}  // namespace plumbago
