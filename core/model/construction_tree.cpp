#include "model/construction_tree.h"

#include "base/errors.h"
#include "model/project.h"

namespace gridifs {
namespace {

/// Nodes of a tree, counted (a hostile file cannot make evaluation run away).
std::size_t countNodes(const ConstructionNode& node) {
  std::size_t n = 1;
  for (const ConstructionNode& child : node.children) n += countNodes(child);
  return n;
}

void checkNode(const ConstructionTree& tree, const ConstructionNode& node, const std::string& path) {
  switch (node.kind) {
    case ConstructionNode::Kind::File:
      if (node.file.empty()) throw ModelError(path + ".file", "a file leaf needs the path of a project");
      return;
    case ConstructionNode::Kind::Part:
      if (!findPart(tree, node.part))
        throw ModelError(path + ".part",
                         "there is no part named \"" + node.part.substr(0, 60) + "\" in construction.parts");
      return;
    case ConstructionNode::Kind::Operation:
      break;
  }
  const ConstructionOpSpec* spec = findConstructionOp(node.op);
  if (!spec)
    throw ModelError(path + ".op",
                     "unknown operation \"" + node.op.substr(0, 40) + "\" (expected " + constructionOpList() + ")");
  const std::size_t n = node.children.size();
  if (n < spec->min_children || n > spec->max_children) {
    const std::string wanted = spec->min_children == spec->max_children
                                   ? std::to_string(spec->min_children)
                                   : std::to_string(spec->min_children) + " to " + std::to_string(spec->max_children);
    throw ModelError(path + ".children",
                     std::string(spec->name) + " takes " + wanted + " operands, not " + std::to_string(n));
  }
  for (std::size_t i = 0; i < n; ++i) checkNode(tree, node.children[i], path + ".children[" + std::to_string(i) + "]");
}

}  // namespace

const std::vector<ConstructionOpSpec>& constructionOps() {
  // Union, product and shuffle are associative (block matrix, Kronecker product, tensor sum),
  // so a node may take more than two operands; concatenation reads left to right and takes two.
  static const std::vector<ConstructionOpSpec> ops = {
      {"union", "Union", CombineOp::Union, 2, 8, "the union of the attractors (block matrix)"},
      {"concat", "Concatenation", CombineOp::Concat, 2, 2,
       "the first operand's maps may be followed by the second's (grid projects)"},
      {"product", "Tensor product", CombineOp::Product, 2, 8,
       "free-form projects: every pair of maps at once, the sum of the attractors"},
      {"shuffle", "Tensor sum (shuffle)", CombineOp::Shuffle, 2, 8,
       "free-form projects: the maps interleaved, the sum of the attractors"},
      // Entrywise on matrices with the same states are associative too; the matrix product is.
      {"intersection", "Intersection", CombineOp::Intersection, 2, 8,
       "entrywise on matrices with the same states: the words both accept"},
      {"composition", "Composition", CombineOp::Composition, 2, 8,
       "the matrix product: a word of the first, then a word of the second"},
      {"matrix-union", "Matrix union", CombineOp::MatrixUnion, 2, 8,
       "entrywise on matrices with the same states: the words either accepts"},
  };
  return ops;
}

const ConstructionOpSpec* findConstructionOp(const std::string& name) {
  for (const ConstructionOpSpec& spec : constructionOps())
    if (name == spec.name) return &spec;
  return nullptr;
}

std::string constructionOpList() {
  std::string out;
  const auto& ops = constructionOps();
  for (std::size_t i = 0; i < ops.size(); ++i) {
    if (i > 0) out += i + 1 == ops.size() ? " or " : ", ";
    out += ops[i].name;
  }
  return out;
}

void checkConstructionTree(const ConstructionTree& tree) {
  if (countNodes(tree.root) > std::size_t(limits::kMaxFunctions))
    throw ModelError("construction.root", "the tree has more than " + std::to_string(limits::kMaxFunctions) + " nodes");
  for (std::size_t i = 0; i < tree.parts.size(); ++i) {
    const std::string path = "construction.parts[" + std::to_string(i) + "]";
    if (tree.parts[i].name.empty()) throw ModelError(path + ".name", "a part needs a name");
    for (std::size_t j = 0; j < i; ++j)
      if (tree.parts[j].name == tree.parts[i].name)
        throw ModelError(path + ".name", "another part is already named \"" + tree.parts[i].name + "\"");
    if (!tree.parts[i].content || tree.parts[i].content->functions.empty())
      throw ModelError(path + ".functions", "a part needs at least one function");
  }
  checkNode(tree, tree.root, "construction.root");
}

bool ConstructionNode::operator==(const ConstructionNode& other) const {
  return kind == other.kind && file == other.file && part == other.part && op == other.op && children == other.children;
}

bool ConstructionPart::operator==(const ConstructionPart& other) const {
  if (name != other.name) return false;
  if (content == other.content) return true;
  return content && other.content && *content == *other.content;
}

std::string nodeJsonPath(const NodePath& path) {
  std::string out = "construction.root";
  for (std::size_t i : path) out += ".children[" + std::to_string(i) + "]";
  return out;
}

const ConstructionNode* findNode(const ConstructionTree& tree, const NodePath& path) {
  const ConstructionNode* node = &tree.root;
  for (std::size_t i : path) {
    if (i >= node->children.size()) return nullptr;
    node = &node->children[i];
  }
  return node;
}

ConstructionNode* findNode(ConstructionTree& tree, const NodePath& path) {
  return const_cast<ConstructionNode*>(findNode(static_cast<const ConstructionTree&>(tree), path));
}

const ConstructionPart* findPart(const ConstructionTree& tree, const std::string& name) {
  for (const ConstructionPart& part : tree.parts)
    if (part.name == name) return &part;
  return nullptr;
}

}  // namespace gridifs
