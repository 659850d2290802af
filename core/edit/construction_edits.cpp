#include "edit/construction_edits.h"

#include <algorithm>

#include "base/errors.h"
#include "construction/construction_evaluation.h"

namespace gridifs {
namespace {

ConstructionTree& requireTree(Project& project) {
  if (!project.construction) throw ModelError("construction", "the project has no construction tree");
  return *project.construction;
}

ConstructionNode& requireNode(ConstructionTree& tree, const NodePath& path) {
  ConstructionNode* node = findNode(tree, path);
  if (!node) throw ModelError(nodeJsonPath(path), "there is no such node in the tree");
  return *node;
}

ConstructionNode operationNode(const std::string& op, std::vector<ConstructionNode> children) {
  ConstructionNode node;
  node.kind = ConstructionNode::Kind::Operation;
  node.op = op;
  node.children = std::move(children);
  return node;
}

void collectParts(const ConstructionNode& node, std::vector<std::string>& names) {
  if (node.kind == ConstructionNode::Kind::Part) names.push_back(node.part);
  for (const ConstructionNode& child : node.children) collectParts(child, names);
}

/// Drops parts that no leaf names: a part lives as long as a leaf shows it.
void dropUnusedParts(ConstructionTree& tree) {
  std::vector<std::string> used;
  collectParts(tree.root, used);
  std::erase_if(tree.parts,
                [&](const ConstructionPart& p) { return std::find(used.begin(), used.end(), p.name) == used.end(); });
}

}  // namespace

void AddConstructionLeaf::apply(Project& project) const {
  if (leaf.kind == ConstructionNode::Kind::Operation) throw ModelError("construction", "a leaf is a file or a part");
  if (!project.construction) {
    ConstructionTree tree;
    if (part) tree.parts.push_back(*part);
    tree.root = leaf;
    project.construction = std::move(tree);
  } else {
    ConstructionTree& tree = *project.construction;
    if (part) {
      if (findPart(tree, part->name))
        throw ModelError("construction.parts", "another part is already named \"" + part->name + "\"");
      tree.parts.push_back(*part);
    }
    ConstructionNode& target = requireNode(tree, at.value_or(NodePath{}));
    const ConstructionOpSpec* spec =
        target.kind == ConstructionNode::Kind::Operation ? findConstructionOp(target.op) : nullptr;
    if (spec && target.children.size() < spec->max_children)
      target.children.push_back(leaf);
    else
      target = operationNode("union", {std::move(target), leaf});
  }
  reevaluateConstruction(project);
}

std::string AddConstructionLeaf::label() const {
  return leaf.kind == ConstructionNode::Kind::File ? "Add leaf " + leaf.file : "Add part " + leaf.part;
}

void GroupConstructionNodes::apply(Project& project) const {
  ConstructionTree& tree = requireTree(project);
  ConstructionNode& node = requireNode(tree, parent);
  if (node.kind != ConstructionNode::Kind::Operation || children.empty())
    throw ModelError(nodeJsonPath(parent), "only operands of an operation can be combined");
  std::vector<std::size_t> sorted = children;
  std::sort(sorted.begin(), sorted.end());
  sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
  if (sorted.back() >= node.children.size()) throw ModelError(nodeJsonPath(parent), "there is no such operand");
  std::vector<ConstructionNode> grouped, kept;
  for (std::size_t i = 0; i < node.children.size(); ++i)
    (std::binary_search(sorted.begin(), sorted.end(), i) ? grouped : kept).push_back(node.children[i]);
  kept.insert(kept.begin() + std::ptrdiff_t(sorted.front()), operationNode(op, std::move(grouped)));
  // All operands grouped: the new node is the old one's only operand, so it takes its place.
  if (kept.size() == 1)
    node = std::move(kept.front());
  else
    node.children = std::move(kept);
  reevaluateConstruction(project);
}

void SetConstructionOp::apply(Project& project) const {
  ConstructionNode& target = requireNode(requireTree(project), node);
  if (target.kind != ConstructionNode::Kind::Operation) throw ModelError(nodeJsonPath(node), "a leaf has no operation");
  target.op = op;
  reevaluateConstruction(project);
}

void RemoveConstructionNode::apply(Project& project) const {
  ConstructionTree& tree = requireTree(project);
  requireNode(tree, node);
  if (node.empty()) {
    project.construction.reset();
    return;
  }
  const NodePath parentPath(node.begin(), node.end() - 1);
  ConstructionNode& parent = requireNode(tree, parentPath);
  parent.children.erase(parent.children.begin() + std::ptrdiff_t(node.back()));
  if (parent.children.size() == 1) {
    ConstructionNode only = std::move(parent.children.front());
    parent = std::move(only);
  }
  dropUnusedParts(tree);
  reevaluateConstruction(project);
}

void ReloadConstructionLeaves::apply(Project& project) const {
  requireTree(project);
  project.construction = tree;
  reevaluateConstruction(project);
}

}  // namespace gridifs
