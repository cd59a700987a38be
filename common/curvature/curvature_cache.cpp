#include "common/curvature/curvature_cache.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "common/util/output_file.hpp"

namespace plumbago {
namespace {

namespace fs = std::filesystem;

constexpr char kMagic[8] = {'P', 'L', 'B', 'C', 'U', 'R', 'V', '\0'};
constexpr uint32_t kFormatVersion = 1;
constexpr size_t kFloatsPerVertex = 11;  // k_min, k_max, normal, d_min, d_max

uint64_t mix(uint64_t z) {  // splitmix64 finalizer
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

// 64-bit hash of a byte range, eight bytes at a time.
uint64_t hash_bytes(const void* data, size_t size, uint64_t h) {
  const auto* bytes = static_cast<const unsigned char*>(data);
  h = mix(h ^ size);
  size_t i = 0;
  for (; i + 8 <= size; i += 8) {
    uint64_t word;
    std::memcpy(&word, bytes + i, 8);
    h = mix(h ^ word) * 0x9E3779B97F4A7C15ull;
  }
  uint64_t tail = 0;
  std::memcpy(&tail, bytes + i, size - i);
  return mix(h ^ tail);
}

template <class T>
uint64_t hash_vector(const std::vector<T>& v, uint64_t h) {
  return hash_bytes(v.data(), v.size() * sizeof(T), h);
}

std::vector<float> pack(const Curvature& c) {
  std::vector<float> out;
  out.reserve(c.size() * kFloatsPerVertex);
  for (size_t v = 0; v < c.size(); ++v) {
    out.push_back(c.k_min[v]);
    out.push_back(c.k_max[v]);
    for (const glm::vec3* u : {&c.normal[v], &c.d_min[v], &c.d_max[v]}) out.insert(out.end(), {u->x, u->y, u->z});
  }
  return out;
}

// Unpacks, or returns false if a value is not finite or a vector is not unit.
bool unpack(const std::vector<float>& in, Curvature& c) {
  size_t n = in.size() / kFloatsPerVertex;
  c.k_min.resize(n), c.k_max.resize(n), c.normal.resize(n), c.d_min.resize(n), c.d_max.resize(n);
  for (size_t v = 0; v < n; ++v) {
    const float* x = in.data() + v * kFloatsPerVertex;
    for (size_t i = 0; i < kFloatsPerVertex; ++i)
      if (!std::isfinite(x[i])) return false;
    c.k_min[v] = x[0], c.k_max[v] = x[1];
    c.normal[v] = {x[2], x[3], x[4]}, c.d_min[v] = {x[5], x[6], x[7]}, c.d_max[v] = {x[8], x[9], x[10]};
    for (const glm::vec3& u : {c.normal[v], c.d_min[v], c.d_max[v]})
      if (std::abs(glm::length(u) - 1.0f) > 1e-3f) return false;
    if (c.k_min[v] > c.k_max[v]) return false;
  }
  return true;
}

struct Header {
  char magic[8];
  uint32_t version;
  uint32_t params_length;
  uint64_t mesh_hash;
  uint64_t vertex_count;
};

}  // namespace

std::string curvature_cache_dir() {
  if (const char* dir = std::getenv("PLUMBAGO_CACHE_DIR"); dir && *dir) return dir;
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return (fs::path(xdg) / "plumbago").string();
  if (const char* home = std::getenv("HOME"); home && *home) return (fs::path(home) / ".cache" / "plumbago").string();
  return (fs::temp_directory_path() / "plumbago-cache").string();
}

uint64_t mesh_content_hash(const Mesh& mesh) {
  uint64_t h = hash_vector(mesh.positions, 0x706c756d6261676full);
  h = hash_vector(mesh.normals, h);
  return hash_vector(mesh.triangles, h);
}

namespace {

// Writes "curvature.name=value;" for each field a params struct visits.
struct ParamsKeyWriter {
  std::ostringstream os;
  void field(const char* name, double value) { os << "curvature." << name << '=' << value << ';'; }
  void real(float& f, const char* n, double, double, double, const char*) { field(n, f); }
  void integer(int& i, const char* n, int, int, int, const char*) { field(n, i); }
  void boolean(bool& b, const char* n, bool, const char*) { field(n, b); }
  template <class E>
  void choice(E& e, const char* n, E, const std::vector<std::string>&, const char*) {
    field(n, int(e));
  }
};

}  // namespace

std::string curvature_params_key(const CurvatureParams& params) {
  ParamsKeyWriter writer;
  writer.os.precision(9);
  CurvatureParams copy = params;
  copy.visit(writer);
  return writer.os.str();
}

std::string CurvatureCacheKey::file_name() const {
  uint64_t h = hash_bytes(params.data(), params.size(), mesh_hash ^ mix(vertex_count));
  char name[32];
  std::snprintf(name, sizeof name, "%016llx.curv", static_cast<unsigned long long>(h));
  return name;
}

std::optional<Curvature> read_curvature_cache(const std::string& path, const CurvatureCacheKey& key, std::string& why) {
  why.clear();
  auto reject = [&](std::string reason) {
    why = std::move(reason);
    return std::optional<Curvature>();
  };
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  Header h{};
  size_t payload = key.vertex_count * kFloatsPerVertex * sizeof(float);
  if (bytes.size() < sizeof h) return reject("truncated header");
  std::memcpy(&h, bytes.data(), sizeof h);
  if (std::memcmp(h.magic, kMagic, sizeof kMagic) != 0) return reject("not a curvature cache file");
  if (h.version != kFormatVersion) return reject("format version " + std::to_string(h.version));
  if (bytes.size() != sizeof h + h.params_length + payload + sizeof(uint64_t))
    return reject("size does not match its key");
  std::string params(bytes.data() + sizeof h, h.params_length);
  if (h.mesh_hash != key.mesh_hash || h.vertex_count != key.vertex_count || params != key.params)
    return reject("stale: made for another mesh or other parameters");
  const char* data = bytes.data() + sizeof h + h.params_length;
  uint64_t checksum;
  std::memcpy(&checksum, data + payload, sizeof checksum);
  if (checksum != hash_bytes(data, payload, key.mesh_hash)) return reject("checksum mismatch");
  std::vector<float> values(key.vertex_count * kFloatsPerVertex);
  std::memcpy(values.data(), data, payload);
  Curvature c;
  if (!unpack(values, c)) return reject("invalid values");
  return c;
}

void write_curvature_cache(const std::string& path, const CurvatureCacheKey& key, const Curvature& c) {
  std::vector<float> values = pack(c);
  Header h{};
  std::memcpy(h.magic, kMagic, sizeof kMagic);
  h.version = kFormatVersion;
  h.params_length = uint32_t(key.params.size());
  h.mesh_hash = key.mesh_hash;
  h.vertex_count = key.vertex_count;
  uint64_t checksum = hash_bytes(values.data(), values.size() * sizeof(float), key.mesh_hash);
  OutputFile file(path);
  {
    std::ofstream out(file.temporary_path(), std::ios::binary);
    out.write(reinterpret_cast<const char*>(&h), sizeof h);
    out.write(key.params.data(), std::streamsize(key.params.size()));
    out.write(reinterpret_cast<const char*>(values.data()), std::streamsize(values.size() * sizeof(float)));
    out.write(reinterpret_cast<const char*>(&checksum), sizeof checksum);
    if (!out) throw std::runtime_error(path + ": cannot write the curvature cache file");
  }
  file.commit();
}

Curvature compute_curvature(const Mesh& mesh, const CurvatureParams& params, const CurvatureOptions& options) {
  if (!options.use_cache) return estimate_curvature(mesh, params, options.progress);
  CurvatureCacheKey key{mesh_content_hash(mesh), mesh.positions.size(), curvature_params_key(params)};
  fs::path dir = options.cache_dir.empty() ? curvature_cache_dir() : options.cache_dir;
  std::string path = (dir / key.file_name()).string(), why;
  if (auto cached = read_curvature_cache(path, key, why)) return *cached;
  if (!why.empty() && options.progress)
    std::fprintf(stderr, "plumbago: curvature cache %s: %s; recomputing\n", path.c_str(), why.c_str());
  Curvature c = estimate_curvature(mesh, params, options.progress);
  try {
    fs::create_directories(dir);
    write_curvature_cache(path, key, c);
  } catch (const std::exception& e) {  // a cache that cannot be written only costs time
    if (options.progress) std::fprintf(stderr, "plumbago: curvature cache not written: %s\n", e.what());
  }
  return c;
}

}  // namespace plumbago
