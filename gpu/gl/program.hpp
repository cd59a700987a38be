// GLSL programs built from shaders/ with the stage parameters declared from their C++
// structs: for a struct with stage "edge" the prelude is
//     struct edge_params { float depth_scale; int normals; };
//     uniform edge_params edge;
//     #define EDGE_NORMALS_INTERPOLATED 0 ...
// so shaders read `edge.depth_scale` and no default is ever written in GLSL.
#pragma once

#include <cctype>
#include <map>
#include <string>
#include <vector>

#include "common/scene/scene.hpp"
#include "gpu/gl/gl.hpp"
#include "gpu/gl/gl_objects.hpp"

namespace plumbago::gpu {

namespace detail {
inline void delete_program(GLuint id) { glDeleteProgram(id); }

std::string upper(std::string s);

// Writes the GLSL declaration of a parameter struct (see above).
class GlslDeclarer {
 public:
  explicit GlslDeclarer(std::string stage) : stage_(std::move(stage)) {}
  void real(float&, const char* n, double, double, double, const char*) { field("float", n); }
  void integer(int&, const char* n, int, int, int, const char*) { field("int", n); }
  void boolean(bool&, const char* n, bool, const char*) { field("bool", n); }
  template <class E>
  void choice(E&, const char* n, E, const std::vector<std::string>& names, const char*) {
    field("int", n);
    for (size_t i = 0; i < names.size(); ++i)
      defines_ += "#define " + upper(stage_ + "_" + n + "_" + names[i]) + " " + std::to_string(i) + "\n";
  }
  std::string text() const {
    return "struct " + stage_ + "_params {\n" + fields_ + "};\nuniform " + stage_ + "_params " + stage_ + ";\n" +
           defines_;
  }

 private:
  void field(const char* type, const char* n) { fields_ += std::string("  ") + type + " " + n + ";\n"; }
  std::string stage_, fields_, defines_;
};

// Sets the uniforms `stage.field` of a program from a parameter struct.
class UniformSetter {
 public:
  UniformSetter(GLuint program, std::string stage) : program_(program), stage_(std::move(stage)) {}
  void real(float& f, const char* n, double, double, double, const char*) { glProgramUniform1f(program_, at(n), f); }
  void integer(int& i, const char* n, int, int, int, const char*) { glProgramUniform1i(program_, at(n), i); }
  void boolean(bool& b, const char* n, bool, const char*) { glProgramUniform1i(program_, at(n), b ? 1 : 0); }
  template <class E>
  void choice(E& e, const char* n, E, const std::vector<std::string>&, const char*) {
    glProgramUniform1i(program_, at(n), int(e));
  }

 private:
  GLint at(const char* n) const { return glGetUniformLocation(program_, (stage_ + "." + n).c_str()); }
  GLuint program_;
  std::string stage_;
};
}  // namespace detail

class Program {
 public:
  // Compiles and links shaders/<vertex> and shaders/<fragment>; `prelude` goes after
  // #version. `#include "common_x.glsl"` lines are expanded from shaders/. Throws
  // std::runtime_error with the compiler log and the file name.
  Program(const std::string& vertex, const std::string& fragment, const std::string& prelude = "");
  // A compute program from shaders/<compute>, the same way.
  static Program compute(const std::string& compute, const std::string& prelude = "");
  // A program with a geometry shader between the two, the same way.
  static Program with_geometry(const std::string& vertex, const std::string& geometry, const std::string& fragment,
                               const std::string& prelude = "");
  GLuint id() const { return name_.id(); }
  GLint uniform(const char* name) const { return glGetUniformLocation(id(), name); }

  template <class P>
  void set_params(P p) const {
    detail::UniformSetter s{id(), P::stage};
    p.visit(s);
  }

 private:
  Program() = default;
  // Links the compiled shaders (and deletes them); `what` names them in an error.
  void link(std::initializer_list<GLuint> shaders, const std::string& what);
  GlName<detail::delete_program> name_;
};

template <class P>
std::string glsl_params() {
  P p{};
  detail::GlslDeclarer d{P::stage};
  p.visit(d);
  return d.text();
}

// One program per combination of boolean switches, each compiled in as `#define NAME 0|1`
// and made on first use: llvmpipe runs both sides of an if, even on a uniform, so code a
// switch turns off must not be in the program at all.
class ProgramVariants {
 public:
  ProgramVariants(std::string vertex, std::string fragment, std::string prelude, std::vector<std::string> switches)
      : vertex_(std::move(vertex)),
        fragment_(std::move(fragment)),
        prelude_(std::move(prelude)),
        switches_(std::move(switches)) {}
  // The program with switch k set to on[k].
  const Program& get(const std::vector<bool>& on);

 private:
  std::string vertex_, fragment_, prelude_;
  std::vector<std::string> switches_;
  std::map<std::vector<bool>, Program> made_;
};

// A texture for the sampler uniform of that name.
struct TextureBinding {
  const char* sampler;
  const Texture* texture;
};
// Binds each texture to a unit of its own (0, 1, ... in order) and points its sampler
// there, so that a pass names what it binds instead of keeping two lists in step. A
// sampler the program does not use is skipped (its location is -1).
void bind_textures(const Program& program, std::initializer_list<TextureBinding> textures);

// Sets the uniforms of shaders/scene/common_lights.glsl from view-space unit lights; throws
// past its MAX_LIGHTS (8).
void set_lights(const Program& program, const std::vector<Light>& view_lights);

// Dispatches `count` invocations of a compute program whose work groups are 64 wide, in
// chunks of at most 65535 groups (GL's least maximum); the program's uint uniform `first`
// gets each chunk's first invocation.
void dispatch_in_chunks(const Program& program, size_t count, const char* first);

// Dispatches a compute program whose work groups are `group_size` wide and whose invocations
// each go over every (groups x group_size)th of `count` items: ceil(count / group_size)
// groups, at least 1 and at most 65535; then a barrier, so that what follows reads what it
// wrote to storage buffers.
void dispatch_strided(const Program& program, size_t count, size_t group_size = 64);
// Dispatches a compute program with the groups (x, y, z) the GPU wrote at byte `offset` of
// `groups`; then the same barrier.
void dispatch_indirect(const Program& program, const Buffer& groups, size_t offset = 0);

// Reads shaders/<file> (PLUMBAGO_SHADER_DIR, overridable by the environment variable of
// the same name), expanding includes.
std::string shader_source(const std::string& file);

}  // namespace plumbago::gpu
