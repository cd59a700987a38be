#include "common/ply_strips.hpp"

#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

namespace plumbago {

namespace {

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
};

size_t type_size(const std::string& t, const std::string& path) {
  static const std::map<std::string, size_t> sizes = {
      {"char", 1}, {"uchar", 1}, {"int8", 1}, {"uint8", 1}, {"short", 2}, {"ushort", 2}, {"int16", 2},
      {"uint16", 2}, {"int", 4}, {"uint", 4}, {"int32", 4}, {"uint32", 4}, {"float", 4}, {"float32", 4},
      {"double", 8}, {"float64", 8}};
  auto it = sizes.find(t);
  if (it == sizes.end()) throw MeshError(path + ": unknown PLY property type '" + t + "'");
  return it->second;
}

// Reads one little-endian value of PLY type `t` as a double.
double read_value(std::istream& in, const std::string& t, const std::string& path) {
  unsigned char b[8] = {};
  size_t n = type_size(t, path);
  if (!in.read(reinterpret_cast<char*>(b), std::streamsize(n))) throw MeshError(path + ": the file ends early");
  if (t == "float" || t == "float32") { float f; std::memcpy(&f, b, 4); return f; }
  if (t == "double" || t == "float64") { double d; std::memcpy(&d, b, 8); return d; }
  bool is_signed = t[0] != 'u';
  int64_t v = 0;
  for (size_t i = 0; i < n; ++i) v |= int64_t(b[i]) << (8 * i);
  if (is_signed && (b[n - 1] & 0x80)) v -= int64_t(1) << (8 * n);
  return double(v);
}

PlyHeader read_header(std::istream& in, const std::string& path) {
  PlyHeader h;
  std::string line;
  if (!std::getline(in, line) || line.rfind("ply", 0) != 0) throw MeshError(path + ": not a PLY file");
  while (std::getline(in, line) && line.rfind("end_header", 0) != 0) {
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
  return h;
}

void read_vertices(std::istream& in, const PlyElement& e, Mesh& m, const std::string& path) {
  m.positions.resize(e.count);
  for (size_t i = 0; i < e.count; ++i)
    for (const PlyProperty& p : e.properties) {
      double v = read_value(in, p.type, path);
      if (p.name == "x" || p.name == "y" || p.name == "z") m.positions[i][p.name[0] - 'x'] = float(v);
    }
}

// Triangle k of a strip is (s_k, s_k+1, s_k+2), with odd k flipped to keep the winding.
void add_strip(const std::vector<long>& strip, Mesh& m) {
  for (size_t k = 0; k + 2 < strip.size(); ++k) {
    glm::uvec3 t(unsigned(strip[k]), unsigned(strip[k + 1]), unsigned(strip[k + 2]));
    if (k % 2) std::swap(t[0], t[1]);
    if (t[0] != t[1] && t[1] != t[2] && t[0] != t[2]) m.triangles.push_back(t);
  }
}

void read_strips(std::istream& in, const PlyElement& e, Mesh& m, const std::string& path) {
  for (size_t i = 0; i < e.count; ++i) {
    const PlyProperty& p = e.properties.at(0);
    size_t n = size_t(read_value(in, p.count_type, path));
    std::vector<long> strip;
    for (size_t j = 0; j < n; ++j) {
      long index = long(read_value(in, p.type, path));
      if (index >= 0 && size_t(index) >= m.positions.size())
        throw MeshError(path + ": strip index " + std::to_string(index) + " is out of range");
      if (index < 0) {
        add_strip(strip, m);
        strip.clear();
      } else {
        strip.push_back(index);
      }
    }
    add_strip(strip, m);
  }
}

}  // namespace

bool ply_has_triangle_strips(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  PlyHeader h = read_header(in, path);
  for (const auto& e : h.elements)
    if (e.name == "tristrips") return true;
  return false;
}

Mesh read_ply_triangle_strips(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  PlyHeader h = read_header(in, path);
  if (h.format != "binary_little_endian")
    throw MeshError(path + ": triangle strips are read from binary_little_endian PLY only, not " + h.format);
  Mesh m;
  m.name = path;
  for (const PlyElement& e : h.elements) {
    if (e.name == "vertex") read_vertices(in, e, m, path);
    else if (e.name == "tristrips" && !e.properties.empty() && !e.properties[0].count_type.empty()) read_strips(in, e, m, path);
    else throw MeshError(path + ": PLY element '" + e.name + "' is not supported next to triangle strips");
  }
  return m;
}

}  // namespace plumbago
