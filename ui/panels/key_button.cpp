#include "ui/panels/key_button.h"

#include <imgui.h>

#include <cmath>

#include "ui/base/widgets.h"

namespace gridifs::ui {
namespace {

constexpr double kSameTime = 1e-9;  // as KeyframeTrack::setKey

std::string componentPath(const std::string& path, int components, int c) {
  return components == 1 ? path : path + "[" + std::to_string(c) + "]";
}

bool hasKeyAt(const KeyframeTrack& track, double t) {
  for (const Keyframe& k : track.keys)
    if (std::abs(k.t - t) <= kSameTime) return true;
  return false;
}

std::vector<KeyedNumber> componentsOf(const std::string& path, const double* values, int components) {
  std::vector<KeyedNumber> numbers;
  for (int c = 0; c < components; ++c)
    numbers.push_back({componentPath(path, components, c), values ? values[c] : 0.0});
  return numbers;
}

}  // namespace

KeyState keyStateOf(const Project& project, const std::vector<KeyedNumber>& numbers) {
  std::size_t animated = 0, keyed = 0;
  for (const KeyedNumber& n : numbers) {
    const auto it = project.tracks.find(n.path);
    if (it == project.tracks.end()) continue;
    ++animated;
    if (hasKeyAt(it->second, project.time)) ++keyed;
  }
  if (animated == 0) return KeyState::None;
  return keyed == numbers.size() ? KeyState::KeyHere : KeyState::Animated;
}

KeyState keyStateOf(const Project& project, const std::string& path, int components) {
  return keyStateOf(project, componentsOf(path, nullptr, components));
}

void keyButton(ModellerState& state, EditQueue& edits, const std::string& path, const double* values, int components) {
  keyButton(state, edits, path, componentsOf(path, values, components));
}

void keyButton(ModellerState& state, EditQueue& edits, const std::string& id, const std::vector<KeyedNumber>& numbers) {
  const KeyState keyState = keyStateOf(state.document.project(), numbers);
  const float h = ImGui::GetFrameHeight();
  const ImVec2 pos = ImGui::GetCursorScreenPos();
  ImGui::PushID(id.c_str());
  const bool clicked = ImGui::InvisibleButton("##key", ImVec2(h * 0.75f, h));
  ImGui::PopID();
  const bool hovered = ImGui::IsItemHovered();
  state.probe.item("key." + id);

  // The diamond: Blender's and After Effects' sign for a keyframe.
  const float r = h * 0.26f, cx = pos.x + h * 0.375f, cy = pos.y + h * 0.5f;
  const ImVec2 a(cx, cy - r), b(cx + r, cy), c(cx, cy + r), d(cx - r, cy);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImU32 key = IM_COL32(240, 200, 70, 255), faint = IM_COL32(150, 150, 160, hovered ? 255 : 110);
  switch (keyState) {
    case KeyState::KeyHere:
      draw->AddQuadFilled(a, b, c, d, key);
      break;
    case KeyState::Animated:
      draw->AddQuad(a, b, c, d, key, 1.6f);
      break;
    case KeyState::None:
      draw->AddQuad(a, b, c, d, faint, 1.2f);
      break;
  }
  if (hovered) {
    state.contextHelp = keyState == KeyState::KeyHere
                            ? "Remove the key at the current time; right-click to bind it to a controller"
                            : "Set a key at the current time (the parameter then follows the timeline); "
                              "right-click to bind it to a controller";
  }
  // Right-click: bind the number to a controller, learnt from the next one moved.
  ImGui::PushID(id.c_str());
  if (ImGui::BeginPopupContextItem("##keymenu")) {
    const Project& project = state.document.project();
    for (const KeyedNumber& n : numbers) {
      const std::string label = numbers.size() == 1 ? "Bind... (move a control)" : "Bind " + n.path + "...";
      if (ImGui::MenuItem(label.c_str())) state.learnPath = n.path;
      state.probe.item(numbers.size() == 1 ? "key.bind" : "key.bind." + n.path);
      for (const Binding& b : project.bindings)
        if (b.path == n.path && ImGui::MenuItem(("Unbind " + b.source).c_str()))
          edits.commit(RemoveBinding{b.path, b.source});
    }
    ImGui::EndPopup();
  }
  ImGui::PopID();
  if (clicked) {
    if (keyState == KeyState::KeyHere) {
      RemoveKeys remove;
      for (const KeyedNumber& n : numbers) remove.paths.push_back(n.path);
      edits.commit(std::move(remove));
    } else {
      edits.commit(SetKeys{numbers});
    }
  }
  ImGui::SameLine(0.0f, ImGui::GetStyle().ItemInnerSpacing.x);
}

}  // namespace gridifs::ui
