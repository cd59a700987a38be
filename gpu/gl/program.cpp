#include "gpu/gl/program.hpp"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace plumbago::gpu {

namespace detail {
std::string upper(std::string s) {
  for (char& c : s) c = char(std::toupper(static_cast<unsigned char>(c)));
  return s;
}
}  // namespace detail

namespace {

std::string shader_dir() {
  const char* env = std::getenv("PLUMBAGO_SHADER_DIR");
  return env && *env ? env : PLUMBAGO_SHADER_DIR;
}

std::string read_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read shader " + path + " (set PLUMBAGO_SHADER_DIR?)");
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

GLuint compile(GLenum kind, const std::string& file, const std::string& prelude) {
  std::string src = shader_source(file);
  auto eol = src.find('\n');  // the #version line stays first
  src = src.substr(0, eol + 1) + prelude + "#line 2\n" + src.substr(eol + 1);
  GLuint s = glCreateShader(kind);
  const char* text = src.c_str();
  glShaderSource(s, 1, &text, nullptr);
  glCompileShader(s);
  GLint ok = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[4096] = {};
    glGetShaderInfoLog(s, sizeof log, nullptr, log);
    glDeleteShader(s);
    throw std::runtime_error("shader " + file + " does not compile:\n" + log);
  }
  return s;
}

}  // namespace

std::string shader_source(const std::string& file) {
  std::istringstream in(read_file(shader_dir() + "/" + file));
  std::string out, line;
  while (std::getline(in, line)) {
    if (line.rfind("#include \"", 0) == 0) {
      out += shader_source(line.substr(10, line.rfind('"') - 10));
    } else {
      out += line + "\n";
    }
  }
  return out;
}

Program::Program(const std::string& vertex, const std::string& fragment, const std::string& prelude) {
  GLuint vs = compile(GL_VERTEX_SHADER, vertex, prelude);
  GLuint fs;
  try {
    fs = compile(GL_FRAGMENT_SHADER, fragment, prelude);
  } catch (...) {
    glDeleteShader(vs);
    throw;
  }
  link({vs, fs}, vertex + " + " + fragment);
}

Program Program::compute(const std::string& compute, const std::string& prelude) {
  Program p;
  p.link({compile(GL_COMPUTE_SHADER, compute, prelude)}, compute);
  return p;
}

Program Program::with_geometry(const std::string& vertex, const std::string& geometry, const std::string& fragment,
                               const std::string& prelude) {
  std::vector<GLuint> shaders;
  try {
    shaders.push_back(compile(GL_VERTEX_SHADER, vertex, prelude));
    shaders.push_back(compile(GL_GEOMETRY_SHADER, geometry, prelude));
    shaders.push_back(compile(GL_FRAGMENT_SHADER, fragment, prelude));
  } catch (...) {
    for (GLuint s : shaders) glDeleteShader(s);
    throw;
  }
  Program p;
  p.link({shaders[0], shaders[1], shaders[2]}, vertex + " + " + geometry + " + " + fragment);
  return p;
}

void Program::link(std::initializer_list<GLuint> shaders, const std::string& what) {
  GLuint p = glCreateProgram();
  for (GLuint s : shaders) glAttachShader(p, s);
  glLinkProgram(p);
  for (GLuint s : shaders) glDeleteShader(s);
  name_ = GlName<detail::delete_program>(p);
  GLint ok = 0;
  glGetProgramiv(p, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[4096] = {};
    glGetProgramInfoLog(p, sizeof log, nullptr, log);
    throw std::runtime_error("program " + what + " does not link:\n" + log);
  }
}

const Program& ProgramVariants::get(const std::vector<bool>& on) {
  if (on.size() != switches_.size()) throw std::invalid_argument("program " + fragment_ + ": wrong number of switches");
  auto it = made_.find(on);
  if (it != made_.end()) return it->second;
  std::string defines;
  for (size_t k = 0; k < on.size(); ++k) defines += "#define " + switches_[k] + (on[k] ? " 1\n" : " 0\n");
  return made_.emplace(on, Program(vertex_, fragment_, prelude_ + defines)).first->second;
}

void set_lights(const Program& program, const std::vector<Light>& lights) {
  constexpr size_t kMaxLights = 8;  // MAX_LIGHTS in shaders/scene/common_lights.glsl
  if (lights.size() > kMaxLights)
    throw std::invalid_argument("the GPU backend shades with at most 8 lights, the scene has " +
                                std::to_string(lights.size()));
  std::vector<glm::vec3> directions;
  std::vector<float> intensities;
  for (const Light& l : lights) {
    directions.push_back(l.direction);
    intensities.push_back(l.intensity);
  }
  GLuint id = program.id();
  glProgramUniform1i(id, program.uniform("light_count"), GLint(lights.size()));
  if (lights.empty()) return;
  glProgramUniform3fv(id, program.uniform("light_direction"), GLsizei(lights.size()), &directions[0].x);
  glProgramUniform1fv(id, program.uniform("light_intensity"), GLsizei(lights.size()), intensities.data());
}

void bind_textures(const Program& program, std::initializer_list<TextureBinding> textures) {
  GLint unit = 0;
  for (const TextureBinding& b : textures) {
    glActiveTexture(GL_TEXTURE0 + GLenum(unit));
    glBindTexture(b.texture->target, b.texture->id());
    glProgramUniform1i(program.id(), program.uniform(b.sampler), unit++);
  }
  glActiveTexture(GL_TEXTURE0);
}

void dispatch_in_chunks(const Program& program, size_t count, const char* first) {
  const size_t per_dispatch = size_t(65535) * 64;
  glUseProgram(program.id());
  for (size_t start = 0; start < count; start += per_dispatch) {
    glProgramUniform1ui(program.id(), program.uniform(first), GLuint(start));
    glDispatchCompute(GLuint((std::min(per_dispatch, count - start) + 63) / 64), 1, 1);
  }
}

void dispatch_strided(const Program& program, size_t count, size_t group_size) {
  glUseProgram(program.id());
  glDispatchCompute(GLuint(std::clamp<size_t>((count + group_size - 1) / group_size, 1, 65535)), 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
}

void dispatch_indirect(const Program& program, const Buffer& groups, size_t offset) {
  glUseProgram(program.id());
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, groups.id());
  glDispatchComputeIndirect(GLintptr(offset));
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
}

}  // namespace plumbago::gpu
