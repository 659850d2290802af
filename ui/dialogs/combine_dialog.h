#pragma once
// File › Combine…: the open project combined with a second project file by one of the IFS matrix
// operations (Thollot, Zair, Tosan & Vandorpe 1997, §4: union, concatenation, product, shuffle;
// construction/ifs_combination.h). The operations the two projects do not allow are greyed out with the
// reason; the result replaces the document as one undo step. The second file is read again
// whenever its path or its modification time changes, so a bad file shows its error inline.
#include <array>
#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "construction/ifs_combination.h"
#include "ui/base/edit_queue.h"
#include "ui/base/file_browser.h"
#include "ui/base/modeller_state.h"

namespace gridifs::ui {

class CombineDialog {
 public:
  /// Opens when state.showCombine is set (File menu); call every frame at top level.
  void draw(ModellerState& state, EditQueue& edits);
  nlohmann::json probeJson() const;

 private:
  /// The second project's file: `path_` as typed, relative paths from the open project's folder.
  std::filesystem::path resolvedPath(const ModellerState& state) const;
  /// Reads the second project again when its path or modification time changed; then (and when
  /// the document changed) works out which operations are allowed, and why not.
  void refresh(const ModellerState& state);
  void combine(ModellerState& state, EditQueue& edits);

  bool open_ = false, justOpened_ = false;
  std::string path_;
  CombineOp op_ = CombineOp::Union;
  FileBrowser browser_;

  // The second project as last read, and what each operation gives with the open document.
  std::filesystem::path loadedPath_;
  std::optional<std::filesystem::file_time_type> loadedTime_;
  std::uint64_t loadedRevision_ = 0;
  std::optional<Project> other_;
  std::string loadError_;               // why the second file could not be read (empty when it was)
  std::array<std::string, 7> reasons_;  // per operation: why it is not possible (empty when it is)
  std::string message_;                 // the last Combine's error, shown under the buttons
};

}  // namespace gridifs::ui
