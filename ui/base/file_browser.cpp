#include "ui/base/file_browser.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <system_error>

#include "ui/base/test_probe.h"
#include "ui/base/widgets.h"

namespace gridifs::ui {
namespace fs = std::filesystem;

void FileBrowser::open(Mode mode, const fs::path& folder, const std::string& fileName,
                       std::vector<std::string> extensions, std::string title) {
  mode_ = mode;
  extensions_ = std::move(extensions);
  title_ = std::move(title);
  open_ = justOpened_ = true;
  fileName_ = fileName;
  error_.clear();
  std::error_code ec;
  fs::path start = folder.empty() ? fs::current_path(ec) : folder;
  if (!fs::is_directory(start, ec)) start = fs::current_path(ec);
  enter(start);
}

void FileBrowser::enter(const fs::path& folder) {
  std::error_code ec;
  fs::path canonical = fs::weakly_canonical(folder, ec);
  if (ec) canonical = folder;
  std::vector<Entry> entries;
  fs::directory_iterator it(canonical, fs::directory_options::skip_permission_denied, ec);
  if (ec) {
    error_ = "Cannot list " + canonical.string() + ": " + ec.message();
    folderText_ = folder_.string();
    return;
  }
  for (; it != fs::directory_iterator(); it.increment(ec)) {
    if (ec) break;
    const std::string name = it->path().filename().string();
    if (name.empty() || name[0] == '.') continue;
    std::error_code typeError;
    const bool folderEntry = it->is_directory(typeError);
    if (!folderEntry && !showAll_ &&
        std::find(extensions_.begin(), extensions_.end(), it->path().extension().string()) == extensions_.end())
      continue;
    entries.push_back({name, folderEntry});
  }
  std::sort(entries.begin(), entries.end(),
            [](const Entry& a, const Entry& b) { return a.folder != b.folder ? a.folder : a.name < b.name; });
  entries_ = std::move(entries);
  folder_ = canonical;
  folderText_ = folder_.string();
  error_.clear();
}

std::optional<fs::path> FileBrowser::confirm() {
  if (fileName_.empty()) {
    error_ = "Choose a file name.";
    return std::nullopt;
  }
  fs::path file = fs::path(fileName_).is_absolute() ? fs::path(fileName_) : folder_ / fileName_;
  if (mode_ == Mode::Save && file.extension().empty()) file += ".gridifs";
  std::error_code ec;
  if (mode_ == Mode::Open && !fs::is_regular_file(file, ec)) {
    error_ = "No such file: " + file.string();
    return std::nullopt;
  }
  if (fs::is_directory(file, ec)) {
    enter(file);
    fileName_.clear();
    return std::nullopt;
  }
  open_ = false;
  ImGui::CloseCurrentPopup();
  return file;
}

std::optional<fs::path> FileBrowser::draw(UiProbe& probe) {
  if (!open_) return std::nullopt;
  const std::string titleText =
      (title_.empty() ? (mode_ == Mode::Open ? "Open project" : "Save project as") : title_) + "###browser";
  const char* title = titleText.c_str();
  if (justOpened_) {
    ImGui::OpenPopup(title);
    justOpened_ = false;
  }
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(vp->WorkPos.x + vp->WorkSize.x * 0.5f, vp->WorkPos.y + vp->WorkSize.y * 0.5f),
                          ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  // Never larger than the window: on a small screen the list scrolls instead.
  ImGui::SetNextWindowSize(ImVec2(std::min(ImGui::GetFontSize() * 40, vp->WorkSize.x * 0.95f),
                                  std::min(ImGui::GetFontSize() * 30, vp->WorkSize.y * 0.9f)),
                           ImGuiCond_Appearing);
  std::optional<fs::path> chosen;
  bool keepOpen = true;
  if (ImGui::BeginPopupModal(title, &keepOpen)) {
    if (ImGui::ArrowButton("##up", ImGuiDir_Up)) enter(folder_.parent_path());
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Parent folder");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-ImGui::CalcTextSize("All files").x - ImGui::GetFrameHeight() * 2);
    if (ImGui::InputText("##folder", &folderText_, ImGuiInputTextFlags_EnterReturnsTrue)) enter(folderText_);
    ImGui::SameLine();
    if (ImGui::Checkbox("All files", &showAll_)) enter(folder_);

    const float footer = ImGui::GetFrameHeightWithSpacing() * 2 + ImGui::GetTextLineHeightWithSpacing() * 1.5f;
    if (ImGui::BeginChild("entries", ImVec2(0, -footer), true)) {
      std::optional<fs::path> enterFolder;
      for (const Entry& e : entries_) {
        const std::string label = (e.folder ? "[dir]  " : "       ") + e.name;
        if (ImGui::Selectable(label.c_str(), !e.folder && e.name == fileName_, ImGuiSelectableFlags_AllowDoubleClick)) {
          if (e.folder) {
            if (ImGui::IsMouseDoubleClicked(0)) enterFolder = folder_ / e.name;
          } else {
            fileName_ = e.name;
            if (ImGui::IsMouseDoubleClicked(0)) chosen = confirm();
          }
        }
      }
      if (entries_.empty())
        ImGui::TextDisabled("%s",
                            showAll_ ? "(empty folder)" : ("(no " + extensions_.front() + " files here)").c_str());
      if (enterFolder) enter(*enterFolder);
    }
    ImGui::EndChild();
    ImGui::SetNextItemWidth(-ImGui::CalcTextSize("File name").x - ImGui::GetStyle().ItemInnerSpacing.x * 2);
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
    const bool enter = ImGui::InputText("File name", &fileName_, ImGuiInputTextFlags_EnterReturnsTrue);
    probe.item("browser.fileName");
    if (enter && !chosen) chosen = confirm();
    if (!error_.empty())
      ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.35f, 1.0f), "%s", error_.c_str());
    else if (mode_ == Mode::Save && !fileName_.empty()) {
      std::error_code ec;
      fs::path file = folder_ / fileName_;
      if (file.extension().empty()) file += ".gridifs";
      if (fs::exists(file, ec))
        ImGui::TextDisabled("Saving replaces %s (the old one is kept as %s~).", file.filename().c_str(),
                            file.filename().c_str());
      else
        ImGui::TextDisabled(" ");
    } else {
      ImGui::TextDisabled(" ");
    }
    if (ImGui::Button(mode_ == Mode::Open ? "Open" : "Save", ImVec2(ImGui::GetFontSize() * 6, 0)) && !chosen)
      chosen = confirm();
    ImGui::SameLine();
    if (ImGui::Button("Cancel", ImVec2(ImGui::GetFontSize() * 6, 0)) ||
        ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) {
      open_ = false;
      ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
  }
  if (!keepOpen) open_ = false;
  return chosen;
}

}  // namespace gridifs::ui
