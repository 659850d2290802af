#pragma once
// Named edits of a project's construction tree (Thollot, Zair, Tosan & Vandorpe 1997, §4.3;
// model/construction_tree.h): each changes the tree and makes the functions its value again, as
// one undo step. Each is a plain value gathered in ProjectEdit (edit/project_edit.h).
//
// Thread-safety: plain values; apply() touches only the project given. apply() throws ModelError
// when a node it names is not in the tree, or when the changed tree cannot be evaluated (the
// message names the failing node's JSON path): the Document then keeps the project as it was.
#include <optional>
#include <string>
#include <vector>

#include "model/project.h"

namespace gridifs {

/// Adds a leaf: the root of a new tree when the project has none; else into the operation node
/// `at` when its operation takes one more operand, or in place of node `at` (the root when
/// `at` is empty) as the union of it and the leaf. `part`, when given, is added to the parts
/// first (the leaf then names it).
struct AddConstructionLeaf {
  std::optional<NodePath> at;
  ConstructionNode leaf;
  std::optional<ConstructionPart> part;
  void apply(Project& project) const;
  std::string label() const;
};

/// Puts children `children` (at least one) of operation node `parent` under a new node with
/// operation `op`, at the place of the first of them.
struct GroupConstructionNodes {
  NodePath parent;
  std::vector<std::size_t> children;
  std::string op;
  void apply(Project& project) const;
  std::string label() const { return "Combine with " + op; }
};

/// Changes the operation of node `node`.
struct SetConstructionOp {
  NodePath node;
  std::string op;
  void apply(Project& project) const;
  std::string label() const { return "Operation: " + op; }
};

/// Removes node `node` and what is under it. An operation left with a single operand is
/// replaced by it; removing the root removes the tree (the functions stay as they are). Parts no
/// leaf names any more are dropped.
struct RemoveConstructionNode {
  NodePath node;
  void apply(Project& project) const;
  std::string label() const { return "Remove tree node"; }
};

/// The tree with its file leaves read again (a leaf was edited on disk): `tree` is the
/// project's tree with new `loaded` projects.
struct ReloadConstructionLeaves {
  ConstructionTree tree;
  void apply(Project& project) const;
  std::string label() const { return "Leaf edited"; }
};

}  // namespace gridifs
