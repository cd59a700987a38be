#include "apps/viewer/panels.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cfloat>
#include <cstdio>
#include <map>
#include <tuple>
#include <utility>

#include "common/core/passes.hpp"

namespace plumbago {
namespace {

bool item_text(void* names, int i, const char** out) {
  *out = (*static_cast<const std::vector<std::string>*>(names))[size_t(i)].c_str();
  return true;
}

bool combo(const char* label, int& index, const std::vector<std::string>& names) {
  return ImGui::Combo(label, &index, item_text, const_cast<std::vector<std::string>*>(&names), int(names.size()));
}

void tooltip(const std::string& text) {
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) ImGui::SetTooltip("%s", text.c_str());
}

// Ranges over several decades (texture sizes, depth scales) slide logarithmically.
ImGuiSliderFlags slider_flags(const ParamSpec& spec) {
  bool decades = spec.max >= 100 && (spec.min == 0 || spec.max / spec.min >= 100);
  return ImGuiSliderFlags_AlwaysClamp | (spec.min >= 0 && decades ? ImGuiSliderFlags_Logarithmic : 0);
}

// The widget of one parameter, by type; true when the user changed `value`.
bool param_widget(const ParamSpec& spec, const char* label, double& value) {
  int i = int(value);
  bool b = value != 0, changed = false;
  switch (spec.type) {
    case ParamType::Real:
      return ImGui::SliderScalar(label, ImGuiDataType_Double, &value, &spec.min, &spec.max, "%.4g", slider_flags(spec));
    case ParamType::Integer:
      changed = ImGui::SliderInt(label, &i, int(spec.min), int(spec.max), "%d", slider_flags(spec));
      break;
    case ParamType::Choice:
      changed = combo(label, i, spec.choices);
      break;
    case ParamType::Boolean:
      changed = ImGui::Checkbox(label, &b);
      i = b;
      break;
  }
  if (changed) value = i;
  return changed;
}

std::string param_tooltip(const ParamSpec& spec) {
  std::string range = spec.type == ParamType::Real || spec.type == ParamType::Integer
                          ? ", range [" + format_value(spec, spec.min) + ", " + format_value(spec, spec.max) + "]"
                          : "";
  return spec.doc + "\n\n" + spec.key + ": default " + format_value(spec, spec.default_value) + range;
}

bool listed(const Scene& scene, const std::string& effect) {
  return std::find(scene.effects.begin(), scene.effects.end(), effect) != scene.effects.end();
}

void select_stage(Inspection& in, const std::string& buffer) {
  in.stage.select(buffer);
  in.heatmap = -1;
}

// The check's results, a row a stage; a click on one shows its heat map (again: the frame).
void results_table(Inspection& in) {
  const std::vector<StageParity>& results = in.check.results();
  if (results.empty() || !ImGui::BeginTable("##parity", 5, ImGuiTableFlags_RowBg)) return;
  ImGui::TableSetupColumn("stage", ImGuiTableColumnFlags_WidthStretch);
  for (const char* h : {"max abs", "RMSE", "over tol", ""})
    ImGui::TableSetupColumn(h, ImGuiTableColumnFlags_WidthFixed);
  ImGui::TableHeadersRow();
  for (size_t i = 0; i < results.size(); ++i) {
    const StageParity& s = results[i];
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    if (ImGui::Selectable(s.name.c_str(), in.heatmap == int(i), ImGuiSelectableFlags_SpanAllColumns))
      in.heatmap = in.heatmap == int(i) ? -1 : int(i);
    tooltip(format_diff(s.name, s.diff) + "\n" + s.note + "\n(click: its heat map in place of the frame)");
    ImGui::TableNextColumn();
    ImGui::Text("%.3g", s.diff.max_abs);
    ImGui::TableNextColumn();
    ImGui::Text("%.3g", s.diff.rmse);
    ImGui::TableNextColumn();
    ImGui::Text("%.2f%%", 100 * s.diff.over_tolerance);
    ImGui::TableNextColumn();
    ImGui::TextColored(s.pass ? ImVec4(0.4f, 0.9f, 0.4f, 1) : ImVec4(1, 0.4f, 0.3f, 1), s.pass ? "pass" : "FAIL");
  }
  ImGui::EndTable();
}

// Preprocessing in the background: how long it has run against what the last one took.
void preprocessing_bar(const Session& session) {
  double s = session.preprocessing_s(), last = session.last_preprocessing_s();
  char label[96];
  std::snprintf(label, sizeof label, "preprocessing: %.1f s (the last took %.1f s)", s, last);
  ImGui::ProgressBar(last > 0 ? float(std::min(s / last, 0.99)) : 0.0f, ImVec2(-FLT_MIN, 0), label);
  tooltip("Textures, paper, curvature for the new values, made in the background; the frame shown is the last one");
}

}  // namespace

void Panels::draw(Session& session, Inspection& inspection, DrawingTool& drawing, glm::ivec2 framebuffer, float width) {
  ImGui::SetNextWindowPos(ImVec2(float(framebuffer.x) - width, 0), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(width, float(framebuffer.y)), ImGuiCond_Always);
  const ImGuiWindowFlags pinned = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse;
  ImGui::Begin("plumbago view", nullptr, pinned);
  ImGui::PushItemWidth(-ImGui::GetFontSize() * 12);  // room for the labels
  if (!session.error().empty()) ImGui::TextColored(ImVec4(1, 0.4f, 0.3f, 1), "%s", session.error().c_str());
  if (session.preprocessing()) preprocessing_bar(session);
  if (ImGui::CollapsingHeader("Scene", ImGuiTreeNodeFlags_DefaultOpen)) scene_section(session);
  if (ImGui::CollapsingHeader("Camera")) camera_section(session);
  const size_t drawn = drawing.drawing().size();
  if (drawn > std::exchange(drawn_shown_, drawn)) ImGui::SetNextItemOpen(true);  // a new stroke
  if (ImGui::CollapsingHeader("Draw on the model")) draw_section(session, drawing);
  if (ImGui::CollapsingHeader("Stage view", ImGuiTreeNodeFlags_DefaultOpen)) stage_section(session, inspection);
  if (ImGui::CollapsingHeader("Check against the reference", ImGuiTreeNodeFlags_DefaultOpen))
    reference_section(session, inspection);
  if (ImGui::CollapsingHeader("Parameters", ImGuiTreeNodeFlags_DefaultOpen)) params_section(session);
  if (ImGui::CollapsingHeader("Timing", ImGuiTreeNodeFlags_DefaultOpen)) {
    ImGui::Checkbox("render continuously", &continuous);
    tooltip("Render every frame, not only after a change: fps and the plots then follow the renderer");
    timing.draw(session.setup_ms());
  }
  if (ImGui::CollapsingHeader("Save", ImGuiTreeNodeFlags_DefaultOpen)) save_section(session);
  ImGui::PopItemWidth();
  ImGui::End();
}

void Panels::scene_section(Session& session) {
  const Scene& scene = session.scene();
  ImGui::Text("%s, %dx%d", scene.source.c_str(), scene.width, scene.height);
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    int style = int(scene.objects[i].style);
    std::string label = "object " + std::to_string(i);
    if (combo(label.c_str(), style, style_names())) session.set_style(i, Style(style));
    tooltip(scene.objects[i].mesh->name + ": the pipeline that draws it (pencil, sketchy, shaded, strokes)");
  }
  for (const EffectDef& e : effect_table()) {
    const StyleEffect* styled = style_effect(e.name);
    bool fixed = styled && (styled->automatic || !has_style(scene, styled->style));  // follows the objects' styles
    bool on = listed(scene, e.name);
    ImGui::BeginDisabled(fixed);
    if (ImGui::Checkbox(e.name.c_str(), &on)) session.set_effect(e.name, on);
    ImGui::EndDisabled();
    tooltip(e.doc + (fixed ? "\n\n(follows the objects' styles)" : ""));
  }
}

void Panels::camera_section(Session& session) {
  const Camera& c = session.scene().camera;
  ImGui::Text("eye    %8.3f %8.3f %8.3f", c.eye.x, c.eye.y, c.eye.z);
  ImGui::Text("target %8.3f %8.3f %8.3f", c.target.x, c.target.y, c.target.z);
  ImGui::Text("fov %.1f deg, near %.4g, far %.4g", c.fov_deg, c.near, c.far);
  if (ImGui::Button("Scene's camera (R)")) session.move_camera([](OrbitCamera& o) { o.reset(); });
  ImGui::SameLine();
  if (ImGui::Button("Frame the scene (F)")) session.move_camera([](OrbitCamera& o) { o.frame(); });
  ImGui::TextUnformatted("left drag: orbit; right or middle drag: pan; wheel: zoom");
}

void Panels::params_section(Session& session) {
  const std::vector<ParamSpec>& specs = param_specs();
  std::vector<std::string> passes = passes_for(session.scene().effects, session.scene().params);
  auto prefix = [&](size_t i) { return specs[i].key.substr(0, specs[i].key.find('.')); };
  for (size_t first = 0, end = 0; first < specs.size(); first = end) {
    for (end = first; end < specs.size() && prefix(end) == prefix(first);) ++end;
    const char* unused = passes_reading(passes, prefix(first)).empty() ? "  (no stage of this scene reads it)" : "";
    if (!ImGui::TreeNode(prefix(first).c_str(), "%s%s", prefix(first).c_str(), unused)) continue;
    for (size_t i = first; i < end; ++i) param_row(session, specs[i], preprocessing_reads(passes, specs[i].key));
    ImGui::TreePop();
  }
}

void Panels::param_row(Session& session, const ParamSpec& spec, bool slow) {
  ImGui::PushID(spec.key.c_str());
  double value = session.scene().params.value(spec.key);
  ImGui::BeginDisabled(value == spec.default_value);
  if (ImGui::SmallButton("reset")) {
    session.set_param(spec.key, spec.default_value);
    pending_.erase(spec.key);
  }
  ImGui::EndDisabled();
  tooltip("back to the default, " + format_value(spec, spec.default_value));
  ImGui::SameLine();
  auto it = pending_.find(spec.key);
  double shown = it != pending_.end() ? it->second : value;
  if (param_widget(spec, spec.key.c_str() + spec.key.find('.') + 1, shown)) pending_[spec.key] = shown;
  tooltip(param_tooltip(spec) + (slow ? "\n(preprocessing reads it: applied when released)" : ""));
  if (pending_.count(spec.key) && (!slow || !ImGui::IsItemActive())) {
    session.set_param(spec.key, pending_[spec.key]);
    pending_.erase(spec.key);
  }
  ImGui::PopID();
}

void Panels::stage_section(Session& session, Inspection& in) {
  const std::string& shown = in.stage.buffer();
  bool open = ImGui::BeginCombo("buffer", shown.empty() ? "final image" : shown.c_str());
  if (open) {
    if (ImGui::Selectable("final image", shown.empty())) select_stage(in, "");
    for (const auto& [name, img] : session.frame().buffers)
      if (ImGui::Selectable(name.c_str(), name == shown)) select_stage(in, name);
    ImGui::EndCombo();
  }
  tooltip(
      "Any intermediate buffer of this frame in place of the final image, as `render --dump-stages` writes its "
      "PNG; the cursor over the frame shows the buffer's raw values");
  session.keep_buffers(open || !in.stage.buffer().empty());  // an open list needs the names
  if (in.heatmap >= 0 && ImGui::Button("Back to the frame (the heat map is shown)")) in.heatmap = -1;
}

void Panels::reference_section(const Session& session, Inspection& in) {
  ImGui::BeginDisabled(in.check.running());
  if (ImGui::Button("Check against the reference")) {
    in.check.start(session.scene());
    in.heatmap = -1;
  }
  ImGui::EndDisabled();
  tooltip(
      "`plumbago compare` of this view: every stage on both backends, fed the same inputs, and whole frames; the "
      "CPU reference computes in the background");
  if (in.check.running()) ImGui::ProgressBar(float(in.check.progress()));
  if (!in.check.error().empty()) ImGui::TextColored(ImVec4(1, 0.4f, 0.3f, 1), "%s", in.check.error().c_str());
  results_table(in);
}

void Panels::save_section(Session& session) {
  auto attempt = [&](const std::string& path, auto&& write) {
    try {
      write(path);
      status_ = "wrote " + path;
    } catch (const std::exception& e) {
      status_ = e.what();
    }
  };
  ImGui::InputText("##scene", &scene_path_);
  ImGui::SameLine();
  if (ImGui::Button("Save scene")) attempt(scene_path_, [&](const std::string& p) { save_scene(session.scene(), p); });
  tooltip("The scene with this camera, parameters, effects and styles: `plumbago render FILE` draws this frame");
  ImGui::InputText("##image", &image_path_);
  ImGui::SameLine();
  if (ImGui::Button("Save frame"))
    attempt(image_path_, [&](const std::string& p) { write_image(session.frame().color, p); });
  tooltip("The rendered frame at the scene's resolution, as `plumbago render -o FILE` writes it");
  ImGui::InputText("##screenshot", &screenshot_path);
  ImGui::SameLine();
  if (ImGui::Button("Screenshot (P)")) screenshot_wanted = true;
  tooltip("What the window shows, panel included");
  ImGui::TextWrapped("%s", status_.c_str());
}

// Kalnins et al. 2002's tool: what a left drag draws (a decal or hatch in a style, a crease
// or silhouette example), undo and redo, the strokes drawn, and their files saved.
void Panels::draw_section(const Session& session, DrawingTool& drawing) {
  int drag = int(left_drag);
  ImGui::Text("left drag:");
  for (auto [mode, name, doc] : {std::tuple{LeftDrag::Orbit, "orbit", "orbits the camera"},
                                 std::tuple{LeftDrag::Draw, "draw", "draws a stroke, landed on release"},
                                 std::tuple{LeftDrag::Erase, "erase", "a click erases the decal or hatch under it"}}) {
    ImGui::SameLine();
    ImGui::RadioButton(name, &drag, int(mode));
    tooltip(std::string("Left drag over the frame ") + doc);
  }
  left_drag = LeftDrag(drag);
  int role = int(draw_settings.role);
  if (combo("stroke", role, stroke_role_names())) draw_settings.role = StrokeRole(role);
  tooltip(
      "decal: fixed on the surface where drawn; crease, silhouette: an offsets example that restyles those "
      "lines; hatching: a stroke of a hatching group, its level of detail this view's");
  const bool on_surface = draw_settings.role == StrokeRole::Decal || draw_settings.role == StrokeRole::Hatching;
  ImGui::BeginDisabled(!on_surface);
  ImGui::InputText("style", &draw_settings.style);
  tooltip("A preset (" + [] {
    std::string names;
    for (const std::string& n : stroke_style_names()) names += (names.empty() ? "" : ", ") + n;
    return names;
  }() + ") or a style file");
  ImGui::EndDisabled();
  ImGui::BeginDisabled(draw_settings.role != StrokeRole::Hatching);
  ImGui::InputInt("group", &draw_settings.group);
  draw_settings.group = std::clamp(draw_settings.group, 0, kMaxHatchingGroup);
  ImGui::Checkbox("free group", &draw_settings.free);
  ImGui::SameLine();
  ImGui::Checkbox("mobile", &draw_settings.mobile);
  tooltip(
      "Mobile hatching (Kalnins et al. 2002, §6.3): the group moves along a u-line of its object's (u, v) as "
      "the view changes, lit by a pseudo-light opposite its normal where drawn");
  ImGui::EndDisabled();
  if (ImGui::Button("Undo")) drawing.undo();
  tooltip("Ctrl+Z");
  ImGui::SameLine();
  if (ImGui::Button("Redo")) drawing.redo();
  tooltip("Ctrl+Y");
  drawn_list(session, drawing);
  ImGui::InputText("##strokes", &strokes_path_);
  ImGui::SameLine();
  if (ImGui::Button("Save strokes")) {
    try {
      drawing.save(strokes_path_);
    } catch (const std::exception& e) {
      drawing.set_status(e.what());
    }
  }
  tooltip("One stroke file a view drawn in: this path, then -2, -3, ... before its extension");
  ImGui::TextWrapped("%s", drawing.status().c_str());
}

// The strokes drawn, object by object (the examples last), each with a button that erases it.
void Panels::drawn_list(const Session& session, DrawingTool& drawing) {
  const Drawing& drawn = drawing.drawing();
  std::map<uint32_t, std::vector<size_t>> by_object;
  for (size_t i = 0; i < drawn.size(); ++i) by_object[drawn.object(i)].push_back(i);
  for (const auto& [object, strokes] : by_object) {
    if (object == kMissed)
      ImGui::TextDisabled("examples");
    else
      ImGui::TextDisabled("object %u (%s)", object, session.scene().objects.at(object).mesh->name.c_str());
    if (!stroke_rows(drawing, strokes)) return;
  }
  if (drawn.size() > 0 && !drawn.saved()) ImGui::TextDisabled("not saved");
}

// Rows of the drawn strokes `strokes`; false when one was erased (the list changed).
bool Panels::stroke_rows(DrawingTool& drawing, const std::vector<size_t>& strokes) {
  for (size_t i : strokes) {
    const DrawnStroke& s = drawing.drawing().stroke(i);
    ImGui::PushID(int(i));
    if (ImGui::SmallButton("x")) {
      drawing.erase(i);
      ImGui::PopID();
      return false;
    }
    ImGui::SameLine();
    ImGui::Text("%zu: %s%s%s, %zu points%s", i, stroke_role_names()[size_t(s.role)].c_str(),
                s.role == StrokeRole::Hatching ? (" group " + std::to_string(s.group)).c_str() : "",
                s.mobile ? " (mobile)" : "", s.points.size(),
                s.style_name.empty() ? "" : (", " + s.style_name).c_str());
    ImGui::PopID();
  }
  return true;
}

}  // namespace plumbago
