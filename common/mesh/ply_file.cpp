#include "common/mesh/ply_file.hpp"

#include "common/mesh/mesh_formats.hpp"

#include <algorithm>
#include <bit>
#include <cctype>
#include <cfloat>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <string_view>
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

// Sizes of the PLY scalar types, under both their old and their sized names.
const std::map<std::string, size_t>& type_sizes() {
  static const std::map<std::string, size_t> sizes = {{"char", 1},  {"uchar", 1},   {"int8", 1},   {"uint8", 1},
                                                      {"short", 2}, {"ushort", 2},  {"int16", 2},  {"uint16", 2},
                                                      {"int", 4},   {"uint", 4},    {"int32", 4},  {"uint32", 4},
                                                      {"float", 4}, {"float32", 4}, {"double", 8}, {"float64", 8}};
  return sizes;
}

bool is_integral_type(const std::string& t) {
  return type_sizes().count(t) && t != "float" && t != "float32" && t != "double" && t != "float64";
}

constexpr size_t kMaxHeaderBytes = 64 * 1024;

// "path: line N: what".
[[noreturn]] void header_error(const std::string& path, size_t line, const std::string& what) {
  throw MeshError(path + ": line " + std::to_string(line) + ": " + what);
}

// The first bytes of the file, at most kMaxHeaderBytes (where the header must end), and
// the file's size.
std::string read_header_bytes(std::istream& in, const std::string& path, uint64_t& file_size) {
  in.seekg(0, std::ios::end);
  std::streamoff end = in.tellg();
  if (end < 0) throw MeshError(path + ": cannot be read");
  file_size = uint64_t(end);
  in.seekg(0);
  std::string buf(size_t(std::min<uint64_t>(file_size, kMaxHeaderBytes)), '\0');
  in.read(buf.data(), std::streamsize(buf.size()));
  if (!in) throw MeshError(path + ": cannot be read");
  return buf;
}

// The words of the header line that starts at pos (after line lines_read), pos moved past
// it. Throws when no line ends within buf: the header has no 'end_header'.
std::vector<std::string> next_header_line(const std::string& buf, size_t& pos, size_t lines_read, uint64_t file_size,
                                          const std::string& path) {
  size_t nl = buf.find('\n', pos);
  if (nl == std::string::npos) {
    if (lines_read == 0) throw MeshError(path + ": not a PLY file (no 'ply' line)");
    if (file_size > kMaxHeaderBytes)
      header_error(path, lines_read, "no 'end_header' within the first " + std::to_string(kMaxHeaderBytes) + " bytes");
    header_error(path, lines_read, "the header has no 'end_header'");
  }
  std::string line = buf.substr(pos, nl - pos);
  pos = nl + 1;
  if (!line.empty() && line.back() == '\r') line.pop_back();
  std::istringstream ss(line);
  std::vector<std::string> w;
  for (std::string word; ss >> word;) w.push_back(word);
  return w;
}

// The header's lines in turn, into h: known keywords and types only, 'format' first and
// once, no element without properties, no name twice. Errors name the line read last.
class HeaderParser {
 public:
  explicit HeaderParser(const std::string& path) : path_(path) {}

  // Line h.lines + 1, split into words; false once it is 'end_header'.
  bool read_line(const std::vector<std::string>& w) {
    ++h_.lines;
    if (h_.lines == 1) {
      if (w.size() != 1 || w[0] != "ply") throw MeshError(path_ + ": not a PLY file (the first line is not 'ply')");
      return true;
    }
    if (w.empty()) return true;
    const std::string& key = w[0];
    if (key == "comment" || key == "obj_info") return true;
    if (key == "format") {
      format(w);
    } else if (key == "element") {
      element(w);
    } else if (key == "property") {
      property(w);
    } else if (key == "end_header") {
      if (w.size() != 1) fail("malformed 'end_header' line");
      check_last_element();
      return false;
    } else {
      fail("unknown header keyword '" + key + "' (or no 'end_header' before it)");
    }
    return true;
  }

  const PlyHeader& header() const { return h_; }

  // After 'end_header': a format, a vertex element and a face (or tristrips) element.
  void check_complete() const {
    if (!have_format_) fail("no 'format' line");
    if (!has_element("vertex")) fail("no 'element vertex'");
    if (!has_element("face") && !has_element("tristrips")) fail("no 'element face' (nor 'element tristrips')");
  }

 private:
  [[noreturn]] void fail(const std::string& what) const { header_error(path_, h_.lines, what); }

  bool has_element(std::string_view name) const {
    return std::any_of(h_.elements.begin(), h_.elements.end(), [&](const PlyElement& e) { return e.name == name; });
  }

  void check_last_element() const {
    if (!h_.elements.empty() && h_.elements.back().properties.empty())
      header_error(path_, element_lines_.back(), "element '" + h_.elements.back().name + "' has no properties");
  }

  // format ascii|binary_little_endian|binary_big_endian 1.0
  void format(const std::vector<std::string>& w) {
    if (have_format_) fail("a second 'format' line");
    if (!h_.elements.empty()) fail("'format' after an 'element'");
    if (w.size() != 3) fail("malformed 'format' line (format ascii|binary_little_endian|binary_big_endian 1.0)");
    if (w[1] != "ascii" && w[1] != "binary_little_endian" && w[1] != "binary_big_endian")
      fail("unknown PLY format '" + w[1] + "'");
    if (w[2] != "1.0") fail("unsupported PLY version '" + w[2] + "' (1.0 only)");
    h_.format = w[1];
    have_format_ = true;
  }

  // element NAME COUNT
  void element(const std::vector<std::string>& w) {
    if (!have_format_) fail("'element' before the 'format' line");
    check_last_element();
    if (w.size() != 3) fail("malformed 'element' line (element NAME COUNT)");
    const std::string& c = w[2];
    if (c[0] == '-') fail("element '" + w[1] + "' has a negative count " + c);
    uint64_t count = 0;
    auto [ptr, ec] = std::from_chars(c.data(), c.data() + c.size(), count);
    if (ec == std::errc::result_out_of_range) fail("element '" + w[1] + "' count " + c + " is out of range");
    if (ec != std::errc() || ptr != c.data() + c.size())
      fail("element '" + w[1] + "' count '" + c + "' is not a count");
    if (has_element(w[1])) fail("a second element '" + w[1] + "'");
    h_.elements.push_back({w[1], size_t(count), {}});
    element_lines_.push_back(h_.lines);
  }

  // property TYPE NAME, or property list COUNT_TYPE ITEM_TYPE NAME
  void property(const std::vector<std::string>& w) {
    if (h_.elements.empty()) fail("'property' before any 'element'");
    PlyProperty p;
    if (w.size() >= 2 && w[1] == "list") {
      if (w.size() != 5) fail("malformed list property (property list COUNT_TYPE ITEM_TYPE NAME)");
      if (!is_integral_type(w[2])) fail("list count type '" + w[2] + "' is not an integer type");
      if (!type_sizes().count(w[3])) fail("unknown property type '" + w[3] + "'");
      p = {w[4], w[3], w[2]};
    } else {
      if (w.size() != 3) fail("malformed property (property TYPE NAME)");
      if (!type_sizes().count(w[1])) fail("unknown property type '" + w[1] + "'");
      p = {w[2], w[1], ""};
    }
    for (const PlyProperty& q : h_.elements.back().properties)
      if (q.name == p.name) fail("a second property '" + p.name + "' in element '" + h_.elements.back().name + "'");
    h_.elements.back().properties.push_back(p);
  }

  const std::string& path_;
  PlyHeader h_;
  std::vector<size_t> element_lines_;  // the line of each element's 'element'
  bool have_format_ = false;
};

// Every element's count against the body bytes after the header (binary: its minimum
// record size; ASCII: one value per property, a value taking at least two bytes with its
// separator), before anything is allocated.
void check_counts_fit(const PlyHeader& h, uint64_t body, const std::string& path) {
  uint64_t left = body;
  const bool ascii = h.format == "ascii";
  for (const PlyElement& e : h.elements) {
    uint64_t least = 0;  // bytes (binary) or values (ASCII) of the smallest record
    for (const PlyProperty& p : e.properties)
      least += ascii ? 1 : type_sizes().at(p.count_type.empty() ? p.type : p.count_type);
    uint64_t room = ascii ? (left + 1) / 2 : left;  // ASCII: values of at least 1 byte + 1 separator
    if (e.count > room / least) {
      std::string after = left == body ? " after the header" : " left after the header and the elements before it";
      if (ascii)
        throw MeshError(path + ": the file ends early: element " + e.name + " claims " + std::to_string(e.count) +
                        " records of at least " + std::to_string(least) + " values, the " + std::to_string(left) +
                        " bytes" + after + " hold at most " + std::to_string(room) + " values");
      throw MeshError(path + ": element " + e.name + " claims " + std::to_string(e.count) + " records of at least " +
                      std::to_string(least) + " bytes, the file has " + std::to_string(left) + " bytes" + after);
    }
    left -= ascii ? std::min<uint64_t>(left, 2 * e.count * least) : e.count * least;
  }
}

// The mesh the counts make, against the memory budget (a face is at least a triangle).
void check_header_budget(const PlyHeader& h, const std::string& path) {
  auto count_of = [&](const char* name) {
    for (const PlyElement& e : h.elements)
      if (e.name == name) return double(e.count);
    return 0.0;
  };
  mesh_text::check_mesh_budget(path, 0, count_of("vertex"), count_of("face"));
}

// The whole header checked before anything else reads the file (OpenMesh's PLY reader
// crashes on a 'property' before any 'element', loops forever without 'end_header' or on
// an element without properties, and trusts counts of billions): known keywords and
// types only, 'end_header' within 64 KiB, and every element's count small enough for the
// bytes after the header to hold (check_counts_fit). Leaves `in` at the first byte after
// the header.
PlyHeader read_header(std::istream& in, const std::string& path) {
  uint64_t file_size = 0;
  const std::string buf = read_header_bytes(in, path, file_size);
  HeaderParser parser(path);
  size_t pos = 0;
  bool more = true;
  while (more) more = parser.read_line(next_header_line(buf, pos, parser.header().lines, file_size, path));
  parser.check_complete();
  const PlyHeader& h = parser.header();
  check_counts_fit(h, file_size - pos, path);
  check_header_budget(h, path);
  in.clear();
  in.seekg(std::streamoff(pos));
  return h;
}

// The body's values one at a time, ASCII or binary, counting ASCII lines for messages.
class PlyValues {
 public:
  PlyValues(std::istream& in, const PlyHeader& h, const std::string& path)
      : in_(in),
        path_(path),
        ascii_(h.format == "ascii"),
        big_endian_(h.format == "binary_big_endian"),
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
    const auto& sizes = type_sizes();
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

// A value for a message: integral ones as integers ("7", not "7.000000"), NaN as "nan".
std::string number_text(double v) {
  if (std::isnan(v)) return "nan";
  if (v == std::floor(v) && std::abs(v) < 9e15) return std::to_string(int64_t(v));
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

// Triangle k of a strip is (s_k, s_k+1, s_k+2), with odd k flipped to keep the winding.
void add_strip(const std::vector<unsigned>& strip, MeshFile& m) {
  for (size_t k = 0; k + 2 < strip.size(); ++k) {
    glm::uvec3 t(strip[k], strip[k + 1], strip[k + 2]);
    if (k % 2) std::swap(t[0], t[1]);
    if (t[0] != t[1] && t[1] != t[2] && t[0] != t[2]) m.triangles.push_back(t);
  }
}

// Instance i of element e.
void read_instance(PlyValues& values, const PlyElement& e, size_t i, MeshFile& m) {
  auto what = [&] { return e.name + " " + std::to_string(i); };
  for (const PlyProperty& p : e.properties) {
    if (p.count_type.empty()) {
      double v = values.next(p.type);
      if (e.name != "vertex" || (p.name != "x" && p.name != "y" && p.name != "z")) continue;
      if (!std::isfinite(v)) throw MeshError(values.where() + ": " + what() + " has a NaN or infinite coordinate");
      if (std::abs(v) > double(FLT_MAX))
        throw MeshError(values.where() + ": " + what() + " has coordinate " + number_text(v) + ", beyond float range");
      m.positions.back()[p.name[0] - 'x'] = v;
      continue;
    }
    double count = values.next(p.count_type);
    if (!(count >= 0))
      throw MeshError(values.where() + ": " + what() + " has list length " + number_text(count) + ", negative or NaN");
    if (count != std::floor(count) || count > 4294967295.0)
      throw MeshError(values.where() + ": " + what() + " has list length " + number_text(count) + ", not a count");
    size_t n = size_t(count);
    bool indices =
        (e.name == "face" || e.name == "tristrips") && (p.name == "vertex_indices" || p.name == "vertex_index");
    std::vector<unsigned> corners;
    for (size_t j = 0; j < n; ++j) {
      double index = values.next(p.type);
      if (!indices) continue;
      if (e.name == "tristrips" && index == -1) {
        add_strip(corners, m);
        corners.clear();
      } else if (!(index >= 0 && index < double(m.positions.size())) || index != std::floor(index)) {
        // Checked before the conversion to unsigned: NaN, negative, fractional or too
        // large values would make it undefined.
        throw MeshError(values.where() + ": " + what() + " has vertex index " + number_text(index) +
                        (std::isfinite(index) && index == std::floor(index) ? ", out of range (" : ", not an index (") +
                        std::to_string(m.positions.size()) + " vertices)");
      } else {
        corners.push_back(unsigned(index));
      }
    }
    if (e.name == "tristrips") add_strip(corners, m);
    if (e.name == "face") mesh_text::add_fan(corners, m.triangles);
  }
}

}  // namespace

MeshFile read_ply(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  PlyHeader h = read_header(in, path);
  PlyValues values(in, h, path);
  MeshFile m;
  m.name = path;
  for (const PlyElement& e : h.elements) {
    for (size_t i = 0; i < e.count; ++i) {
      if (e.name == "vertex") m.positions.emplace_back(0.0);
      read_instance(values, e, i, m);
    }
  }
  return m;
}

}  // namespace plumbago
