// Strokes drawn in SVG (Kalnins et al. 2002, §3, §4.5): see common/strokes/svg_strokes.hpp.
#include "common/strokes/svg_strokes.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <regex>
#include <sstream>
#include <stdexcept>

namespace plumbago {

namespace {

struct Element {
  std::string name;
  std::map<std::string, std::string> attributes;
  size_t index = 0;  // among the drawn elements, for messages
};

// The start tags of `svg` named svg, polyline or path, with their attributes.
std::vector<Element> elements(const std::string& svg) {
  static const std::regex tag(R"(<\s*(svg|polyline|path|g)\b([^>]*)>)");
  static const std::regex attribute(R"re(([\w:-]+)\s*=\s*("([^"]*)"|'([^']*)'))re");
  std::vector<Element> out;
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), tag); it != std::sregex_iterator(); ++it) {
    Element e{(*it)[1].str(), {}, 0};
    std::string attrs = (*it)[2].str();
    for (auto a = std::sregex_iterator(attrs.begin(), attrs.end(), attribute); a != std::sregex_iterator(); ++a)
      e.attributes[(*a)[1].str()] = (*a)[3].matched ? (*a)[3].str() : (*a)[4].str();
    out.push_back(std::move(e));
  }
  return out;
}

std::vector<double> numbers(const std::string& text) {
  static const std::regex number(R"([-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?)");
  std::vector<double> out;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), number); it != std::sregex_iterator(); ++it)
    out.push_back(std::stod(it->str()));
  return out;
}

class SvgReader {
 public:
  SvgReader(std::string source, int width, int height) : source_(std::move(source)), width_(width), height_(height) {}

  [[noreturn]] void fail(const Element& e, const std::string& what) const {
    std::ostringstream m;
    m << source_ << ": <" << e.name << "> #" << e.index << ": " << what;
    throw std::invalid_argument(m.str());
  }

  // The root's user space onto the window: viewBox, else width and height, else the window.
  void root(const Element& svg) {
    std::vector<double> box = numbers(svg.attributes.count("viewBox") ? svg.attributes.at("viewBox") : "");
    if (box.size() == 4)
      origin_ = {box[0], box[1]}, size_ = {box[2], box[3]};
    else if (svg.attributes.count("width") && svg.attributes.count("height"))
      size_ = {numbers(svg.attributes.at("width")).at(0), numbers(svg.attributes.at("height")).at(0)};
    if (!(size_.x > 0 && size_.y > 0)) fail(svg, "its viewBox or width and height must be positive");
  }

  glm::dvec2 window(glm::dvec2 user) const {
    glm::dvec2 unit = (user - origin_) / size_;
    return {unit.x * width_, (1.0 - unit.y) * height_};
  }

  // The polylines of one element in user units (a path's subpaths each).
  std::vector<std::vector<glm::dvec2>> polylines(const Element& e) const {
    if (e.attributes.count("transform")) fail(e, "has a transform: flatten it first");
    if (e.name == "polyline") {
      std::vector<double> v = numbers(e.attributes.count("points") ? e.attributes.at("points") : "");
      if (v.size() % 2) fail(e, "points: an odd count of numbers");
      std::vector<glm::dvec2> line;
      for (size_t k = 0; k + 1 < v.size(); k += 2) line.push_back({v[k], v[k + 1]});
      return {line};
    }
    return path(e, e.attributes.count("d") ? e.attributes.at("d") : "");
  }

  std::vector<std::vector<glm::dvec2>> path(const Element& e, const std::string& d) const {
    static const std::regex command(R"(([A-Za-z])([^A-Za-z]*))");
    std::vector<std::vector<glm::dvec2>> out;
    glm::dvec2 at(0), start(0);
    for (auto it = std::sregex_iterator(d.begin(), d.end(), command); it != std::sregex_iterator(); ++it) {
      char c = (*it)[1].str()[0];
      bool relative = std::islower(c);
      std::vector<double> v = numbers((*it)[2].str());
      char kind = char(std::toupper(c));
      size_t arity = kind == 'M' || kind == 'L' ? 2 : kind == 'Z' ? 0 : 1;
      if (kind != 'M' && kind != 'L' && kind != 'H' && kind != 'V' && kind != 'Z')
        fail(e, std::string("path command '") + c + "' is not a straight segment: flatten curves first");
      if (arity ? v.empty() || v.size() % arity : !v.empty())
        fail(e, std::string("path command '") + c + "': wrong count of numbers");
      if (kind == 'Z') {
        if (!out.empty()) out.back().push_back(start);
        at = start;
        continue;
      }
      for (size_t k = 0; k < v.size(); k += arity) {
        glm::dvec2 to = kind == 'H'   ? glm::dvec2(v[k] + (relative ? at.x : 0), at.y)
                        : kind == 'V' ? glm::dvec2(at.x, v[k] + (relative ? at.y : 0))
                                      : glm::dvec2(v[k], v[k + 1]) + (relative ? at : glm::dvec2(0));
        if (kind == 'M' && k == 0) out.push_back({}), start = to;
        if (out.empty()) fail(e, "a path must start with M");
        out.back().push_back(to);
        at = to;
      }
    }
    return out;
  }

 private:
  std::string source_;
  int width_, height_;
  glm::dvec2 origin_{0.0}, size_{0.0};

 public:
  void default_size() { size_ = {double(width_), double(height_)}; }
};

double stroke_width(const Element& e) {
  static const std::regex in_style(R"(stroke-width\s*:\s*([-+0-9.eE]+))");
  std::smatch m;
  if (e.attributes.count("style") && std::regex_search(e.attributes.at("style"), m, in_style)) return std::stod(m[1]);
  if (e.attributes.count("stroke-width")) {
    std::vector<double> v = numbers(e.attributes.at("stroke-width"));
    if (!v.empty()) return v[0];
  }
  return 0;
}

StrokeRole role_named(const SvgReader& r, const Element& e, const std::string& name) {
  const std::vector<std::string>& names = stroke_role_names();
  auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end()) r.fail(e, "data-role: expected one of decal, crease, silhouette, hatching");
  return StrokeRole(it - names.begin());
}

// The pressure of each point of one polyline of element e.
std::vector<double> pressures(const SvgReader& r, const Element& e, size_t points, double widest) {
  if (e.attributes.count("data-pressure")) {
    std::vector<double> v = numbers(e.attributes.at("data-pressure"));
    if (v.size() != 1 && v.size() != points) r.fail(e, "data-pressure: expected one number or one per point");
    for (double p : v)
      if (!(p >= 0 && p <= 1)) r.fail(e, "data-pressure: each must be in [0, 1]");
    return v.size() == 1 ? std::vector<double>(points, v[0]) : v;
  }
  double w = stroke_width(e);
  return std::vector<double>(points, w > 0 && widest > 0 ? std::min(1.0, w / widest) : 1.0);
}

}  // namespace

std::vector<DrawnStroke> svg_strokes(const std::string& svg, const std::string& source, int width, int height,
                                     const SvgStrokeDefaults& defaults) {
  SvgReader reader(source, width, height);
  std::vector<Element> all = elements(svg);
  reader.default_size();
  double widest = 0;
  size_t index = 0;
  for (Element& e : all) {
    e.index = index++;
    if (e.name == "svg") reader.root(e);
    if (e.name == "g" && e.attributes.count("transform")) reader.fail(e, "has a transform: flatten it first");
    if (e.name == "polyline" || e.name == "path") widest = std::max(widest, stroke_width(e));
  }
  std::vector<DrawnStroke> out;
  for (const Element& e : all) {
    if (e.name != "polyline" && e.name != "path") continue;
    for (const std::vector<glm::dvec2>& line : reader.polylines(e)) {
      if (line.size() < 2) reader.fail(e, "a stroke needs 2 points or more");
      DrawnStroke s;
      s.role = e.attributes.count("data-role") ? role_named(reader, e, e.attributes.at("data-role")) : defaults.role;
      std::vector<double> p = pressures(reader, e, line.size(), widest);
      for (size_t k = 0; k < line.size(); ++k) s.points.push_back({reader.window(line[k]), p[k]});
      if (s.role == StrokeRole::Decal || s.role == StrokeRole::Hatching)
        s.style_name = e.attributes.count("data-style") ? e.attributes.at("data-style") : defaults.style;
      if (s.role == StrokeRole::Hatching) {
        std::vector<double> g = numbers(e.attributes.count("data-group") ? e.attributes.at("data-group") : "");
        s.group = g.empty() ? defaults.group : int(g[0]);
        s.free = e.attributes.count("data-free") ? e.attributes.at("data-free") == "true" : defaults.free;
      }
      out.push_back(std::move(s));
    }
  }
  return out;
}

}  // namespace plumbago
