// What both backends' frames share: a frame's CPU data by Slot (common/core/handle.hpp),
// over what preprocessing made, and the check of every read against the descriptors of the
// stages running (common/core/stage.hpp check_declared).
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "common/core/handle.hpp"
#include "common/core/preprocess.hpp"
#include "common/core/stage.hpp"

namespace plumbago {

class FrameData {
 public:
  explicit FrameData(Preprocessed pre) : pre(std::move(pre)) {}

  template <class T>
  void put(Slot<T> slot, T value) {
    checked(slot.name);
    data.put(slot, std::make_shared<const T>(std::move(value)));
  }
  // The frame's, else preprocessing's; null where neither made it.
  template <class T>
  const T* get(Maybe<Slot<T>> slot) const {
    checked(slot.handle.name);
    const T* value = data.find(slot.handle);
    return value ? value : pre.get(slot);
  }
  template <class T>
  const T& get(Slot<T> slot) const {
    if (const T* value = get(maybe(slot))) return *value;
    throw std::logic_error(std::string("frame: no stage made '") + slot.name + "'");
  }

  // What a running stage made of its own `slot` in the path's previous frame, where this
  // frame follows it (Carry); null otherwise.
  template <class T>
  const T* before(Slot<T> slot) const {
    checked(slot.name);
    return previous ? previous->find(slot) : nullptr;
  }

  Preprocessed pre;
  DataTable data;                       // the frame's CPU data
  const DataTable* previous = nullptr;  // the previous frame's (Carry::before)
  std::vector<std::string> running;     // the stages running now (none: the pipeline or parity)

 protected:
  // A read or write of a running stage must be one its descriptor declares.
  void checked(const std::string& name) const {
    if (!running.empty()) check_declared(running, name);
  }
};

}  // namespace plumbago
