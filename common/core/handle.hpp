// Typed handles for everything a frame passes between stages. A stage's header declares
// its outputs once as handles; its descriptor (common/core/stage.hpp) lists them, and both
// backends' frames read and write through them, so a name is never spelled twice:
//
//   inline constexpr Buffer kContourDarkness{"edge_detect.contour_darkness"};  // an image
//   inline constexpr Slot<Visibility> kVisibleRuns{"visibility.runs"};        // CPU data
//
//   f.put(kContourDarkness, contour_darkness(...));   // reference/pencil/edge_detect.cpp
//   const Image& d = f.get(kContourDarkness);           // a stage that declares it an input
//   const Image* c = f.get(maybe(kContourDarkness));     // an input whose condition may not hold
//
// What a handle holds depends on the backend for images (an Image in the reference, a
// texture on the GPU) and is the handle's type for CPU data (the same in both).
#pragma once

#include <any>
#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>

namespace plumbago {

// An image of the frame that a stage writes ("<stage>.<output>").
struct Buffer {
  const char* name;
};

// CPU data of type T that a stage (or preprocessing) makes and later stages read.
template <class T>
struct Slot {
  const char* name;
};

// A whole G-buffer ("gbuffer", "sketchy_gbuffer") and its channels: a stage declares the
// channels it reads, and the frame hands it the whole G-buffer.
struct GBufferSlot {
  const char* name;
  Buffer normal, face_normal, depth, ids, bary, gouraud, theta_min, theta_max;
};

// A GPU object one pass makes and later passes of the frame use (a depth buffer, corner
// angles): GPU-only wiring between passes, declared next to the pass that makes it.
template <class T>
struct Shared {
  const char* name;
};

// An input whose condition may not hold: get() returns null where it was not made.
template <class H>
struct Maybe {
  H handle;
};
template <class H>
constexpr Maybe<H> maybe(H handle) {
  return {handle};
}

// Values by handle name, each held as shared_ptr<const T>; a read with another type than
// the one put is a std::logic_error, not a reinterpretation.
class DataTable {
 public:
  template <class T>
  void put(Slot<T> slot, std::shared_ptr<const T> value) {
    items_[slot.name] = std::move(value);
  }
  template <class T>
  const T* find(Slot<T> slot) const {
    auto it = items_.find(slot.name);
    if (it == items_.end()) return nullptr;
    auto* held = std::any_cast<std::shared_ptr<const T>>(&it->second);
    if (!held) throw std::logic_error(std::string("'") + slot.name + "' holds data of another type");
    return held->get();
  }
  void clear() { items_.clear(); }

 private:
  std::map<std::string, std::any, std::less<>> items_;
};

}  // namespace plumbago
