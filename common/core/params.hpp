// One source of truth for every parameter (docs/design.md, principle 1).
//
// Each stage declares one struct with a `visit` template listing its fields once:
// key, default, valid range and a one-line doc. Everything else derives from it:
//  - `param_specs()` (plumbago params, the scene parser, --set, experiments),
//  - `ParamSet::get<Struct>()` (the reference passes and the GPU passes),
//  - the GLSL struct declaration and its uniform values (gpu/gl/program.cpp).
//
//   struct EdgeDetectParams {
//     static constexpr const char* stage = "edge";
//     float depth_scale;
//     template <class V> void visit(V& v) {
//       v.real(depth_scale, "depth_scale", 8.0, 0.0, 1000.0, "doc");
//     }
//   };
#pragma once

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace plumbago {

enum class ParamType { Real, Integer, Boolean, Choice };

struct ParamSpec {
  std::string key;  // "stage.name"
  ParamType type;
  double default_value;
  double min, max;                   // valid range (inclusive); Choice: 0..n-1
  std::vector<std::string> choices;  // Choice only
  std::string doc;
};

// A refused parameter name or value. The message names the key and what is valid.
struct ParamError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Every parameter of every stage, in stage order.
const std::vector<ParamSpec>& param_specs();
const ParamSpec& param_spec(const std::string& key);  // throws ParamError, listing names
std::string format_value(const ParamSpec& spec, double value);

// Collects the specs of one struct (used by param_specs()).
class SpecCollector {
 public:
  SpecCollector(std::string stage, std::vector<ParamSpec>& out) : stage_(std::move(stage)), out_(out) {}
  template <class R>  // float, or double where a stage computes in double
  void real(R&, const char* name, double def, double lo, double hi, const char* doc) {
    add(name, ParamType::Real, def, lo, hi, {}, doc);
  }
  void integer(int&, const char* name, int def, int lo, int hi, const char* doc) {
    add(name, ParamType::Integer, def, lo, hi, {}, doc);
  }
  void boolean(bool&, const char* name, bool def, const char* doc) {
    add(name, ParamType::Boolean, def, 0, 1, {}, doc);
  }
  template <class E>
  void choice(E&, const char* name, E def, std::vector<std::string> names, const char* doc) {
    double n = double(names.size()) - 1;
    add(name, ParamType::Choice, double(int(def)), 0, n, std::move(names), doc);
  }

 private:
  void add(const char* name, ParamType t, double def, double lo, double hi, std::vector<std::string> choices,
           const char* doc);
  std::string stage_;
  std::vector<ParamSpec>& out_;
};

// The values of all parameters: defaults plus validated overrides.
class ParamSet {
 public:
  // Parses and validates `value` for `key`; throws ParamError naming the key and range.
  void set(const std::string& key, const std::string& value);
  void set(const std::string& key, double value);
  // Parses "stage.name=value".
  void set_assignment(const std::string& assignment);
  double value(const std::string& key) const;
  const std::map<std::string, double>& overrides() const { return overrides_; }

  template <class P>
  P get() const {
    P p{};
    Loader loader{*this, P::stage};
    p.visit(loader);
    return p;
  }

 private:
  struct Loader {
    const ParamSet& set;
    std::string stage;
    double at(const char* name) const { return set.value(stage + "." + name); }
    template <class R>
    void real(R& r, const char* n, double, double, double, const char*) {
      r = R(at(n));
    }
    void integer(int& i, const char* n, int, int, int, const char*) { i = int(at(n)); }
    void boolean(bool& b, const char* n, bool, const char*) { b = at(n) != 0.0; }
    template <class E>
    void choice(E& e, const char* n, E, const std::vector<std::string>&, const char*) {
      e = E(int(at(n)));
    }
  };
  std::map<std::string, double> overrides_;
};

}  // namespace plumbago
