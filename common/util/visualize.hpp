// Turning named intermediate buffers into viewable images (--dump-stages, compare --out).
#pragma once

#include <map>
#include <string>

#include "common/util/image.hpp"
#include "common/util/output_file.hpp"

namespace plumbago {

// Normals map [-1,1] -> [0,1]; ids are scaled by their maximum; 2-channel buffers get a
// zero blue channel; everything else is written as is (PNG clamps to [0,1]).
Image viewable(const std::string& buffer_name, const Image& img);

// Writes every buffer as DIR/<prefix><name>.png (viewable) and .exr (the raw floats)
// among `out`'s files (which the caller commits), every location checked first.
void dump_buffers(const std::map<std::string, Image>& buffers, const std::string& dir, const std::string& prefix,
                  OutputFiles& out);

}  // namespace plumbago
