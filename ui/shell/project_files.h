#pragma once
// Files for the modeller: New/Open/Save/Save As, recent files, the prompt
// before losing unsaved work, load and save errors shown in the window (never fatal), and
// autosave to a recovery file with an offer to recover after a crash.
#include <filesystem>
#include <future>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "ui/base/edit_queue.h"
#include "ui/base/file_browser.h"
#include "ui/base/modeller_state.h"

namespace gridifs::ui {

/// Where the modeller keeps its settings (XDG base directories).
struct AppFolders {
  std::filesystem::path config;  // $XDG_CONFIG_HOME/gridifs: imgui.ini, recent files
  std::filesystem::path state;   // $XDG_STATE_HOME/gridifs: recovery files
  static AppFolders fromEnvironment();
};

class ProjectFiles {
 public:
  ProjectFiles(ModellerState& state, AppFolders folders, double autosaveSeconds);

  /// Opens `file` at startup; a failure shows an error and keeps the default project.
  void openAtStartup(const std::filesystem::path& file);
  /// A start without a file: the examples' default project (InterIFS's twisted functions) as a new,
  /// untitled project, or a random world where the examples are not at hand; never a one-dot
  /// preview.
  void openStartProject();
  /// The example projects (assets/ and its folders), for File › Examples.
  const std::vector<std::filesystem::path>& examples() const { return examples_; }
  /// Opens an example as File › Open opens a file (asking first about unsaved work).
  void requestOpenExample(const std::filesystem::path& file);
  /// Looks for recovery files left by a session that did not exit cleanly.
  void checkForRecovery();

  void requestNew();
  void requestOpenDialog();
  /// File › Import flame…: asks for a .flame file and opens its first genome as a new,
  /// unsaved document (one undo step); errors are shown in the window.
  void requestImportFlameDialog();
  /// Imports `file`'s genome `genome` (index or name; empty: the first) as a new document.
  bool importFlame(const std::filesystem::path& file, const std::string& genome = {});
  void requestOpen(const std::filesystem::path& file);
  void requestQuit();
  /// Saves to the document's file, or asks for one. Returns false when nothing was saved.
  bool save();
  void saveAsDialog();
  /// Saves atomically to `file` (core: temporary + rename, `~` backup). Errors are shown.
  bool saveTo(const std::filesystem::path& file);

  /// Draws the dialogs (browser, unsaved-work prompt, errors, recovery offer).
  void draw(EditQueue& edits);
  /// Autosaves when due. Call once per frame.
  void tick();
  /// Removes this session's recovery file (clean exit).
  void shutdown();

  bool quitConfirmed() const { return quitConfirmed_; }
  bool modalOpen() const;
  std::string windowTitle() const;
  const std::vector<std::filesystem::path>& recent() const { return recent_; }
  /// Where the examples are: GRIDIFS_ASSETS when set, else the source tree's assets/.
  static std::filesystem::path examplesFolder();
  const AppFolders& folders() const { return folders_; }

 private:
  struct New {};
  struct Open {
    std::optional<std::filesystem::path> file;  // none: ask with the browser
  };
  struct Quit {};
  struct ImportFlame {};
  using Action = std::variant<New, Open, Quit, ImportFlame>;

  void request(Action action);
  void perform(const Action& action);
  bool load(const std::filesystem::path& file);
  void addRecent(const std::filesystem::path& file);
  void loadRecent();
  void saveRecent() const;
  void showError(const std::string& title, const std::string& message);
  std::filesystem::path recoveryFile() const;
  /// Waits for the autosave in flight (if any) and reports its error; true when none failed.
  bool finishAutosave();

  ModellerState& state_;
  AppFolders folders_;
  double autosaveSeconds_;
  double lastAutosave_ = 0.0;
  std::uint64_t autosavedRevision_ = 0;
  // The autosave runs on a worker thread (serialising and syncing a large project to a busy
  // disk can take longer than a frame); it holds its own copy of the project. Its result is an
  // error message, empty on success.
  std::future<std::string> autosave_;
  std::uint64_t autosavingRevision_ = 0;
  FileBrowser browser_;
  bool browserForSave_ = false;
  bool browserForFlame_ = false;
  std::optional<Action> pending_;  // waits for the unsaved-work prompt
  bool promptUnsaved_ = false;
  std::optional<Action> afterSave_;  // runs once a Save As from the prompt succeeded
  std::string errorTitle_, errorText_;
  bool showError_ = false;
  struct Recovery {
    std::filesystem::path file, original;
    std::string when;
  };
  std::vector<Recovery> recoveries_;
  bool offerRecovery_ = false;
  bool quitConfirmed_ = false;
  std::vector<std::filesystem::path> recent_;
  std::vector<std::filesystem::path> examples_;
};

}  // namespace gridifs::ui
