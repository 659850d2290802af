#pragma once
// The Construction tree window (Function › Construction tree…, key T): the project's tree of
// leaves and operations (Thollot, Zair, Tosan & Vandorpe 1997, §4.3, figure 4.2). It shows the
// nodes, adds a leaf (a project file or a part of the current functions), puts selected operands
// under a new operation, changes a node's operation and removes a node, each one undo step; a
// change the tree cannot evaluate is refused with its reason under the tree. File leaves are
// watched: when one is saved, the tree is evaluated again (one undo step, "Leaf edited") and
// the preview follows.
#include <filesystem>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "ui/base/edit_queue.h"
#include "ui/base/modeller_state.h"

namespace gridifs::ui {

class ConstructionTreePanel {
 public:
  /// Draws the window when state.showConstruction; watches the leaf files in every frame.
  void draw(ModellerState& state, EditQueue& edits);
  /// What a GUI test reads: the node count, the selection and the inline error.
  nlohmann::json probeJson(const ModellerState& state) const;

 private:
  void watchLeaves(ModellerState& state, EditQueue& edits);
  void drawNode(ModellerState& state, const ConstructionTree& tree, const ConstructionNode& node, const NodePath& path);
  void drawSelectionActions(ModellerState& state, EditQueue& edits, const ConstructionTree& tree);
  void drawAddLeaf(ModellerState& state, EditQueue& edits);
  /// Commits `edit` when the project stays valid with it; otherwise keeps the reason as the
  /// inline error and commits nothing.
  bool tryCommit(ModellerState& state, EditQueue& edits, const ProjectEdit& edit);

  std::vector<NodePath> selected_;
  std::string error_;
  std::string fileText_, partName_;
  std::vector<unsigned char> partFunctions_;  // which functions a new part takes (1: all by default)
  struct Seen {
    std::filesystem::file_time_type time;
    std::uintmax_t size = 0;
  };
  std::map<std::string, Seen> seen_;  // the leaf files as last read, by path
  double nextCheck_ = 0.0;
  std::uint64_t checkedRevision_ = 0;
  bool stale_ = false;  // the functions differ from the tree's value (edited directly)
};

}  // namespace gridifs::ui
