// Preprocessing (Lee et al. 2006 §5; docs/stages.md) shared by both backends: made once per
// scene and parameter set on the CPU, handed unchanged to the reference and uploaded to the
// GPU. Only the steps the scene's passes name are run (common/core/passes.hpp). Each step
// puts its outputs under the handles its header declares; frames read them through the
// same get() as every other input.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/core/frame.hpp"
#include "common/core/handle.hpp"
#include "common/scene/scene.hpp"

namespace plumbago {

struct Preprocessed {
  template <class T>
  void put(Slot<T> slot, T value) {
    data.put(slot, std::make_shared<const T>(std::move(value)));
  }
  template <class T>
  void put(Slot<T> slot, std::shared_ptr<const T> value) {
    data.put(slot, std::move(value));
  }
  template <class T>
  const T* get(Maybe<Slot<T>> slot) const {
    return data.find(slot.handle);
  }
  template <class T>
  const T& get(Slot<T> slot) const {
    if (const T* value = data.find(slot)) return *value;
    throw std::logic_error(std::string("preprocessing did not make '") + slot.name + "'");
  }

  DataTable data;
  std::vector<PassTime> ran;  // the steps that ran, with their times
};

// The preprocessing stages among `passes`, in stage order, after checking that every object's
// mesh can be drawn (validate_drawable_mesh: MeshError naming it, before any work).
Preprocessed preprocess(const Scene& scene, const std::vector<std::string>& passes);

}  // namespace plumbago
