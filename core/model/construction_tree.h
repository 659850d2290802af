#pragma once
// The construction tree of a project (Thollot, Zair, Tosan & Vandorpe 1997, §4.3 and their
// figure 4.2): complex attractors built "step by step" from simple IFSs by the matrix operations
// of §4. Leaves are other projects (files, paths relative to this project's file) or named parts
// kept inside this project; inner nodes are operations named in one table. This header holds
// the tree as the project keeps it; construction/construction_evaluation.h holds the operations
// and the evaluation, whose result gives the project its functions, transitions and free-form
// space (adoptEvaluation).
//
// A file leaf keeps the project it was read from (`loaded`, not saved): evaluation is a pure
// function of the tree, and an edit or undo step holds everything it needs. io/construction_io.h
// reads the files; a tree parsed from text alone has its file leaves unloaded.
//
// Thread-safety: plain values; loaded leaves are immutable and shared between copies.
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace gridifs {

struct Project;

struct ConstructionNode {
  enum class Kind { File, Part, Operation };
  Kind kind = Kind::Part;
  std::string file;  // File: the path as written, relative to the project's folder
  std::string part;  // Part: the name of one of ConstructionTree::parts
  std::string op;    // Operation: a constructionOps() name
  std::vector<ConstructionNode> children;
  /// File: the project the file held when it was read (null until then; not saved).
  std::shared_ptr<const Project> loaded;
  /// Equal as saved: the loaded content is not compared (it is the file's, not the tree's).
  bool operator==(const ConstructionNode& other) const;
};

/// A named part of this project: a function set kept in the tree (only its functions,
/// transitions and space are used).
struct ConstructionPart {
  std::string name;
  std::shared_ptr<const Project> content;
  bool operator==(const ConstructionPart& other) const;
};

/// "construction": {"parts": [...], "root": node}.
struct ConstructionTree {
  std::vector<ConstructionPart> parts;
  ConstructionNode root;
  bool operator==(const ConstructionTree&) const = default;
};

/// A node's address: the child indices from the root ({} is the root).
using NodePath = std::vector<std::size_t>;

/// "construction.root.children[1].children[0]" for `path`.
std::string nodeJsonPath(const NodePath& path);
/// The node at `path`, or null.
const ConstructionNode* findNode(const ConstructionTree& tree, const NodePath& path);
ConstructionNode* findNode(ConstructionTree& tree, const NodePath& path);
const ConstructionPart* findPart(const ConstructionTree& tree, const std::string& name);

/// The combinations of construction/ifs_combination.h, by what they do to the IFS matrices.
enum class CombineOp { Union, Concat, Product, Shuffle, Intersection, Composition, MatrixUnion };

/// One operation a node may apply, a row of constructionOps().
struct ConstructionOpSpec {
  const char* name;   // the JSON "op" value, the same as `gridifs combine --op`
  const char* label;  // what the tree panel shows
  CombineOp combine;
  std::size_t min_children = 2, max_children = 2;  // more than two: folded from the left
  const char* help;                                // one line for the panel's tooltip
};

/// Every operation a node may have; adding an operation is one row.
const std::vector<ConstructionOpSpec>& constructionOps();
/// The row named `name`, or null.
const ConstructionOpSpec* findConstructionOp(const std::string& name);
/// The operations' names as a list ("union, concat, … or matrix-union"), for error messages.
std::string constructionOpList();

/// Checks the tree's shape: known operations with their number of children, parts that
/// exist, non-empty names, at most limits::kMaxFunctions nodes. Throws ModelError at the
/// offending node's JSON path.
void checkConstructionTree(const ConstructionTree& tree);

}  // namespace gridifs
