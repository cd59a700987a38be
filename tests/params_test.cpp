#include <gtest/gtest.h>

#include "common/edge_detect.hpp"
#include "common/params.hpp"

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

TEST(Params, DefaultsComeFromTheTable) {
  auto p = ParamSet{}.get<EdgeDetectParams>();
  EXPECT_FLOAT_EQ(p.depth_scale, float(param_spec("edge.depth_scale").default_value));
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
