#include "apps/viewer/timing.hpp"

#include <imgui.h>

#include <algorithm>
#include <cfloat>

#include "common/core/passes.hpp"

namespace plumbago {
namespace {

constexpr double kSeconds = 10;  // plotted history

// A plot as wide as the space left (ImGui 1.86's PlotLines reads no negative width).
void plot(const char* id, const std::vector<float>& values, float height) {
  ImGui::PushItemWidth(-FLT_MIN);
  ImGui::PlotLines(id, values.data(), int(values.size()), 0, nullptr, 0.0f, FLT_MAX, ImVec2(0, height));
  ImGui::PopItemWidth();
}

}  // namespace

void Timing::add(const Frame& frame, double wall_ms) {
  double now = clock_.ms() / 1000;
  samples_.push_back({now, wall_ms, frame.ran});
  while (samples_.front().at_s < now - kSeconds) samples_.pop_front();
}

std::vector<float> Timing::history(const std::string& pass) const {
  std::vector<float> out;
  for (const Sample& s : samples_) {
    if (pass.empty()) out.push_back(float(s.wall_ms));
    for (const PassTime& p : s.ran)
      if (p.name == pass) out.push_back(float(p.ms));
  }
  return out;
}

void Timing::draw(double setup_ms) const {
  if (samples_.empty()) {
    ImGui::TextUnformatted("no frame yet");
    return;
  }
  double now = clock_.ms() / 1000;
  long last_second = std::count_if(samples_.begin(), samples_.end(), [&](const Sample& s) { return s.at_s > now - 1; });
  const Sample& last = samples_.back();
  ImGui::Text("last frame %.1f ms (%.1f fps back to back); %ld drawn in the last second", last.wall_ms,
              1000 / last.wall_ms, last_second);
  ImGui::Text("last new renderer: %.0f ms (preprocessing, programs, geometry)", setup_ms);
  plot("##frame", history(""), 48);
  draw_passes(false);
  if (ImGui::TreeNode("preprocessing (made once, kept across camera moves)")) {
    draw_passes(true);
    ImGui::TreePop();
  }
}

void Timing::draw_passes(bool preprocessing) const {
  if (!ImGui::BeginTable(preprocessing ? "##pre" : "##passes", 3)) return;
  ImGui::TableSetupColumn("pass", ImGuiTableColumnFlags_WidthFixed);
  ImGui::TableSetupColumn("ms", ImGuiTableColumnFlags_WidthFixed);
  ImGui::TableSetupColumn("history", ImGuiTableColumnFlags_WidthStretch);
  for (const PassTime& p : samples_.back().ran) {
    if (is_preprocessing(p.name) != preprocessing) continue;
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(p.name.c_str());
    ImGui::TableNextColumn();
    ImGui::Text("%8.2f ms", p.ms);
    ImGui::TableNextColumn();
    ImGui::PushID(p.name.c_str());
    plot("##history", history(p.name), ImGui::GetTextLineHeight());
    ImGui::PopID();
  }
  ImGui::EndTable();
}

}  // namespace plumbago
