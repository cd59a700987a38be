// The on-disk cache of compute_curvature (Lee et al. 2006, §5.3; Alliez et al. 2003): one binary file per (mesh
// content, method, parameters), named by a hash of all three. A file is used only if its magic,
// format version, full key, size and payload checksum all match and every value is
// finite; anything else is stale or corrupt and is recomputed and overwritten.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "common/curvature/curvature.hpp"

namespace plumbago {

// $PLUMBAGO_CACHE_DIR, else $XDG_CACHE_HOME/plumbago, else $HOME/.cache/plumbago.
std::string curvature_cache_dir();

// Hash of the positions, normals and triangles.
uint64_t mesh_content_hash(const Mesh& mesh);

// "curvature.method=tensor;curvature.radius=0.01;..." for every parameter.
std::string curvature_params_key(const CurvatureParams& params);

struct CurvatureCacheKey {
  uint64_t mesh_hash;
  uint64_t vertex_count;
  std::string params;
  std::string file_name() const;  // hash of the whole key, hex, ".curv"
};

// The cached curvature, or nullopt with `why` saying what was wrong (empty: no file).
std::optional<Curvature> read_curvature_cache(const std::string& path, const CurvatureCacheKey& key, std::string& why);

// Written under a temporary name and renamed into place; throws std::runtime_error
// naming the file if it cannot be written.
void write_curvature_cache(const std::string& path, const CurvatureCacheKey& key, const Curvature& c);

}  // namespace plumbago
