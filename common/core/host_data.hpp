// CPU data that the stages of one frame share (the window lines of Kalnins et al. 2002 and what is
// made of them), by name, made on first use. Both backends' frames hold one.
#pragma once

#include <map>
#include <memory>
#include <string>

namespace plumbago {

class HostData {
 public:
  template <class T, class Make>
  const T& get(const std::string& name, const Make& make) {
    auto it = items_.find(name);
    if (it == items_.end()) it = items_.emplace(name, std::make_shared<T>(make())).first;
    return *std::static_pointer_cast<T>(it->second);
  }
  template <class T>
  void put(const std::string& name, T value) {
    items_[name] = std::make_shared<T>(std::move(value));
  }
  template <class T>
  const T* find(const std::string& name) const {
    auto it = items_.find(name);
    return it == items_.end() ? nullptr : static_cast<const T*>(it->second.get());
  }

 private:
  std::map<std::string, std::shared_ptr<void>> items_;
};

}  // namespace plumbago
