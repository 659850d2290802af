#include "ui/dialogs/combine_dialog.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <iterator>
#include <system_error>

#include "base/errors.h"
#include "io/project_io.h"
#include "ui/base/widgets.h"

namespace gridifs::ui {
namespace {

namespace fs = std::filesystem;

struct OpChoice {
  CombineOp op;
  const char* label;
  const char* help;
};

// Thollot, Zair, Tosan & Vandorpe 1997, §4.1 (intersection, composition, matrix union), §4.2 (union,
// concatenation, shuffle) and §5.4 (product).
constexpr OpChoice kOps[] = {
    {CombineOp::Union, "Union", "Both function lists side by side: the attractor is the union of the two attractors"},
    {CombineOp::Concat, "Concatenation",
     "As union, and a function of the open project may be followed by one of the second: its points continue "
     "through the second project's maps"},
    {CombineOp::Product, "Product",
     "Free-form: tensor product of every pair of matrices on the sums of the control points, the attractor is the "
     "sum of the two (two curves give a patch); grid: the tensor product of the two IFS matrices"},
    {CombineOp::Shuffle, "Shuffle",
     "Tensor sum: the two IFSs' matrices interleaved on the sums of the control points; the same sum of the two "
     "attractors, reached one step at a time"},
    {CombineOp::Intersection, "Intersection",
     "Entrywise on two IFS matrices with the same states: only the maps both allow between the same states "
     "(functions with the same name are the same)"},
    {CombineOp::Composition, "Composition",
     "The product of the two IFS matrices: a map of the open project, then one of the second, between states"},
    {CombineOp::MatrixUnion, "Matrix union",
     "Entrywise on two IFS matrices with the same states: every map either allows between the same states"},
};

std::string upperFirst(std::string s) {
  if (!s.empty() && s[0] >= 'a' && s[0] <= 'z') s[0] = char(s[0] - 'a' + 'A');
  return s;
}

}  // namespace

fs::path CombineDialog::resolvedPath(const ModellerState& state) const {
  fs::path p(path_);
  if (p.is_relative() && !state.document.path().empty()) p = state.document.path().parent_path() / p;
  return p;
}

void CombineDialog::refresh(const ModellerState& state) {
  const fs::path file = resolvedPath(state);
  std::error_code ec;
  std::optional<fs::file_time_type> time;
  if (!path_.empty() && fs::is_regular_file(file, ec)) {
    const auto t = fs::last_write_time(file, ec);
    if (!ec) time = t;
  }
  const bool fileChanged = file != loadedPath_ || time != loadedTime_;
  if (fileChanged) {
    loadedPath_ = file;
    loadedTime_ = time;
    other_.reset();
    loadError_.clear();
    if (path_.empty()) {
      loadError_ = "Type or browse for the project to combine with.";
    } else if (!time) {
      loadError_ =
          fs::exists(file, ec) ? file.string() + " is not a file." : "There is no file at " + file.string() + ".";
    } else {
      try {
        other_ = loadProject(file);
      } catch (const std::exception& e) {
        loadError_ = "Cannot read " + file.filename().string() + ": " + e.what();
      }
    }
  }
  if (!fileChanged && loadedRevision_ == state.document.revision()) return;
  loadedRevision_ = state.document.revision();
  for (std::size_t i = 0; i < reasons_.size(); ++i) {
    reasons_[i].clear();
    if (!other_) continue;
    try {
      combineProjects(state.document.project(), *other_, kOps[i].op);
    } catch (const ModelError& e) {
      reasons_[i] = upperFirst(e.what()) + ".";
    }
  }
  // A choice the new pair does not allow moves to the first one it does.
  if (!reasons_[std::size_t(op_)].empty())
    for (std::size_t i = 0; i < reasons_.size(); ++i)
      if (reasons_[i].empty()) {
        op_ = kOps[i].op;
        break;
      }
}

void CombineDialog::combine(ModellerState& state, EditQueue& edits) {
  message_.clear();
  if (!other_) return;
  const CombineOp op = op_;
  Project result;
  try {
    result = combineProjects(state.document.project(), *other_, op);
  } catch (const ModelError& e) {
    message_ = upperFirst(e.what()) + ".";
    return;
  }
  const std::size_t count = result.functions.size();
  const std::string name = loadedPath_.filename().string();
  edits.commit(std::string("Combine (") + combineOpName(op) + ")", ReplaceProject{std::move(result)});
  state.activeFunction = FunctionRef(0);
  state.activeOp = -1;
  state.info("Combined with " + name + " (" + combineOpName(op) + "): " + std::to_string(count) + " functions");
  open_ = false;
  ImGui::CloseCurrentPopup();
}

void CombineDialog::draw(ModellerState& state, EditQueue& edits) {
  if (state.showCombine) {
    state.showCombine = false;
    open_ = justOpened_ = true;
    message_.clear();
    loadedRevision_ = 0;
  }
  if (!open_) return;
  const char* title = "Combine projects###combine";
  if (justOpened_) {
    ImGui::OpenPopup(title);
    justOpened_ = false;
  }
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  const float em = ImGui::GetFontSize();
  ImGui::SetNextWindowPos(ImVec2(vp->WorkPos.x + vp->WorkSize.x * 0.5f, vp->WorkPos.y + vp->WorkSize.y * 0.5f),
                          ImGuiCond_Always, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSizeConstraints(ImVec2(em * 36.0f, 0), ImVec2(em * 36.0f, vp->WorkSize.y * 0.9f));
  bool keepOpen = true;
  if (!ImGui::BeginPopupModal(title, &keepOpen, ImGuiWindowFlags_AlwaysAutoResize)) {
    open_ = false;
    return;
  }
  refresh(state);
  const std::string first = state.document.path().empty()
                                ? "the open project (unsaved)"
                                : "the open project, " + state.document.path().filename().string();
  ImGui::PushTextWrapPos(0.0f);
  ImGui::TextDisabled("Combines %s (first) with a second project file; the result replaces the open project.",
                      first.c_str());
  ImGui::PopTextWrapPos();
  ImGui::SetNextItemWidth(-em * 9.0f);
  ImGui::InputTextWithHint("##second", "second project (.gridifs)", &path_);
  state.probe.item("combine.path");
  contextHelp(state, "The second project's file; a relative path starts in the open project's folder");
  ImGui::SameLine();
  if (ImGui::Button("Browse...##second")) {
    const fs::path current = resolvedPath(state);
    std::error_code ec;
    const fs::path folder = current.has_parent_path()       ? current.parent_path()
                            : state.document.path().empty() ? fs::current_path(ec)
                                                            : state.document.path().parent_path();
    browser_.open(FileBrowser::Mode::Open, folder, {}, {".gridifs"}, "Combine with");
  }
  ImGui::SameLine();
  ImGui::TextUnformatted("Second");
  if (!loadError_.empty()) {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.35f, 1.0f), "%s", loadError_.c_str());
    ImGui::PopTextWrapPos();
    state.probe.item("combine.load_error");
  }

  ImGui::Separator();
  // One reason for all four (two kinds of project) is said once, under the list.
  bool sameReason = !reasons_[0].empty();
  for (const std::string& r : reasons_) sameReason &= r == reasons_[0];
  for (std::size_t i = 0; i < std::size(kOps); ++i) {
    const bool allowed = other_ && reasons_[i].empty();
    ImGui::BeginDisabled(!allowed);
    if (ImGui::RadioButton(kOps[i].label, op_ == kOps[i].op)) op_ = kOps[i].op;
    ImGui::EndDisabled();
    state.probe.item(std::string("combine.op.") + combineOpName(kOps[i].op));
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
      ImGui::SetTooltip("%s", reasons_[i].empty() ? kOps[i].help : reasons_[i].c_str());
    if (!reasons_[i].empty() && !sameReason) {
      ImGui::Indent();
      ImGui::PushTextWrapPos(0.0f);
      ImGui::TextDisabled("%s", reasons_[i].c_str());
      ImGui::PopTextWrapPos();
      ImGui::Unindent();
    }
  }
  if (sameReason) {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.35f, 1.0f), "%s", reasons_[0].c_str());
    ImGui::PopTextWrapPos();
  }
  const std::size_t chosen = std::size_t(op_);
  const bool canCombine = other_ && reasons_[chosen].empty();

  ImGui::Separator();
  ImGui::BeginDisabled(!canCombine);
  const bool run = ImGui::Button("Combine", ImVec2(em * 7.0f, 0));
  state.probe.item("combine.run");
  ImGui::EndDisabled();
  ImGui::SameLine();
  if (ImGui::Button("Close", ImVec2(em * 7.0f, 0))) {
    open_ = false;
    ImGui::CloseCurrentPopup();
  }
  state.probe.item("combine.close");
  if (!message_.empty()) {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.35f, 1.0f), "%s", message_.c_str());
    ImGui::PopTextWrapPos();
  }
  if (auto picked = browser_.draw(state.probe)) path_ = picked->string();
  if (run && canCombine) combine(state, edits);
  ImGui::EndPopup();
  if (!keepOpen) open_ = false;
}

nlohmann::json CombineDialog::probeJson() const {
  nlohmann::json reasons = nlohmann::json::object();
  for (std::size_t i = 0; i < std::size(kOps); ++i) reasons[combineOpName(kOps[i].op)] = reasons_[i];
  return {{"open", open_},
          {"path", path_},
          {"op", combineOpName(op_)},
          {"loaded", other_.has_value()},
          {"load_error", loadError_},
          {"reasons", reasons},
          {"message", message_}};
}

}  // namespace gridifs::ui
