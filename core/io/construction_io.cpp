#include "io/construction_io.h"

#include <algorithm>

#include "io/json_read.h"

namespace gridifs::construction_io {
namespace {

using json = nlohmann::json;
using ordered_json = nlohmann::ordered_json;
using namespace json_read;

ConstructionNode readNode(const json& j, const std::string& path, int depth) {
  requireObject(j, path);
  if (depth > limits::kMaxJsonDepth) fail(path, "the tree is nested too deeply");
  const bool hasFile = j.contains("file"), hasPart = j.contains("part"), hasOp = j.contains("op");
  if (int(hasFile) + int(hasPart) + int(hasOp) != 1)
    fail(path, "a node needs exactly one of \"file\" (a project), \"part\" (a part's name) or \"op\" (an operation)");
  ConstructionNode node;
  if (hasFile) {
    node.kind = ConstructionNode::Kind::File;
    node.file = readString(j["file"], join(path, "file"), 4096);
    if (node.file.empty()) fail(join(path, "file"), "a file leaf needs the path of a project");
    return node;
  }
  if (hasPart) {
    node.kind = ConstructionNode::Kind::Part;
    node.part = readString(j["part"], join(path, "part"), limits::kMaxNameLength);
    return node;
  }
  node.kind = ConstructionNode::Kind::Operation;
  node.op = readString(j["op"], join(path, "op"), 64);
  auto children = j.find("children");
  const std::string cp = join(path, "children");
  if (children == j.end()) fail(cp, "an operation needs its operands as \"children\"");
  if (!children->is_array()) fail(cp, std::string("expected an array of nodes, found ") + typeName(*children));
  if (children->size() > std::size_t(limits::kMaxFunctions))
    fail(cp, "more than " + std::to_string(limits::kMaxFunctions) + " operands");
  for (std::size_t i = 0; i < children->size(); ++i)
    node.children.push_back(readNode((*children)[i], item(cp, i), depth + 1));
  return node;
}

ordered_json writeNode(const ConstructionNode& node) {
  ordered_json o;
  switch (node.kind) {
    case ConstructionNode::Kind::File:
      o["file"] = node.file;
      break;
    case ConstructionNode::Kind::Part:
      o["part"] = node.part;
      break;
    case ConstructionNode::Kind::Operation: {
      o["op"] = node.op;
      ordered_json children = ordered_json::array();
      for (const ConstructionNode& child : node.children) children.push_back(writeNode(child));
      o["children"] = children;
      break;
    }
  }
  return o;
}

void readLeaves(ConstructionNode& node, const std::string& path, const std::filesystem::path& folder,
                std::vector<std::filesystem::path>& chain, const LoadFile& load) {
  for (std::size_t i = 0; i < node.children.size(); ++i)
    readLeaves(node.children[i], path + ".children[" + std::to_string(i) + "]", folder, chain, load);
  if (node.kind != ConstructionNode::Kind::File) return;
  const std::string at = path + ".file";
  const std::filesystem::path file = folder / node.file;
  const std::filesystem::path key = chainKey(file);
  if (std::find(chain.begin(), chain.end(), key) != chain.end())
    fail(at, "the leaf " + node.file + " leads back to a project that contains it (a cycle)");
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) fail(at, "the leaf file " + file.string() + " does not exist");
  chain.push_back(key);
  try {
    node.loaded = std::make_shared<const Project>(load(file, chain));
  } catch (const ModelError& e) {
    chain.pop_back();
    // A cycle found further down is reported where it closes, by the project that holds it.
    fail(at, "the leaf " + node.file + " cannot be used: " + e.what());
  } catch (const IoError& e) {
    chain.pop_back();
    fail(at, "cannot read the leaf " + node.file + ": " + e.what());
  }
  chain.pop_back();
}

}  // namespace

std::optional<ConstructionTree> readConstruction(const json& root, const ReadPart& readPart) {
  auto it = root.find("construction");
  if (it == root.end() || it->is_null()) return std::nullopt;
  requireObject(*it, "construction");
  ConstructionTree tree;
  if (auto parts = it->find("parts"); parts != it->end()) {
    if (!parts->is_array())
      fail("construction.parts", std::string("expected an array of parts, found ") + typeName(*parts));
    if (parts->size() > std::size_t(limits::kMaxFunctions))
      fail("construction.parts", "more than " + std::to_string(limits::kMaxFunctions) + " parts");
    for (std::size_t i = 0; i < parts->size(); ++i) {
      const std::string p = item("construction.parts", i);
      const json& part = (*parts)[i];
      requireObject(part, p);
      ConstructionPart out;
      auto name = part.find("name");
      if (name == part.end()) fail(p, "a part needs a \"name\"");
      out.name = readString(*name, join(p, "name"), limits::kMaxNameLength);
      out.content = std::make_shared<const Project>(readPart(part, p));
      tree.parts.push_back(std::move(out));
    }
  }
  auto rootNode = it->find("root");
  if (rootNode == it->end()) fail("construction.root", "the construction has no root node");
  tree.root = readNode(*rootNode, "construction.root", 0);
  checkConstructionTree(tree);
  return tree;
}

void writeConstruction(const Project& project, ordered_json& root, const WritePart& writePart) {
  if (!project.construction) return;
  const ConstructionTree& tree = *project.construction;
  ordered_json out;
  if (!tree.parts.empty()) {
    ordered_json parts = ordered_json::array();
    for (const ConstructionPart& part : tree.parts) {
      ordered_json p;
      p["name"] = part.name;
      if (part.content) writePart(*part.content, p);
      parts.push_back(p);
    }
    out["parts"] = parts;
  }
  out["root"] = writeNode(tree.root);
  root["construction"] = out;
}

std::filesystem::path chainKey(const std::filesystem::path& file) {
  std::error_code ec;
  std::filesystem::path key = std::filesystem::weakly_canonical(std::filesystem::absolute(file, ec), ec);
  return ec ? std::filesystem::absolute(file).lexically_normal() : key;
}

void readLeafFiles(ConstructionTree& tree, const std::filesystem::path& folder,
                   std::vector<std::filesystem::path>& chain, const LoadFile& load) {
  readLeaves(tree.root, "construction.root", folder, chain, load);
}

}  // namespace gridifs::construction_io
