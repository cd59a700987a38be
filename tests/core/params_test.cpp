// The parameter table (common/core/params.hpp): keys, defaults, overrides and refusals.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "common/core/params.hpp"
#include "common/core/stage_registry.hpp"
#include "common/pencil/edge_detect.hpp"

namespace plumbago {
namespace {

TEST(Params, EveryKeyIsStageDotNameAndDefaultInRange) {
  ASSERT_FALSE(param_specs().empty());
  for (const auto& s : param_specs()) {
    EXPECT_NE(s.key.find('.'), std::string::npos) << s.key;
    EXPECT_GE(s.default_value, s.min) << s.key;
    EXPECT_LE(s.default_value, s.max) << s.key;
    EXPECT_FALSE(s.doc.empty()) << s.key;
  }
}

TEST(Params, OverrideReachesTheStageStruct) {
  ParamSet set;
  set.set_assignment("edge.depth_scale=12");
  set.set_assignment("edge.normals=face");
  auto p = set.get<EdgeDetectParams>();
  EXPECT_FLOAT_EQ(p.depth_scale, 12.0f);
  EXPECT_EQ(p.normals, EdgeNormals::Face);
}

// Visits a struct loaded from a default ParamSet and checks each field against the literal
// default its `visit` writes and against the table (param_specs(), made by SpecCollector
// from the same `visit`): a Loader that stored something else, or a SpecCollector that
// recorded another default, range, type or choice list, fails here.
struct DefaultsChecker {
  std::string stage;
  size_t fields = 0;

  const ParamSpec& spec(const char* name, ParamType type) {
    ++fields;
    const ParamSpec& s = param_spec(stage + "." + name);
    EXPECT_EQ(s.type, type) << s.key;
    return s;
  }
  template <class R>
  void real(R& r, const char* name, double def, double lo, double hi, const char*) {
    const ParamSpec& s = spec(name, ParamType::Real);
    EXPECT_EQ(s.default_value, def) << s.key;
    EXPECT_EQ(s.min, lo) << s.key;
    EXPECT_EQ(s.max, hi) << s.key;
    EXPECT_EQ(r, R(def)) << s.key;
    EXPECT_EQ(r, R(s.default_value)) << s.key;
  }
  void integer(int& i, const char* name, int def, int lo, int hi, const char*) {
    const ParamSpec& s = spec(name, ParamType::Integer);
    EXPECT_EQ(s.default_value, double(def)) << s.key;
    EXPECT_EQ(s.min, double(lo)) << s.key;
    EXPECT_EQ(s.max, double(hi)) << s.key;
    EXPECT_EQ(i, def) << s.key;
    EXPECT_EQ(double(i), s.default_value) << s.key;
  }
  void boolean(bool& b, const char* name, bool def, const char*) {
    const ParamSpec& s = spec(name, ParamType::Boolean);
    EXPECT_EQ(s.default_value, def ? 1.0 : 0.0) << s.key;
    EXPECT_EQ(b, def) << s.key;
    EXPECT_EQ(b, s.default_value != 0.0) << s.key;
  }
  template <class E>
  void choice(E& e, const char* name, E def, const std::vector<std::string>& names, const char*) {
    const ParamSpec& s = spec(name, ParamType::Choice);
    EXPECT_EQ(s.default_value, double(int(def))) << s.key;
    EXPECT_EQ(s.choices, names) << s.key;
    EXPECT_EQ(s.max, double(names.size()) - 1) << s.key;
    EXPECT_EQ(int(e), int(def)) << s.key;
    EXPECT_EQ(double(int(e)), s.default_value) << s.key;
  }
};

template <class P>
size_t check_defaults() {
  P p = ParamSet{}.get<P>();
  DefaultsChecker checker{P::stage};
  p.visit(checker);
  EXPECT_GT(checker.fields, 0u) << P::stage;
  return checker.fields;
}

template <class... P>
size_t check_struct_defaults(TypeList<P...>) {
  return (size_t(0) + ... + check_defaults<P>());
}

template <class... Stages>
size_t check_all_defaults(TypeList<Stages...>) {
  return (check_struct_defaults(typename Stages::Params{}) + ...);
}

TEST(Params, DefaultsComeFromTheTable) {
  // A default ParamSet gives each key the table's default.
  ParamSet defaults;
  for (const auto& s : param_specs()) EXPECT_EQ(defaults.value(s.key), s.default_value) << s.key;
  // A few defaults as the headers write them (and docs/stages.md lists them).
  EXPECT_EQ(param_spec("edge.depth_scale").default_value, 10.0);            // common/pencil/edge_detect.hpp
  EXPECT_EQ(param_spec("edge.normals").default_value, 0.0);                 // interpolated
  EXPECT_EQ(param_spec("edge.background_pairs").default_value, 0.0);        // continuous
  EXPECT_EQ(param_spec("compose.contour_attenuation").default_value, 0.5);  // common/pencil/compose.hpp
  EXPECT_EQ(param_spec("compose.contrast").default_value, 0.5);
  EXPECT_EQ(param_spec("contour.copies").default_value, 3.0);  // common/pencil/multi_contour.hpp
  EXPECT_EQ(param_spec("contour.stroke_opacity").default_value, 0.7);
  EXPECT_EQ(param_spec("curvature.ring_fallback").default_value, 1.0);  // common/curvature/curvature.hpp
  EXPECT_EQ(param_spec("paper.mu_p").default_value, 0.05);              // common/pencil/paper.hpp
  EXPECT_EQ(param_spec("sketchy.shade_c").default_value, -3.0);         // common/sketchy/sketchy.hpp
  EXPECT_EQ(param_spec("pencil_textures.layers").default_value, 32.0);  // common/pencil/pencil_textures.hpp
  // The edge stage's struct, field by field, as the stages load it.
  EXPECT_EQ(check_defaults<EdgeDetectParams>(), 3u);
  auto p = ParamSet{}.get<EdgeDetectParams>();
  EXPECT_EQ(p.depth_scale, 10.0f);
  EXPECT_EQ(p.normals, EdgeNormals::Interpolated);
  EXPECT_EQ(p.background_pairs, BackgroundPairs::Continuous);
}

// Every stage's struct (common/core/stage_registry.hpp) loads the defaults its visit writes, and
// the table holds exactly their fields.
TEST(Params, EveryStructLoadsTheDefaultsItsVisitWrites) {
  EXPECT_EQ(check_all_defaults(AllStages{}), param_specs().size());
}

TEST(Params, UnknownNameIsRefusedWithTheValidNames) {
  ParamSet set;
  try {
    set.set_assignment("edge.depth_scal=3");
    FAIL() << "accepted an unknown name";
  } catch (const ParamError& e) {
    std::string m = e.what();
    EXPECT_NE(m.find("edge.depth_scal'"), std::string::npos) << m;
    EXPECT_NE(m.find("edge.depth_scale"), std::string::npos) << m;
  }
}

TEST(Params, OutOfRangeAndMalformedValuesAreRefusedWithTheRange) {
  ParamSet set;
  EXPECT_THROW(set.set_assignment("edge.depth_scale=-1"), ParamError);
  EXPECT_THROW(set.set_assignment("edge.depth_scale=nan"), ParamError);
  EXPECT_THROW(set.set_assignment("edge.depth_scale=12abc"), ParamError);
  EXPECT_THROW(set.set_assignment("edge.normals=smooth"), ParamError);
  EXPECT_THROW(set.set_assignment("noequals"), ParamError);
  try {
    set.set_assignment("edge.depth_scale=1e9");
  } catch (const ParamError& e) {
    EXPECT_NE(std::string(e.what()).find("[0, 10000]"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(set.overrides().empty());
}

}  // namespace
}  // namespace plumbago
