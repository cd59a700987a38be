#include "common/strokes/stroke_style.hpp"
#include "common/scene/json_position.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "common/util/input_file.hpp"

namespace plumbago {

namespace {

using nlohmann::json;
namespace fs = std::filesystem;

std::string number_text(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

std::string key_path(const char* name) { return std::string("/") + name; }

// Names the source and the JSON pointer in every refusal.
struct Refuser {
  std::string source;
  [[noreturn]] void fail(const std::string& path, const std::string& what) const {
    throw StrokeStyleError(source + ": " + (path.empty() ? "/" : path) + ": " + what);
  }
  void check_range(const std::string& path, double x, double lo, double hi) const {
    if (!std::isfinite(x)) fail(path, "must be a finite number, got " + number_text(x));
    if (x < lo || x > hi)
      fail(path, "must be in [" + number_text(lo) + ", " + number_text(hi) + "], got " + number_text(x));
  }
};

// Kalnins et al.'s (2002, §4.3, App. A) offset list: each entry in range, t not decreasing, at least one entry.
void check_offsets(const OffsetExample& e, const Refuser& r) {
  r.check_range("/offsets/length_px", e.length_px, 1.0, 1e5);
  if (e.offsets.empty()) r.fail("/offsets/points", "expected at least one offset");
  for (size_t i = 0; i < e.offsets.size(); ++i) {
    std::string p = "/offsets/points/" + std::to_string(i);
    const StrokeOffset& o = e.offsets[i];
    r.check_range(p + "/0", o.t, 0.0, 1.0);
    r.check_range(p + "/1", o.displacement_px, -1000.0, 1000.0);
    r.check_range(p + "/2", o.pressure, 0.0, 1.0);
    if (i > 0 && o.t < e.offsets[i - 1].t)
      r.fail(p + "/0", "t must not decrease (" + number_text(o.t) + " after " + number_text(e.offsets[i - 1].t) + ")");
  }
}

struct Defaults {
  void real(float& f, const char*, double def, double, double, const char*) { f = float(def); }
  void boolean(bool& b, const char*, bool def, const char*) { b = def; }
  template <class E>
  void choice(E& e, const char*, E def, const std::vector<std::string>&, const char*) {
    e = def;
  }
};

// The specs of StrokeStyle::visit with the JSON names as keys.
struct SpecList {
  std::vector<ParamSpec> specs;
  void real(float&, const char* name, double def, double lo, double hi, const char* doc) {
    specs.push_back({name, ParamType::Real, def, lo, hi, {}, doc});
  }
  void boolean(bool&, const char* name, bool def, const char* doc) {
    specs.push_back({name, ParamType::Boolean, double(def), 0, 1, {}, doc});
  }
  template <class E>
  void choice(E&, const char* name, E def, const std::vector<std::string>& names, const char* doc) {
    specs.push_back({name, ParamType::Choice, double(int(def)), 0, double(names.size()) - 1, names, doc});
  }
};

// Checks the values of a style built in code against their ranges. The bounds are
// rounded to float as the fields are, so that a value read from JSON always passes.
struct Validator {
  const Refuser& r;
  void real(float& f, const char* name, double, double lo, double hi, const char*) {
    r.check_range(key_path(name), f, double(float(lo)), double(float(hi)));
  }
  void boolean(bool&, const char*, bool, const char*) {}
  template <class E>
  void choice(E& e, const char* name, E, const std::vector<std::string>& names, const char*) {
    if (int(e) < 0 || size_t(int(e)) >= names.size()) r.fail(key_path(name), "not one of " + joined(names));
  }
};

double read_number(const json& j, const std::string& path, double lo, double hi, const Refuser& r) {
  if (!j.is_number()) r.fail(path, std::string("expected a number, got ") + j.type_name());
  double x = j.get<double>();
  r.check_range(path, x, lo, hi);
  return x;
}

// Reads each scalar of StrokeStyle::visit from the object, defaults for those left out.
class Reader {
 public:
  Reader(const json& j, const Refuser& r) : j_(j), r_(r) {}

  void real(float& f, const char* name, double def, double lo, double hi, const char*) {
    f = float(read(name) ? read_number(j_[name], key_path(name), lo, hi, r_) : def);
  }
  void boolean(bool& b, const char* name, bool def, const char*) {
    b = def;
    if (!read(name)) return;
    if (!j_[name].is_boolean())
      r_.fail(key_path(name), std::string("expected true or false, got ") + j_[name].type_name());
    b = j_[name].get<bool>();
  }
  template <class E>
  void choice(E& e, const char* name, E def, const std::vector<std::string>& names, const char*) {
    e = def;
    if (!read(name)) return;
    const json& v = j_[name];
    auto it = v.is_string() ? std::find(names.begin(), names.end(), v.get<std::string>()) : names.end();
    if (it == names.end()) r_.fail(key_path(name), "expected one of " + joined(names) + ", got " + v.dump());
    e = E(int(it - names.begin()));
  }

  // The scalar names visited so far.
  const std::vector<std::string>& names() const { return names_; }

 private:
  bool read(const char* name) {
    names_.push_back(name);
    return j_.contains(name);
  }
  const json& j_;
  const Refuser& r_;
  std::vector<std::string> names_;
};

StrokeOffset read_offset(const json& j, const std::string& path, const Refuser& r) {
  if (!j.is_array() || j.size() != 4) r.fail(path, "expected [t, displacement_px, pressure, break]");
  StrokeOffset o;
  o.t = read_number(j[0], path + "/0", -INFINITY, INFINITY, r);
  o.displacement_px = read_number(j[1], path + "/1", -INFINITY, INFINITY, r);
  o.pressure = read_number(j[2], path + "/2", -INFINITY, INFINITY, r);
  if (!j[3].is_boolean()) r.fail(path + "/3", std::string("expected true or false, got ") + j[3].type_name());
  o.pen_up = j[3].get<bool>();
  return o;
}

OffsetExample read_offsets(const json& j, const Refuser& r) {
  if (!j.is_object()) r.fail("/offsets", "expected {\"length_px\": ..., \"points\": [...]}");
  for (const auto& [key, value] : j.items())
    if (key != "length_px" && key != "points") r.fail("/offsets/" + key, "unknown key (known here: length_px, points)");
  if (!j.contains("length_px")) r.fail("/offsets/length_px", "missing (the example's length when drawn, px)");
  if (!j.contains("points") || !j["points"].is_array()) r.fail("/offsets/points", "expected an array of offsets");
  OffsetExample e;
  e.length_px = read_number(j["length_px"], "/offsets/length_px", -INFINITY, INFINITY, r);
  for (size_t i = 0; i < j["points"].size(); ++i)
    e.offsets.push_back(read_offset(j["points"][i], "/offsets/points/" + std::to_string(i), r));
  check_offsets(e, r);
  return e;
}

void refuse_unknown_keys(const json& j, const std::vector<std::string>& scalars, const Refuser& r) {
  std::vector<std::string> known = scalars;
  known.insert(known.end(), {"description", "offsets"});
  for (const auto& [key, value] : j.items())
    if (std::find(known.begin(), known.end(), key) == known.end())
      r.fail("/" + key, "unknown key (known: " + joined(known) + ")");
}

StrokeStyle read_style(const json& j, const Refuser& r) {
  if (!j.is_object()) r.fail("", "expected an object");
  StrokeStyle s;
  Reader reader(j, r);
  s.visit(reader);
  refuse_unknown_keys(j, reader.names(), r);
  if (j.contains("description")) {
    if (!j["description"].is_string()) r.fail("/description", "expected a string");
    s.description = j["description"].get<std::string>();
  }
  if (j.contains("offsets")) s.offsets = read_offsets(j["offsets"], r);
  return s;
}

}  // namespace

bool is_stroke_style_preset(const std::string& s) {
  bool json_suffix = s.size() >= 5 && s.compare(s.size() - 5, 5, ".json") == 0;
  return s.find('/') == std::string::npos && !json_suffix;
}

StrokeStyle default_stroke_style() {
  StrokeStyle s;
  Defaults d;
  s.visit(d);
  return s;
}

std::vector<ParamSpec> stroke_style_specs() {
  StrokeStyle s;
  SpecList list;
  s.visit(list);
  return list.specs;
}

void validate_stroke_style(const StrokeStyle& style, const std::string& source) {
  Refuser r{source};
  Validator v{r};
  StrokeStyle copy = style;  // visit takes its fields by reference
  copy.visit(v);
  if (style.offsets) check_offsets(*style.offsets, r);
}

StrokeStyle parse_stroke_style(const std::string& text, const std::string& source) {
  return read_style(parse_json_text_as<StrokeStyleError>(text, source), Refuser{source});
}

std::string stroke_style_dir() {
  const char* dir = std::getenv("PLUMBAGO_STYLE_DIR");
  return dir && *dir ? std::string(dir) : std::string(PLUMBAGO_SOURCE_DIR "/styles/strokes");
}

std::vector<std::string> stroke_style_names() {
  std::vector<std::string> names;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(stroke_style_dir(), ec))
    if (entry.is_regular_file() && entry.path().extension() == ".json") names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

StrokeStyle load_stroke_style(const std::string& name_or_path) {
  std::string path = name_or_path;
  if (is_stroke_style_preset(name_or_path)) {
    path = (fs::path(stroke_style_dir()) / (name_or_path + ".json")).string();
    std::error_code error;  // a name too long for a file name, say: no such preset either
    if (!fs::is_regular_file(path, error))
      throw StrokeStyleError("stroke style '" + name_or_path + "': no such preset in " + stroke_style_dir() +
                             " (known: " + joined(stroke_style_names()) + ")");
  }
  return parse_stroke_style(read_input_file_as<StrokeStyleError>(path, "stroke style file"), path);
}

StrokeStyle load_stroke_style_from(const std::string& name_or_path, const std::string& base_dir) {
  bool relative_file = !is_stroke_style_preset(name_or_path) && !fs::path(name_or_path).is_absolute();
  return load_stroke_style(relative_file ? (fs::path(base_dir) / name_or_path).string() : name_or_path);
}

}  // namespace plumbago
