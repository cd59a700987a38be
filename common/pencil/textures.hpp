// Every texture the pipeline generates on the CPU (Lee et al. 2006, §4.2, §5.1, §5.5), made once per
// parameter set and uploaded unchanged to the GPU, plus a way to look at them.
#pragma once

#include <map>
#include <string>

#include "common/core/params.hpp"
#include "common/util/image.hpp"

namespace plumbago {

// Name -> viewable image (PNG ready): each pencil layer, a contact sheet of the stack,
// the contour texture, paper height/normal/color, each copy's offset field, the
// sketchy noise.
std::map<std::string, Image> texture_gallery(const ParamSet& params, uint32_t seed, int width, int height);

// Layers side by side, `columns` across, layer 0 at the top left.
Image contact_sheet(const std::vector<Image>& layers, int columns);

}  // namespace plumbago
