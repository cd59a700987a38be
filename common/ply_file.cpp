#include "common/ply_file.hpp"

#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

namespace plumbago {

namespace {

static_assert(std::endian::native == std::endian::little, "binary PLY values are decoded as little-endian");

struct PlyProperty {
  std::string name, type, count_type;  // count_type set for lists
};

struct PlyElement {
  std::string name;
  size_t count = 0;
  std::vector<PlyProperty> properties;
};

struct PlyHeader {
  std::string format;
  std::vector<PlyElement> elements;
  size_t lines = 0;
};

PlyHeader read_header(std::istream& in, const std::string& path) {
  PlyHeader h;
  std::string line;
  if (!std::getline(in, line) || line.rfind("ply", 0) != 0) throw MeshError(path + ": not a PLY file");
  h.lines = 1;
  while (std::getline(in, line) && ++h.lines && line.rfind("end_header", 0) != 0) {
    std::istringstream ss(line);
    std::string word;
    ss >> word;
    if (word == "format") ss >> h.format;
    if (word == "element") h.elements.push_back({}), ss >> h.elements.back().name >> h.elements.back().count;
    if (word == "property" && !h.elements.empty()) {
      PlyProperty p;
      ss >> p.type;
      if (p.type == "list") ss >> p.count_type >> p.type;
      ss >> p.name;
      h.elements.back().properties.push_back(p);
    }
  }
  if (h.format != "ascii" && h.format != "binary_little_endian" && h.format != "binary_big_endian")
    throw MeshError(path + ": unknown PLY format '" + h.format + "'");
  return h;
}

// The body's values one at a time, ASCII or binary, counting ASCII lines for messages.
class PlyValues {
 public:
  PlyValues(std::istream& in, const PlyHeader& h, const std::string& path)
      : in_(in), path_(path), ascii_(h.format == "ascii"), big_endian_(h.format == "binary_big_endian"),
        line_(h.lines + 1) {}

  double next(const std::string& type) { return ascii_ ? next_word() : next_binary(type); }

  // "file:line" for ASCII, "file" for binary.
  std::string where() const { return ascii_ ? path_ + ":" + std::to_string(line_) : path_; }

 private:
  double next_word() {
    int c;
    while ((c = in_.peek()) != EOF && std::isspace(c)) line_ += in_.get() == '\n';
    std::string word;
    while ((c = in_.peek()) != EOF && !std::isspace(c)) word += char(in_.get());
    if (word.empty()) throw MeshError(where() + ": the file ends early");
    char* end = nullptr;
    double v = std::strtod(word.c_str(), &end);
    if (*end != '\0') throw MeshError(where() + ": '" + word + "' is not a number");
    return v;
  }

  double next_binary(const std::string& t) {
    static const std::map<std::string, size_t> sizes = {
        {"char", 1}, {"uchar", 1}, {"int8", 1}, {"uint8", 1}, {"short", 2}, {"ushort", 2}, {"int16", 2},
        {"uint16", 2}, {"int", 4}, {"uint", 4}, {"int32", 4}, {"uint32", 4}, {"float", 4}, {"float32", 4},
        {"double", 8}, {"float64", 8}};
    auto it = sizes.find(t);
    if (it == sizes.end()) throw MeshError(path_ + ": unknown PLY property type '" + t + "'");
    size_t n = it->second;
    unsigned char b[8] = {};
    if (!in_.read(reinterpret_cast<char*>(b), std::streamsize(n))) throw MeshError(path_ + ": the file ends early");
    if (big_endian_) std::reverse(b, b + n);
    if (t == "float" || t == "float32") {
      float f;
      std::memcpy(&f, b, 4);
      return f;
    }
    if (t == "double" || t == "float64") {
      double d;
      std::memcpy(&d, b, 8);
      return d;
    }
    int64_t v = 0;
    for (size_t i = 0; i < n; ++i) v |= int64_t(b[i]) << (8 * i);
    if (t[0] != 'u' && (b[n - 1] & 0x80)) v -= int64_t(1) << (8 * n);
    return double(v);
  }

  std::istream& in_;
  std::string path_;
  bool ascii_, big_endian_;
  size_t line_;
};

// Triangle k of a strip is (s_k, s_k+1, s_k+2), with odd k flipped to keep the winding.
void add_strip(const std::vector<unsigned>& strip, Mesh& m) {
  for (size_t k = 0; k + 2 < strip.size(); ++k) {
    glm::uvec3 t(strip[k], strip[k + 1], strip[k + 2]);
    if (k % 2) std::swap(t[0], t[1]);
    if (t[0] != t[1] && t[1] != t[2] && t[0] != t[2]) m.triangles.push_back(t);
  }
}

void add_fan(const std::vector<unsigned>& polygon, Mesh& m) {
  for (size_t k = 1; k + 1 < polygon.size(); ++k) m.triangles.push_back({polygon[0], polygon[k], polygon[k + 1]});
}

// Instance i of element e.
void read_instance(PlyValues& values, const PlyElement& e, size_t i, Mesh& m) {
  auto what = [&] { return e.name + " " + std::to_string(i); };
  for (const PlyProperty& p : e.properties) {
    if (p.count_type.empty()) {
      double v = values.next(p.type);
      if (e.name != "vertex" || (p.name != "x" && p.name != "y" && p.name != "z")) continue;
      if (!std::isfinite(v)) throw MeshError(values.where() + ": " + what() + " has a NaN or infinite coordinate");
      m.positions.back()[p.name[0] - 'x'] = float(v);
      continue;
    }
    double count = values.next(p.count_type);
    if (!(count >= 0)) throw MeshError(values.where() + ": " + what() + " has a negative list length");
    size_t n = size_t(count);
    bool indices = (e.name == "face" || e.name == "tristrips") && (p.name == "vertex_indices" || p.name == "vertex_index");
    std::vector<unsigned> corners;
    for (size_t j = 0; j < n; ++j) {
      double index = values.next(p.type);
      if (!indices) continue;
      if (e.name == "tristrips" && index == -1) {
        add_strip(corners, m);
        corners.clear();
      } else if (index < 0 || index >= double(m.positions.size())) {
        throw MeshError(values.where() + ": " + what() + " has vertex index " + std::to_string(int64_t(index)) +
                        ", out of range (" + std::to_string(m.positions.size()) + " vertices)");
      } else {
        corners.push_back(unsigned(index));
      }
    }
    if (e.name == "tristrips") add_strip(corners, m);
    if (e.name == "face") add_fan(corners, m);
  }
}

}  // namespace

Mesh read_ply(const std::string& path, bool& has_strips) {
  std::ifstream in(path, std::ios::binary);
  PlyHeader h = read_header(in, path);
  PlyValues values(in, h, path);
  Mesh m;
  m.name = path;
  has_strips = false;
  for (const PlyElement& e : h.elements) {
    has_strips |= e.name == "tristrips";
    for (size_t i = 0; i < e.count; ++i) {
      if (e.name == "vertex") m.positions.emplace_back(0.0f);
      read_instance(values, e, i, m);
    }
  }
  return m;
}

}  // namespace plumbago
