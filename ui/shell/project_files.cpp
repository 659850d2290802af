#include "ui/shell/project_files.h"

#include <imgui.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <sstream>

#include "base/atomic_file.h"
#include "base/bounded_read.h"
#include "explore/explore.h"
#include "io/flame_import.h"
#include "io/project_io.h"

namespace gridifs::ui {
namespace fs = std::filesystem;

namespace {

/// Autosaved work: a construction tree's file leaves are found beside the original project (or
/// where their absolute paths say, for an untitled one), not beside the autosave.
Project loadRecovered(const fs::path& autosave, const fs::path& original) {
  const std::optional<std::string> text = readBoundedFile(autosave, limits::kMaxFileBytes, "project file");
  if (!text) throw IoError(autosave.string() + " is larger than 64 MiB");
  Project project = parseProject(*text);
  if (project.construction) readConstructionLeaves(project, original);
  return project;
}

fs::path xdgFolder(const char* variable, const char* fallback) {
  if (const char* v = std::getenv(variable); v && *v && fs::path(v).is_absolute()) return fs::path(v) / "gridifs";
  const char* home = std::getenv("HOME");
  return fs::path(home && *home ? home : "/tmp") / fallback / "gridifs";
}

bool processAlive(long pid) { return pid > 0 && (::kill(pid_t(pid), 0) == 0 || errno == EPERM); }

std::string fileTime(const fs::path& file) {
  std::error_code ec;
  const auto t = fs::last_write_time(file, ec);
  if (ec) return "an earlier session";
  const auto sys = std::chrono::time_point_cast<std::chrono::system_clock::duration>(
      t - fs::file_time_type::clock::now() + std::chrono::system_clock::now());
  const std::time_t tt = std::chrono::system_clock::to_time_t(sys);
  char text[64];
  std::strftime(text, sizeof text, "%Y-%m-%d %H:%M", std::localtime(&tt));
  return text;
}

}  // namespace

AppFolders AppFolders::fromEnvironment() {
  return {xdgFolder("XDG_CONFIG_HOME", ".config"), xdgFolder("XDG_STATE_HOME", ".local/state")};
}

ProjectFiles::ProjectFiles(ModellerState& state, AppFolders folders, double autosaveSeconds)
    : state_(state), folders_(std::move(folders)), autosaveSeconds_(autosaveSeconds) {
  std::error_code ec;
  fs::create_directories(folders_.config, ec);
  fs::create_directories(folders_.state, ec);
  loadRecent();
  // The examples: assets/*.gridifs and one folder down, sorted, for File › Examples.
  const fs::path root = examplesFolder();
  for (fs::recursive_directory_iterator it(root, ec); !ec && it != fs::recursive_directory_iterator();
       it.increment(ec)) {
    if (it.depth() > 1) it.disable_recursion_pending();
    if (it->is_regular_file(ec) && it->path().extension() == ".gridifs") examples_.push_back(it->path());
  }
  std::sort(examples_.begin(), examples_.end());
}

fs::path ProjectFiles::examplesFolder() {
  if (const char* named = std::getenv("GRIDIFS_ASSETS"); named && *named) return named;
  return GRIDIFS_ASSETS_DIR;
}

void ProjectFiles::openStartProject() {
  try {
    // The default example has no files of its own, so it opens as an untitled copy: Save asks
    // where, and the example stays as it is.
    state_.document.reset(loadProject(examplesFolder() / "default.gridifs"));
  } catch (const std::exception&) {
    try {
      state_.document.reset(randomWorld({ExploreStyle::Grid, 0, 1}).project);
    } catch (const std::exception&) {
      return;  // the one-grid project stays
    }
  }
  state_.forgetDocumentViewState();
  state_.info("Welcome: File > New random world or View > Explore (E) find new forms; File > Examples has more");
}

void ProjectFiles::requestOpenExample(const fs::path& file) { request(Open{file}); }

fs::path ProjectFiles::recoveryFile() const {
  return folders_.state / ("recovery-" + std::to_string(::getpid()) + ".gridifs");
}

std::string ProjectFiles::windowTitle() const {
  const Document& d = state_.document;
  const std::string name = d.path().empty() ? "untitled" : d.path().filename().string();
  return name + (d.dirty() ? "*" : "") + " — GridIFS";
}

bool ProjectFiles::modalOpen() const { return browser_.isOpen() || promptUnsaved_ || showError_ || offerRecovery_; }

void ProjectFiles::showError(const std::string& title, const std::string& message) {
  errorTitle_ = title;
  errorText_ = message;
  showError_ = true;
  state_.error(title + ": " + message);
}

bool ProjectFiles::load(const fs::path& file) {
  try {
    Project project = loadProject(file);
    state_.document.reset(std::move(project), fs::absolute(file));
    state_.forgetDocumentViewState();
    addRecent(fs::absolute(file));
    state_.info("Opened " + file.string());
    return true;
  } catch (const ModelError& e) {
    showError("Could not open " + file.filename().string(), file.string() + ": " + e.what());
  } catch (const IoError& e) {
    showError("Could not open " + file.filename().string(), e.what());
  } catch (const std::exception& e) {
    showError("Could not open " + file.filename().string(), e.what());
  }
  return false;
}

void ProjectFiles::openAtStartup(const fs::path& file) { load(file); }

void ProjectFiles::checkForRecovery() {
  std::error_code ec;
  for (fs::directory_iterator it(folders_.state, ec); !ec && it != fs::directory_iterator(); it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.rfind("recovery-", 0) != 0 || it->path().extension() != ".gridifs") continue;
    const long pid = std::strtol(name.c_str() + 9, nullptr, 10);
    if (processAlive(pid) && pid != long(::getpid())) continue;  // another running session's
    Recovery r{it->path(), {}, fileTime(it->path())};
    std::ifstream original(fs::path(it->path()).replace_extension(".path"));
    std::string line;
    if (std::getline(original, line)) r.original = line;
    recoveries_.push_back(r);
  }
  offerRecovery_ = !recoveries_.empty();
}

void ProjectFiles::request(Action action) {
  const bool losesWork = state_.document.dirty();
  if (losesWork) {
    pending_ = std::move(action);
    promptUnsaved_ = true;
    return;
  }
  perform(action);
}

void ProjectFiles::perform(const Action& action) {
  if (std::holds_alternative<New>(action)) {
    state_.document.reset(defaultNewProject());
    state_.forgetDocumentViewState();
    state_.info("New project");
  } else if (const auto* open = std::get_if<Open>(&action)) {
    if (open->file)
      load(*open->file);
    else {
      browserForSave_ = false;
      browserForFlame_ = false;
      const fs::path folder = state_.document.path().empty() ? fs::path() : state_.document.path().parent_path();
      browser_.open(FileBrowser::Mode::Open, folder);
    }
  } else if (std::holds_alternative<ImportFlame>(action)) {
    browserForSave_ = false;
    browserForFlame_ = true;
    const fs::path folder = state_.document.path().empty() ? fs::path() : state_.document.path().parent_path();
    browser_.open(FileBrowser::Mode::Open, folder, {}, {".flame", ".flam3", ".xml"}, "Import flame");
  } else {
    quitConfirmed_ = true;
  }
}

void ProjectFiles::requestImportFlameDialog() { request(ImportFlame{}); }

bool ProjectFiles::importFlame(const fs::path& file, const std::string& genome) {
  try {
    // Inline palettes are kept with the application's state: the document has no folder yet.
    FlameFileImport imported = importFlameFile(file, genome, folders_.state / "palettes");
    state_.document.reset(defaultNewProject());
    state_.document.apply("Import flame", ReplaceProject{std::move(imported.project)});
    state_.forgetDocumentViewState();
    std::string message = "Imported " + imported.description;
    for (const std::string& w : imported.warnings) message += "; " + w;
    state_.info(message);
    return true;
  } catch (const std::exception& e) {
    showError("Could not import " + file.filename().string(), e.what());
  }
  return false;
}

void ProjectFiles::requestNew() { request(New{}); }
void ProjectFiles::requestOpenDialog() { request(Open{}); }
void ProjectFiles::requestOpen(const fs::path& file) { request(Open{file}); }
void ProjectFiles::requestQuit() { request(Quit{}); }

bool ProjectFiles::save() {
  if (state_.document.path().empty()) {
    saveAsDialog();
    return false;
  }
  return saveTo(state_.document.path());
}

void ProjectFiles::saveAsDialog() {
  browserForSave_ = true;
  const fs::path current = state_.document.path();
  browser_.open(FileBrowser::Mode::Save, current.empty() ? fs::path() : current.parent_path(),
                current.empty() ? "untitled.gridifs" : current.filename().string());
}

bool ProjectFiles::saveTo(const fs::path& file) {
  if (state_.document.inGesture()) state_.document.endGesture();
  try {
    saveProject(state_.document.project(), file);
    state_.document.markSaved(fs::absolute(file));
    addRecent(fs::absolute(file));
    finishAutosave();  // else it could write the recovery file again after this removal
    std::error_code ec;
    fs::remove(recoveryFile(), ec);
    state_.info("Saved " + file.string());
    return true;
  } catch (const std::exception& e) {
    showError("Could not save " + file.filename().string(),
              std::string(e.what()) + " The file on disk was not changed.");
    return false;
  }
}

bool ProjectFiles::finishAutosave() {
  if (!autosave_.valid()) return true;
  const std::string error = autosave_.get();
  if (!error.empty()) {
    state_.error("Autosave failed: " + error);
    return false;
  }
  autosavedRevision_ = autosavingRevision_;
  return true;
}

void ProjectFiles::tick() {
  if (autosave_.valid() && autosave_.wait_for(std::chrono::seconds(0)) == std::future_status::ready) finishAutosave();
  const Document& d = state_.document;
  if (!d.dirty()) {
    if (autosavedRevision_ != 0 || autosave_.valid()) {
      finishAutosave();
      std::error_code ec;
      fs::remove(recoveryFile(), ec);
      fs::remove(fs::path(recoveryFile()).replace_extension(".path"), ec);
      autosavedRevision_ = 0;
    }
    lastAutosave_ = state_.now;
    return;
  }
  if (autosave_.valid()) return;  // one at a time; the next tick catches up
  if (state_.now - lastAutosave_ < autosaveSeconds_ || d.revision() == autosavedRevision_) return;
  lastAutosave_ = state_.now;
  autosavingRevision_ = d.revision();
  autosave_ = std::async(std::launch::async, [project = d.project(), original = d.path(), file = recoveryFile()] {
    try {
      saveProject(project, file);
      std::error_code ec;
      fs::remove(fs::path(file).concat("~"), ec);
      writeFileAtomically(fs::path(file).replace_extension(".path"), original.string() + "\n");
      return std::string();
    } catch (const std::exception& e) {
      return std::string(e.what());
    }
  });
}

void ProjectFiles::shutdown() {
  finishAutosave();
  std::error_code ec;
  fs::remove(recoveryFile(), ec);
  fs::remove(fs::path(recoveryFile()).concat("~"), ec);
  fs::remove(fs::path(recoveryFile()).replace_extension(".path"), ec);
}

void ProjectFiles::draw(EditQueue& edits) {
  if (auto chosen = browser_.draw(state_.probe)) {
    if (browserForSave_) {
      if (saveTo(*chosen) && afterSave_) {
        const Action next = *afterSave_;
        afterSave_.reset();
        perform(next);
      }
    } else if (browserForFlame_) {
      browserForFlame_ = false;
      importFlame(*chosen);
    } else {
      load(*chosen);
    }
  }
  if (!browser_.isOpen()) afterSave_.reset();

  const ImGuiViewport* vp = ImGui::GetMainViewport();
  const ImVec2 middle(vp->WorkPos.x + vp->WorkSize.x * 0.5f, vp->WorkPos.y + vp->WorkSize.y * 0.5f);
  const ImVec2 button(ImGui::GetFontSize() * 8, 0);

  if (promptUnsaved_) ImGui::OpenPopup("Unsaved changes");
  ImGui::SetNextWindowPos(middle, ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  if (ImGui::BeginPopupModal("Unsaved changes", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    const std::string name =
        state_.document.path().empty() ? "untitled project" : state_.document.path().filename().string();
    ImGui::Text("Save the changes to %s first?", name.c_str());
    ImGui::TextDisabled("Otherwise they are lost.");
    ImGui::Spacing();
    if (ImGui::Button("Save", button)) {
      promptUnsaved_ = false;
      ImGui::CloseCurrentPopup();
      if (state_.document.path().empty()) {
        afterSave_ = pending_;
        saveAsDialog();
      } else if (save() && pending_) {
        perform(*pending_);
      }
      pending_.reset();
    }
    state_.probe.item("unsaved.save");
    ImGui::SameLine();
    if (ImGui::Button("Don't save", button)) {
      promptUnsaved_ = false;
      ImGui::CloseCurrentPopup();
      if (pending_) perform(*pending_);
      pending_.reset();
    }
    state_.probe.item("unsaved.discard");
    ImGui::SameLine();
    if (ImGui::Button("Cancel", button) || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) {
      promptUnsaved_ = false;
      pending_.reset();
      ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
  }

  if (showError_) ImGui::OpenPopup("Problem###error");
  ImGui::SetNextWindowPos(middle, ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSizeConstraints(ImVec2(ImGui::GetFontSize() * 20, 0), ImVec2(ImGui::GetFontSize() * 40, FLT_MAX));
  if (ImGui::BeginPopupModal("Problem###error", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::TextColored(ImVec4(1.0f, 0.55f, 0.4f, 1.0f), "%s", errorTitle_.c_str());
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 38);
    ImGui::TextUnformatted(errorText_.c_str());
    ImGui::PopTextWrapPos();
    ImGui::Spacing();
    if (ImGui::Button("OK", button) || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter)) ||
        ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) {
      showError_ = false;
      ImGui::CloseCurrentPopup();
    }
    state_.probe.item("error.ok");
    ImGui::EndPopup();
  }

  if (offerRecovery_ && !showError_) ImGui::OpenPopup("Recover unsaved work?");
  ImGui::SetNextWindowPos(middle, ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  if (ImGui::BeginPopupModal("Recover unsaved work?", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    const Recovery& r = recoveries_.front();
    ImGui::Text("GridIFS did not close properly last time.");
    ImGui::Text("Unsaved work on %s was autosaved at %s.",
                r.original.empty() ? "an untitled project" : r.original.filename().c_str(), r.when.c_str());
    ImGui::Spacing();
    auto discardAll = [&] {
      std::error_code ec;
      for (const Recovery& each : recoveries_) {
        fs::remove(each.file, ec);
        fs::remove(fs::path(each.file).replace_extension(".path"), ec);
      }
      recoveries_.clear();
      offerRecovery_ = false;
      ImGui::CloseCurrentPopup();
    };
    if (ImGui::Button("Recover", button)) {
      try {
        Project recovered = loadRecovered(r.file, r.original);
        Project base = defaultNewProject();
        fs::path original = r.original;
        std::error_code ec;
        if (!original.empty() && fs::exists(original, ec)) {
          try {
            base = loadProject(original);
          } catch (const std::exception&) {
          }
        }
        state_.document.reset(base, original);
        state_.forgetDocumentViewState();
        edits.commit("Recover unsaved work", ReplaceProject{recovered});
        state_.info("Recovered unsaved work from " + r.when + "; save it to keep it.");
      } catch (const std::exception& e) {
        showError("Could not recover", e.what());
      }
      discardAll();
    }
    state_.probe.item("recovery.recover");
    ImGui::SameLine();
    if (ImGui::Button("Discard", button)) discardAll();
    ImGui::EndPopup();
  }
}

void ProjectFiles::addRecent(const fs::path& file) {
  std::erase(recent_, file);
  recent_.insert(recent_.begin(), file);
  if (recent_.size() > 10) recent_.resize(10);
  saveRecent();
}

void ProjectFiles::loadRecent() {
  std::ifstream in(folders_.config / "recent-files.txt");
  std::string line;
  while (std::getline(in, line) && recent_.size() < 10)
    if (!line.empty()) recent_.push_back(line);
}

void ProjectFiles::saveRecent() const {
  std::string text;
  for (const fs::path& p : recent_) text += p.string() + "\n";
  try {
    writeFileAtomically(folders_.config / "recent-files.txt", text);
  } catch (const IoError&) {
    // The recent-files list is a convenience: a read-only config folder must not stop a save.
  }
}

}  // namespace gridifs::ui
