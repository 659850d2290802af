#pragma once
// An in-app file browser: ImGui over std::filesystem, so opening and saving
// work the same on every platform and under Xvfb, without a desktop portal.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace gridifs::ui {

struct UiProbe;

class FileBrowser {
 public:
  enum class Mode { Open, Save };
  /// Shows the browser (as a modal) from the next draw() on, listing files with one of
  /// `extensions` (and folders); `title` names the action ("Import flame").
  void open(Mode mode, const std::filesystem::path& folder, const std::string& fileName = {},
            std::vector<std::string> extensions = {".gridifs"}, std::string title = {});
  bool isOpen() const { return open_; }
  /// Draws the browser while open; returns the chosen file once, when the artist confirms.
  std::optional<std::filesystem::path> draw(UiProbe& probe);

 private:
  struct Entry {
    std::string name;
    bool folder = false;
  };
  void enter(const std::filesystem::path& folder);
  std::optional<std::filesystem::path> confirm();

  Mode mode_ = Mode::Open;
  bool open_ = false, justOpened_ = false, showAll_ = false;
  std::filesystem::path folder_;
  std::string folderText_, fileName_, error_;
  std::vector<Entry> entries_;
  std::vector<std::string> extensions_{".gridifs"};
  std::string title_;
};

}  // namespace gridifs::ui
