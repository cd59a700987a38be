// The GL context: GL 4.5 core on whatever this machine offers, and GL errors are caught.
#include <gtest/gtest.h>

#include "gpu/gl/context.hpp"
#include "gpu/gl/gl.hpp"

namespace plumbago::gpu {
namespace {

TEST(GlContext, OffersGl45CoreAndNamesItsRenderer) {
  Context& c = Context::get();
  std::printf("[gl] platform %s, renderer %s, version %s\n", c.platform().c_str(), c.renderer().c_str(),
              c.version().c_str());
  EXPECT_FALSE(c.renderer().empty());
  GLint major = 0, minor = 0, mask = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &mask);
  EXPECT_GE(major * 10 + minor, 45);
  EXPECT_TRUE(mask & GL_CONTEXT_CORE_PROFILE_BIT);
  EXPECT_NO_THROW(c.check_errors("nothing"));
}

TEST(GlContext, AGlErrorFailsTheCheckAndNamesTheStage) {
  Context& c = Context::get();
  glEnable(GL_TEXTURE_2D);  // not a core-profile capability: GL_INVALID_ENUM
  try {
    c.check_errors("the deliberate mistake");
    FAIL() << "a GL error went unnoticed";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("the deliberate mistake"), std::string::npos) << e.what();
  }
  EXPECT_NO_THROW(c.check_errors("after the check"));  // reported once, then cleared
}

}  // namespace
}  // namespace plumbago::gpu
