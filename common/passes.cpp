#include "common/passes.hpp"

#include <algorithm>
#include <set>
#include <stdexcept>

#include "common/sketchy.hpp"

namespace plumbago {

namespace {

bool object_style(const ParamSet& p) { return p.get<SketchyParams>().style == SketchyStyle::Object; }

}  // namespace

const std::vector<PassDef>& pass_table() {
  static const std::vector<PassDef> table = {
      {"distortion", PassKind::Preprocessing, {}, "offset grids of the contour copies (SPEC 1.4, Lee Eq. 2)"},
      {"contour_texture", PassKind::Preprocessing, {}, "the pencil layer used as contour texture (SPEC 1.2)"},
      {"curvature", PassKind::Preprocessing, {}, "principal curvature per vertex (SPEC 1.1)"},
      {"pencil_textures", PassKind::Preprocessing, {}, "the pencil tone stack (SPEC 1.2, Lee Eq. 3-4)"},
      {"paper", PassKind::Preprocessing, {}, "paper height, normal map and color (SPEC 1.3)"},
      {"gbuffer", PassKind::Stage, {}, "G-buffer: normals, depth, ids, barycentrics, Gouraud (SPEC 2.1)"},
      {"edge_detect", PassKind::Stage, {"gbuffer"}, "contour darkness from normal and depth discontinuities (SPEC 2.2)"},
      {"contour_light", PassKind::Stage, {"edge_detect"}, "lit contours drawn lighter (SPEC 2.3, Lee Eq. 1)"},
      {"interior_intensity", PassKind::Stage, {"gbuffer"}, "interior intensity and brightness (SPEC 2.5)"},
      {"pencil_interior", PassKind::Stage, {"interior_intensity", "curvature", "pencil_textures"},
       "tone to layer, rotated pencil textures, 3-way blending, cross hatching, paper effect (SPEC 2.6-2.10)"},
      {"multi_contour", PassKind::Stage, {"contour_light", "distortion", "contour_texture"},
       "contour copies on distorted planes with the contour texture (SPEC 2.4)"},
      {"compose", PassKind::Stage, {"gbuffer"}, "contours, interior and paper into the final image (SPEC 2.11)"},
      {"sketchy_noise", PassKind::Preprocessing, {}, "noise textures of the sketchy uncertainty (SPEC 3.2, 3.5)"},
      {"sketchy_gbuffer", PassKind::Stage, {}, "G-buffer of the objects whose style is sketchy (SPEC 3.1)"},
      {"sketchy_enlarged", PassKind::Stage, {}, "noise coordinates on the enlarged sketchy objects (SPEC 3.5, object style)",
       object_style},
      {"sketchy_maps", PassKind::Stage, {"sketchy_gbuffer"}, "edge and shade maps of the sketchy objects (SPEC 3.1)"},
      {"sketchy_composite", PassKind::Stage, {"sketchy_maps", "sketchy_noise", "sketchy_enlarged"},
       "perturbed edges and shade, drawn as a depth sprite over the ordinary objects (SPEC 3.2-3.4)"},
  };
  return table;
}

const std::vector<EffectDef>& effect_table() {
  static const std::vector<EffectDef> table = {
      {"contours", {"edge_detect", "contour_light", "multi_contour", "compose"}, "image-space contours (Lee 2006 §4)"},
      {"interior", {"pencil_interior", "compose"}, "pencil textures along curvature directions (Lee 2006 §5)"},
      {"crosshatch", {"pencil_interior", "compose"}, "cross hatching in dark regions (Lee 2006 Fig. 7)"},
      {"paper", {"paper", "compose"}, "stroke/paper interaction and paper color (Lee 2006 §5.5)"},
      {"sketchy", {"sketchy_composite"},
       "sketchy drawing of the objects whose style is sketchy (Nienhaus & Doellner 2004); on by itself when one is"},
  };
  return table;
}

bool is_effect(const std::string& name) {
  const auto& t = effect_table();
  return std::any_of(t.begin(), t.end(), [&](const EffectDef& e) { return e.name == name; });
}

std::string effect_names() {
  std::string names;
  for (const auto& e : effect_table()) names += (names.empty() ? "" : ", ") + e.name;
  return names;
}

namespace {

const PassDef& find_pass(const std::string& name) {
  for (const auto& p : pass_table())
    if (p.name == name) return p;
  throw std::logic_error("pass table names an unknown pass '" + name + "'");
}

void add_with_needs(const std::string& name, const ParamSet& params, std::set<std::string>& chosen) {
  const PassDef& pass = find_pass(name);
  if (pass.wanted && !pass.wanted(params)) return;
  if (!chosen.insert(name).second) return;
  for (const auto& n : pass.needs) add_with_needs(n, params, chosen);
}

}  // namespace

std::vector<std::string> passes_for(const std::vector<std::string>& effects, const ParamSet& params) {
  std::set<std::string> chosen;
  for (const auto& effect : effects) {
    auto it = std::find_if(effect_table().begin(), effect_table().end(),
                           [&](const EffectDef& e) { return e.name == effect; });
    if (it == effect_table().end())
      throw std::invalid_argument("unknown effect '" + effect + "' (known: " + effect_names() + ")");
    for (const auto& p : it->passes) add_with_needs(p, params, chosen);
  }
  std::vector<std::string> ordered;
  for (const auto& p : pass_table())
    if (chosen.count(p.name)) ordered.push_back(p.name);
  return ordered;
}

bool is_preprocessing(const std::string& pass) {
  for (const auto& p : pass_table())
    if (p.name == pass) return p.kind == PassKind::Preprocessing;
  return false;
}

std::vector<std::string> frame_stages(const std::vector<std::string>& passes) {
  std::vector<std::string> stages;
  for (const auto& p : passes)
    if (find_pass(p).kind == PassKind::Stage) stages.push_back(p);
  return stages;
}

}  // namespace plumbago
