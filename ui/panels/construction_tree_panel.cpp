// The Construction tree window (ui/panels/construction_tree_panel.h): the tree of Thollot, Zair,
// Tosan & Vandorpe's figure 4.2 drawn as nested rows, with the named edits of
// edit/construction_edits.h behind its buttons.
#include "ui/panels/construction_tree_panel.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>

#include "construction/construction_evaluation.h"
#include "io/project_io.h"
#include "schema/validation.h"
#include "ui/base/widgets.h"

namespace gridifs::ui {
namespace {

namespace fs = std::filesystem;

/// "root", "0", "0.1": a node's name in the probe and its ImGui id.
std::string pathId(const NodePath& path) {
  if (path.empty()) return "root";
  std::string out;
  for (std::size_t i = 0; i < path.size(); ++i) out += (i ? "." : "") + std::to_string(path[i]);
  return out;
}

std::size_t functionCount(const ConstructionTree& tree, const ConstructionNode& node) {
  if (node.kind == ConstructionNode::Kind::File) return node.loaded ? node.loaded->functions.size() : 0;
  if (node.kind == ConstructionNode::Kind::Part) {
    const ConstructionPart* part = findPart(tree, node.part);
    return part && part->content ? part->content->functions.size() : 0;
  }
  return 0;
}

void collectFiles(const ConstructionNode& node, std::vector<std::string>& files) {
  if (node.kind == ConstructionNode::Kind::File) files.push_back(node.file);
  for (const ConstructionNode& child : node.children) collectFiles(child, files);
}

/// The path a file leaf stores: relative to the project's folder when the project has a file,
/// absolute otherwise (an untitled project has no folder to start from).
std::string leafPath(const ModellerState& state, const std::string& typed) {
  const fs::path file = fs::absolute(state.projectFolder() / typed).lexically_normal();
  if (state.document.path().empty()) return file.string();
  return file.lexically_relative(fs::absolute(state.projectFolder()).lexically_normal()).generic_string();
}

std::string freePartName(const ConstructionTree* tree) {
  for (int i = 1;; ++i) {
    const std::string name = "part" + std::to_string(i);
    if (!tree || !findPart(*tree, name)) return name;
  }
}

}  // namespace

bool ConstructionTreePanel::tryCommit(ModellerState& state, EditQueue& edits, const ProjectEdit& edit) {
  try {
    Project next = state.document.project();
    applyEdit(next, edit);
    validateProject(next);
  } catch (const std::exception& e) {
    error_ = e.what();
    return false;
  }
  error_.clear();
  edits.commit(edit);
  return true;
}

void ConstructionTreePanel::watchLeaves(ModellerState& state, EditQueue& edits) {
  const Project& project = state.document.project();
  if (!project.construction || state.now < nextCheck_ || state.document.inGesture()) return;
  nextCheck_ = state.now + 0.5;
  std::vector<std::string> files;
  collectFiles(project.construction->root, files);
  bool changed = false;
  for (const std::string& name : files) {
    const fs::path file = state.projectFolder() / name;
    std::error_code ec;
    Seen now{fs::last_write_time(file, ec), 0};
    if (ec) continue;
    now.size = fs::file_size(file, ec);
    const std::string key = fs::absolute(file).lexically_normal().string();
    auto it = seen_.find(key);
    if (it == seen_.end()) {
      seen_[key] = now;  // first sight: the tree was read from this version
      continue;
    }
    if (it->second.time != now.time || it->second.size != now.size) changed = true;
    it->second = now;
  }
  if (!changed) return;
  try {
    Project reread = project;
    readConstructionLeaves(reread, state.document.path().empty() ? fs::path() : state.document.path());
    tryCommit(state, edits, ReloadConstructionLeaves{*reread.construction});
  } catch (const std::exception& e) {
    error_ = e.what();  // a leaf saved half-way or invalid: the tree keeps its last value
  }
}

void ConstructionTreePanel::drawNode(ModellerState& state, const ConstructionTree& tree, const ConstructionNode& node,
                                     const NodePath& path) {
  std::string text;
  if (node.kind == ConstructionNode::Kind::Operation) {
    const ConstructionOpSpec* spec = findConstructionOp(node.op);
    text = spec ? spec->label : node.op;
  } else {
    text = node.kind == ConstructionNode::Kind::File ? "file " + node.file : "part " + node.part;
    const std::size_t n = functionCount(tree, node);
    text += "  (" + std::to_string(n) + (n == 1 ? " function)" : " functions)");
  }
  const bool isSelected = std::find(selected_.begin(), selected_.end(), path) != selected_.end();
  ImGuiTreeNodeFlags flags = ImGuiTreeNodeFlags_DefaultOpen | ImGuiTreeNodeFlags_OpenOnArrow |
                             ImGuiTreeNodeFlags_SpanAvailWidth | (isSelected ? ImGuiTreeNodeFlags_Selected : 0);
  if (node.children.empty()) flags |= ImGuiTreeNodeFlags_Leaf | ImGuiTreeNodeFlags_NoTreePushOnOpen;
  const bool open = ImGui::TreeNodeEx(pathId(path).c_str(), flags, "%s", text.c_str());
  state.probe.item("tree.node." + pathId(path));
  if (ImGui::IsItemClicked() && !ImGui::IsItemToggledOpen()) {
    if (ImGui::GetIO().KeyCtrl || ImGui::GetIO().KeyShift) {
      if (isSelected)
        std::erase(selected_, path);
      else
        selected_.push_back(path);
    } else {
      selected_ = {path};
    }
  }
  if (node.kind == ConstructionNode::Kind::Operation && ImGui::IsItemHovered()) {
    if (const ConstructionOpSpec* spec = findConstructionOp(node.op)) ImGui::SetTooltip("%s", spec->help);
  }
  if (!open || node.children.empty()) return;
  for (std::size_t i = 0; i < node.children.size(); ++i) {
    NodePath child = path;
    child.push_back(i);
    drawNode(state, tree, node.children[i], child);
  }
  ImGui::TreePop();
}

void ConstructionTreePanel::drawSelectionActions(ModellerState& state, EditQueue& edits, const ConstructionTree& tree) {
  std::erase_if(selected_, [&](const NodePath& p) { return findNode(tree, p) == nullptr; });
  if (selected_.empty()) {
    ImGui::TextDisabled("Click a node to change it; Ctrl+click selects several operands.");
    return;
  }
  if (selected_.size() == 1) {
    const NodePath path = selected_.front();
    const ConstructionNode& node = *findNode(tree, path);
    if (node.kind == ConstructionNode::Kind::Operation) {
      ImGui::TextUnformatted("Operation:");
      for (const ConstructionOpSpec& spec : constructionOps()) {
        ImGui::SameLine();
        if (ImGui::RadioButton(spec.name, node.op == spec.name) && node.op != spec.name)
          tryCommit(state, edits, SetConstructionOp{path, spec.name});
        state.probe.item(std::string("tree.op.") + spec.name);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", spec.help);
      }
    }
    if (ImGui::Button("Remove node")) {
      if (tryCommit(state, edits, RemoveConstructionNode{path})) selected_.clear();
    }
    state.probe.item("tree.remove");
    return;
  }
  // Several nodes: operands of one operation can go under a new one.
  NodePath parent(selected_.front().begin(), selected_.front().end() - (selected_.front().empty() ? 0 : 1));
  std::vector<std::size_t> children;
  bool siblings = !selected_.front().empty();
  for (const NodePath& p : selected_) {
    if (p.empty() || NodePath(p.begin(), p.end() - 1) != parent)
      siblings = false;
    else
      children.push_back(p.back());
  }
  if (!siblings) {
    ImGui::TextDisabled("Select operands of the same operation to combine them.");
    return;
  }
  ImGui::TextUnformatted("Combine the selected with:");
  for (const ConstructionOpSpec& spec : constructionOps()) {
    ImGui::SameLine();
    if (ImGui::SmallButton(spec.name) && tryCommit(state, edits, GroupConstructionNodes{parent, children, spec.name}))
      selected_.clear();
    state.probe.item(std::string("tree.group.") + spec.name);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", spec.help);
  }
}

void ConstructionTreePanel::drawAddLeaf(ModellerState& state, EditQueue& edits) {
  const Project& project = state.document.project();
  const ConstructionTree* tree = project.construction ? &*project.construction : nullptr;
  // Where a leaf goes: into (or beside) the one selected node, else beside the root.
  std::optional<NodePath> at;
  if (selected_.size() == 1) at = selected_.front();
  sectionTitle("Add a leaf");
  ImGui::SetNextItemWidth(-ImGui::CalcTextSize("Add file leaf").x - ImGui::GetStyle().ItemSpacing.x * 2 -
                          ImGui::GetStyle().FramePadding.x * 2);
  const bool entered = ImGui::InputTextWithHint("##file", "project file, relative to this one", &fileText_,
                                                ImGuiInputTextFlags_EnterReturnsTrue);
  state.probe.item("tree.file");
  ImGui::SameLine();
  const bool clicked = ImGui::Button("Add file leaf");
  if ((clicked || entered) && !fileText_.empty()) {
    try {
      const fs::path file = state.projectFolder() / fileText_;
      ConstructionNode leaf;
      leaf.kind = ConstructionNode::Kind::File;
      leaf.file = leafPath(state, fileText_);
      // The version read now is the one watched from: a save right after it counts as an edit.
      std::error_code ec;
      const Seen read{fs::last_write_time(file, ec), fs::file_size(file, ec)};
      leaf.loaded = std::make_shared<const Project>(loadProject(file));
      if (tryCommit(state, edits, AddConstructionLeaf{at, leaf, std::nullopt})) {
        if (!ec) seen_[fs::absolute(file).lexically_normal().string()] = read;
        fileText_.clear();
      }
    } catch (const std::exception& e) {
      error_ = fileText_ + ": " + e.what();
    }
  }
  state.probe.item("tree.add_file");

  partFunctions_.resize(project.functions.size(), 1);
  ImGui::TextUnformatted("A part of the current functions:");
  for (std::size_t i = 0; i < project.functions.size(); ++i) {
    bool on = partFunctions_[i] != 0;
    if (i % 4) ImGui::SameLine();
    if (ImGui::Checkbox((project.functions[i].name + "##part" + std::to_string(i)).c_str(), &on))
      partFunctions_[i] = on ? 1 : 0;
  }
  if (partName_.empty()) partName_ = freePartName(tree);
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 10);
  ImGui::InputText("Name##part", &partName_);
  ImGui::SameLine();
  if (ImGui::Button("Add part")) {
    std::vector<std::size_t> indices;
    for (std::size_t i = 0; i < partFunctions_.size(); ++i)
      if (partFunctions_[i]) indices.push_back(i);
    try {
      ConstructionNode leaf;
      leaf.kind = ConstructionNode::Kind::Part;
      leaf.part = partName_;
      const ConstructionPart part{partName_, std::make_shared<const Project>(partOfFunctions(project, indices))};
      if (tryCommit(state, edits, AddConstructionLeaf{at, leaf, part})) partName_.clear();
    } catch (const std::exception& e) {
      error_ = e.what();
    }
  }
  state.probe.item("tree.add_part");
}

void ConstructionTreePanel::draw(ModellerState& state, EditQueue& edits) {
  watchLeaves(state, edits);
  if (!state.showConstruction) return;
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(vp->WorkPos.x + vp->WorkSize.x * 0.5f, vp->WorkPos.y + vp->WorkSize.y * 0.5f),
                          ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSize(ImVec2(std::min(ImGui::GetFontSize() * 34, vp->WorkSize.x * 0.95f),
                                  std::min(ImGui::GetFontSize() * 30, vp->WorkSize.y * 0.9f)),
                           ImGuiCond_Appearing);
  if (!ImGui::Begin("Construction tree", &state.showConstruction, ImGuiWindowFlags_NoCollapse)) {
    ImGui::End();
    return;
  }
  state.probe.window("window.construction");
  if (ImGui::IsWindowAppearing()) ImGui::SetWindowFocus();
  const Project& project = state.document.project();
  if (state.document.revision() != checkedRevision_) {
    checkedRevision_ = state.document.revision();
    stale_ = false;
    if (project.construction) {
      try {
        stale_ = evaluateConstructionTree(*project.construction).functions != project.functions;
      } catch (const std::exception&) {
        stale_ = true;
      }
    }
  }
  sectionTitle("Tree (leaves are IFSs, nodes the matrix operations)");
  if (!project.construction) {
    ImGui::TextWrapped("No construction tree: the functions are edited directly. Add a leaf below to start one.");
  } else {
    drawNode(state, *project.construction, project.construction->root, {});
    ImGui::Spacing();
    drawSelectionActions(state, edits, *project.construction);
    if (stale_)
      ImGui::TextWrapped(
          "The functions were edited since the tree was evaluated; the next change of the tree replaces them.");
  }
  if (!error_.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
    ImGui::TextWrapped("%s", error_.c_str());
    ImGui::PopStyleColor();
    state.probe.item("tree.error");
  }
  ImGui::Spacing();
  drawAddLeaf(state, edits);
  ImGui::End();
}

nlohmann::json ConstructionTreePanel::probeJson(const ModellerState& state) const {
  const Project& project = state.document.project();
  nlohmann::json selected = nlohmann::json::array();
  for (const NodePath& p : selected_) selected.push_back(pathId(p));
  std::function<int(const ConstructionNode&)> count = [&](const ConstructionNode& n) {
    int c = 1;
    for (const ConstructionNode& child : n.children) c += count(child);
    return c;
  };
  return {{"nodes", project.construction ? count(project.construction->root) : 0},
          {"root_op", project.construction ? project.construction->root.op : ""},
          {"selected", selected},
          {"error", error_},
          {"stale", stale_}};
}

}  // namespace gridifs::ui
