#include "construction/construction_evaluation.h"

#include <algorithm>

#include "base/errors.h"

namespace gridifs {
namespace {

Project evaluateNode(const ConstructionTree& tree, const ConstructionNode& node, const std::string& path) {
  switch (node.kind) {
    case ConstructionNode::Kind::File:
      if (!node.loaded)
        throw ModelError(path + ".file",
                         "the leaf " + node.file + " has not been read (open the project from its file)");
      return *node.loaded;
    case ConstructionNode::Kind::Part: {
      const ConstructionPart* part = findPart(tree, node.part);
      if (!part || !part->content) throw ModelError(path + ".part", "there is no part named \"" + node.part + "\"");
      return *part->content;
    }
    case ConstructionNode::Kind::Operation:
      break;
  }
  const ConstructionOpSpec* spec = findConstructionOp(node.op);
  if (!spec) throw ModelError(path + ".op", "unknown operation \"" + node.op.substr(0, 40) + "\"");
  if (node.children.empty()) throw ModelError(path + ".children", std::string(spec->name) + " has no operands");
  Project value = evaluateNode(tree, node.children[0], path + ".children[0]");
  for (std::size_t i = 1; i < node.children.size(); ++i) {
    const Project next = evaluateNode(tree, node.children[i], path + ".children[" + std::to_string(i) + "]");
    try {
      value = combineProjects(value, next, spec->combine);
    } catch (const ModelError& e) {
      throw ModelError(path, std::string(spec->name) + " failed: " + e.what());
    }
  }
  return value;
}

}  // namespace

Project evaluateConstructionTree(const ConstructionTree& tree) {
  checkConstructionTree(tree);
  return evaluateNode(tree, tree.root, "construction.root");
}

void adoptEvaluation(Project& project, const Project& evaluated) {
  project.functions = evaluated.functions;
  project.transitions = evaluated.transitions;
  project.space = evaluated.space;
  project.states = evaluated.states;
}

void reevaluateConstruction(Project& project) {
  if (!project.construction) return;
  adoptEvaluation(project, evaluateConstructionTree(*project.construction));
}

Project partOfFunctions(const Project& project, const std::vector<std::size_t>& indices) {
  if (indices.empty()) throw ModelError("", "a part needs at least one function");
  Project part;
  part.space = project.space;
  for (std::size_t i : indices) {
    if (i >= project.functions.size()) throw ModelError("", "there is no function " + std::to_string(i));
    part.functions.push_back(project.functions[i]);
  }
  if (!project.transitions.empty()) {
    for (std::size_t i : indices) {
      std::vector<double> row;
      for (std::size_t j : indices) row.push_back(project.transitions[i][j]);
      part.transitions.push_back(std::move(row));
    }
  }
  return part;
}

}  // namespace gridifs
