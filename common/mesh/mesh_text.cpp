// Helpers the project's own mesh readers share (common/mesh/mesh_formats.hpp).
#include <cmath>
#include <filesystem>
#include <sstream>

#include "common/mesh/mesh_formats.hpp"
#include "common/util/memory_budget.hpp"

namespace plumbago::mesh_text {

bool is_finite_float(const std::string& word, double* value) {
  char* end = nullptr;
  double v = std::strtod(word.c_str(), &end);
  // The whole word, not up to a NUL byte within it: "\0\0032" is not a number.
  if (word.empty() || end != word.c_str() + word.size() || !std::isfinite(float(v))) return false;
  if (value) *value = v;
  return true;
}

std::vector<std::string> words(const std::string& line, bool comments) {
  std::istringstream ss(comments ? line.substr(0, line.find('#')) : line);
  std::vector<std::string> w;
  for (std::string word; ss >> word;) w.push_back(word);
  return w;
}

uint64_t file_size(const std::string& path) {
  std::error_code error;
  uint64_t size = std::filesystem::file_size(path, error);
  if (error) throw MeshError(path + ": cannot be read (" + error.message() + ")");
  return size;
}

void check_mesh_budget(const std::string& path, size_t line, double vertices, double triangles) {
  std::string what = "a mesh of " + std::to_string(uint64_t(vertices)) + " vertices and " +
                     std::to_string(uint64_t(triangles)) + " triangles";
  if (std::string why = over_memory_budget(what, mesh_bytes(vertices, triangles)); !why.empty())
    throw MeshError(path + (line ? ":" + std::to_string(line) : std::string()) + ": " + why);
}

void add_fan(const std::vector<unsigned>& polygon, std::vector<glm::uvec3>& triangles) {
  for (size_t k = 1; k + 1 < polygon.size(); ++k) triangles.push_back({polygon[0], polygon[k], polygon[k + 1]});
}

}  // namespace plumbago::mesh_text
