// `plumbago view --script FILE`: a JSON list of actions the viewer applies in order, as a
// person would through the panel. Each action is an object with one key:
//
//   {"set": {"edge.depth_scale": 14, "paper.texture": "smooth"}}  parameters (--set's values)
//   {"effect": {"paper": false}}          effects on or off
//   {"orbit": [30, -10]}                  orbit by degrees: turntable, then pitch
//   {"stage": "gbuffer.depth"}            stage view of a buffer ("" for the final image)
//   {"check": "report.json"}              check against the reference; writes the report
//   {"heatmap": "edge_detect.edge"}       show the heat map of a checked stage
//   {"save": "scene.json"}                save the scene
//   {"screenshot": "shot.png"}            what the window shows, after the changes drew
//   {"reload": true}                      wait until an edited scene or mesh file reloaded
//   {"draw": {"kind": "decal", "style": "ink", "points": [[x, y], ...], "pressure": [...]}}
//                                         draw a stroke on the model (apps/viewer/drawing.hpp):
//                                         kind decal, crease, silhouette or hatching (with
//                                         "group": G, "free" and "mobile": true|false); points in the
//                                         frame's pixels, origin bottom-left; pressure
//                                         optional, one a point, in [0, 1]
//   {"undo": ""}, {"redo": ""}            the last stroke drawn, taken back or again
//   {"erase": [x, y]}                     the decal or hatch drawn under that frame point
//   {"save_strokes": "strokes.json"}      write the drawn strokes' stroke files (then "save"
//                                         lists them in the scene)
//
// Everything that can be checked before the window opens is (the names of parameters
// and effects, the values' types and ranges); a malformed script is refused naming the
// file, the action's index and its key.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "apps/viewer/drawing.hpp"

namespace plumbago {

struct ScriptAction {
  size_t index;        // in the file, from 0
  std::string key;     // "set", "effect", ...
  nlohmann::json arg;  // checked for its key
};

// A "set" action's value for `key` as ParamSet stores it; throws ParamError as --set does.
double param_value(const std::string& key, const nlohmann::json& value);
// A "draw" action's stroke; throws std::invalid_argument naming what is wrong.
DrawRequest draw_request(const nlohmann::json& arg);

class Script {
 public:
  Script() = default;
  // Reads and checks FILE; throws std::invalid_argument naming the file, index and key.
  explicit Script(const std::string& path);

  bool done() const { return next_ >= actions_.size(); }
  const ScriptAction& next() const { return actions_.at(next_); }
  void advance() { ++next_; }
  // An error applying the next action, naming the file, its index and key.
  std::string where() const { return at(next().index, next().key); }

 private:
  std::string at(size_t index, const std::string& key) const;
  std::string path_;
  std::vector<ScriptAction> actions_;
  size_t next_ = 0;
};

}  // namespace plumbago
