// The construction tree (Thollot, Zair, Tosan & Vandorpe 1997, §4.3): evaluation as nested
// combinations, the file round trip with leaves read from files beside the project, the errors a
// bad tree gives (with their JSON paths), and the named edits as undo steps.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "construction/construction_evaluation.h"
#include "construction/ifs_combination.h"
#include "edit/document.h"
#include "io/project_io.h"
#include "model/construction_tree.h"
#include "model_error_text.h"

using namespace gridifs;
using namespace gridifs::test_support;
namespace fs = std::filesystem;

namespace {

/// A grid IFS of `n` half-size copies around a circle of radius `r` (n = 3: a Sierpinski
/// triangle in the plane z = 0), named prefix1, prefix2, ...
Project ring(int n, double r, const std::string& prefix) {
  Project p = defaultNewProject();
  const Function base = p.functions[0];
  p.functions.clear();
  for (int i = 0; i < n; ++i) {
    Function f = base;
    f.name = prefix + std::to_string(i + 1);
    const double a = 2.0 * M_PI * i / n;
    f.placement.scale = Vec3{0.5, 0.5, 0.5};
    f.placement.translate = Vec3{r * std::cos(a), r * std::sin(a), 0.0};
    p.functions.push_back(f);
  }
  return p;
}

ConstructionNode fileLeaf(const std::string& file) {
  ConstructionNode n;
  n.kind = ConstructionNode::Kind::File;
  n.file = file;
  return n;
}
ConstructionNode partLeaf(const std::string& name) {
  ConstructionNode n;
  n.kind = ConstructionNode::Kind::Part;
  n.part = name;
  return n;
}
ConstructionNode opNode(const std::string& op, std::vector<ConstructionNode> children) {
  ConstructionNode n;
  n.kind = ConstructionNode::Kind::Operation;
  n.op = op;
  n.children = std::move(children);
  return n;
}
ConstructionPart part(const std::string& name, const Project& content) {
  return {name, std::make_shared<const Project>(content)};
}

struct TreeTempDir {
  fs::path path =
      fs::temp_directory_path() / ("gridifs-tree-" + std::to_string(::getpid()) + "-" + std::to_string(std::rand()));
  TreeTempDir() { fs::create_directories(path); }
  ~TreeTempDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

void writeText(const fs::path& file, const std::string& text) { std::ofstream(file) << text; }

/// A project whose tree is union(concat(part a, part b), part c).
Project threePartTree() {
  Project p = defaultNewProject();
  ConstructionTree tree;
  tree.parts = {part("a", ring(3, 0.5, "a")), part("b", ring(2, 0.6, "b")), part("c", ring(4, 0.4, "c"))};
  tree.root = opNode("union", {opNode("concat", {partLeaf("a"), partLeaf("b")}), partLeaf("c")});
  p.construction = tree;
  reevaluateConstruction(p);
  return p;
}

}  // namespace

TEST(ConstructionTree, EvaluatesAsTheNestedCombinations) {
  const Project a = ring(3, 0.5, "a"), b = ring(2, 0.6, "b"), c = ring(4, 0.4, "c");
  const Project expected = combineProjects(combineProjects(a, b, CombineOp::Concat), c, CombineOp::Union);
  const Project p = threePartTree();
  EXPECT_EQ(p.functions, expected.functions);
  EXPECT_EQ(p.transitions, expected.transitions);
  ASSERT_EQ(p.functions.size(), 9u);
  // concat: a's functions may be followed by b's, b's never by a's or c's.
  EXPECT_GT(p.transitions[0][3], 0.0);
  EXPECT_EQ(p.transitions[3][0], 0.0);
  EXPECT_EQ(p.transitions[3][5], 0.0);
}

TEST(ConstructionTree, UnionOfThreeOperandsFoldsFromTheLeft) {
  const Project a = ring(3, 0.5, "a"), b = ring(2, 0.6, "b"), c = ring(4, 0.4, "c");
  Project p = defaultNewProject();
  ConstructionTree tree;
  tree.parts = {part("a", a), part("b", b), part("c", c)};
  tree.root = opNode("union", {partLeaf("a"), partLeaf("b"), partLeaf("c")});
  p.construction = tree;
  reevaluateConstruction(p);
  const Project expected = combineProjects(combineProjects(a, b, CombineOp::Union), c, CombineOp::Union);
  EXPECT_EQ(p.functions, expected.functions);
}

TEST(ConstructionTree, EveryOperationIsOneTableRowNamedAsTheCombineVerb) {
  for (const ConstructionOpSpec& spec : constructionOps()) {
    CombineOp op;
    ASSERT_TRUE(parseCombineOp(spec.name, op)) << spec.name;
    EXPECT_EQ(op, spec.combine);
    EXPECT_EQ(findConstructionOp(spec.name), &spec);
  }
  EXPECT_EQ(findConstructionOp("xor"), nullptr);
}

TEST(ConstructionTree, RoundTripKeepsTreeAndParts) {
  const Project p = threePartTree();
  const std::string text = serializeProject(p);
  EXPECT_NE(text.find("\"construction\""), std::string::npos);
  const Project back = parseProject(text);
  EXPECT_EQ(back, p);
  EXPECT_EQ(serializeProject(back), text);
}

TEST(ConstructionTree, ProjectsWithoutATreeSaveAsBefore) {
  const Project p = loadProject(fs::path(GRIDIFS_ASSETS) / "sierpinski_tetrahedron.gridifs");
  EXPECT_FALSE(p.construction);
  EXPECT_EQ(serializeProject(p).find("construction"), std::string::npos);
}

TEST(ConstructionTree, FileLeavesAreReadBesideTheProjectAndFollowTheirFile) {
  TreeTempDir dir;
  fs::create_directories(dir.path / "leaves");
  saveProject(ring(3, 0.5, "t"), dir.path / "leaves" / "triangle.gridifs");
  saveProject(ring(4, 0.4, "s"), dir.path / "leaves" / "square.gridifs");
  Project p = defaultNewProject();
  p.construction =
      ConstructionTree{{}, opNode("union", {fileLeaf("leaves/triangle.gridifs"), fileLeaf("leaves/square.gridifs")})};
  readConstructionLeaves(p, dir.path / "tree.gridifs");
  ASSERT_EQ(p.functions.size(), 7u);
  saveProject(p, dir.path / "tree.gridifs");
  EXPECT_EQ(loadProject(dir.path / "tree.gridifs").functions, p.functions);

  // The leaf is edited on disk: the project read again is the tree's new value.
  Project triangle = ring(3, 0.7, "t");
  saveProject(triangle, dir.path / "leaves" / "triangle.gridifs");
  const Project again = loadProject(dir.path / "tree.gridifs");
  ASSERT_EQ(again.functions.size(), 7u);
  EXPECT_NEAR(again.functions[0].placement.translate.x, 0.7, 1e-12);
  EXPECT_NE(again.functions, p.functions);
}

TEST(ConstructionTree, BadTreesNameTheirJsonPath) {
  TreeTempDir dir;
  saveProject(ring(3, 0.5, "t"), dir.path / "t.gridifs");
  saveProject(ring(4, 0.4, "s"), dir.path / "s.gridifs");
  const std::string head = R"({"format": "gridifs", "version": 1, "functions": [{"name": "f"}], "construction": )";
  auto loadWith = [&](const std::string& construction) {
    writeText(dir.path / "p.gridifs", head + construction + "}");
    return modelErrorText([&] { loadProject(dir.path / "p.gridifs"); });
  };
  EXPECT_EQ(loadWith(R"({"root": {"op": "xor", "children": [{"file": "t.gridifs"}, {"file": "t.gridifs"}]}})"),
            "construction.root.op: unknown operation \"xor\" (expected " + constructionOpList() + ")");
  EXPECT_EQ(constructionOpList().rfind("union, concat, product", 0), 0u);
  EXPECT_EQ(loadWith(R"({"root": {"op": "concat", "children": [{"file": "t.gridifs"}]}})"),
            "construction.root.children: concat takes 2 operands, not 1");
  EXPECT_EQ(
      loadWith(R"({"root": {"op": "union", "children": [{"file": "t.gridifs"}, {"file": "gone.gridifs"}]}})"),
      "construction.root.children[1].file: the leaf file " + (dir.path / "gone.gridifs").string() + " does not exist");
  EXPECT_EQ(loadWith(R"({"root": {"part": "nothing"}})"),
            "construction.root.part: there is no part named \"nothing\" in construction.parts");
  EXPECT_EQ(
      loadWith(R"({"root": {"file": "t.gridifs", "part": "x"}})"),
      "construction.root: a node needs exactly one of \"file\" (a project), \"part\" (a part's name) or \"op\" (an "
      "operation)");
  EXPECT_EQ(loadWith(R"({"parts": [{"name": "x", "functions": [{"weight": -1}]}], "root": {"part": "x"}})"),
            "construction.parts[0].functions[0].weight: expected a number between 0 and 1e+09, found -1");
  // Two IFSs without a function of the same name intersect in no word, so the intersection has no
  // attractor: the operation's failure names its node.
  const std::string meet =
      loadWith(R"({"root": {"op": "intersection", "children": [{"file": "t.gridifs"}, {"file": "s.gridifs"}]}})");
  EXPECT_EQ(meet.rfind("construction.root: intersection failed: ", 0), 0u) << meet;
}

TEST(ConstructionTree, CyclesThroughFilesAreRefused) {
  TreeTempDir dir;
  const std::string head = R"({"format": "gridifs", "version": 1, "functions": [{"name": "f"}], "construction": )";
  writeText(dir.path / "self.gridifs", head + R"({"root": {"file": "self.gridifs"}}})");
  EXPECT_EQ(modelErrorText([&] { loadProject(dir.path / "self.gridifs"); }),
            "construction.root.file: the leaf self.gridifs leads back to a project that contains it (a cycle)");
  writeText(dir.path / "a.gridifs", head + R"({"root": {"file": "b.gridifs"}}})");
  writeText(dir.path / "b.gridifs", head + R"({"root": {"file": "./a.gridifs"}}})");
  const std::string cycle = modelErrorText([&] { loadProject(dir.path / "a.gridifs"); });
  EXPECT_EQ(cycle.rfind("construction.root.file: the leaf b.gridifs cannot be used: construction.root.file: the leaf "
                        "./a.gridifs leads back",
                        0),
            0u)
      << cycle;
}

TEST(ConstructionTree, EditsAreUndoStepsAndReevaluate) {
  Document doc(ring(3, 0.5, "a"));
  const Project a = doc.project();
  // A part of the project's own functions becomes the root; the functions stay the same.
  AddConstructionLeaf addA{std::nullopt, partLeaf("a"), part("a", partOfFunctions(a, {0, 1, 2}))};
  doc.apply(addA);
  EXPECT_EQ(doc.project().functions, a.functions);
  EXPECT_EQ(doc.undoLabel(), "Add part a");
  // A second leaf under the root: the union of both.
  doc.apply(AddConstructionLeaf{std::nullopt, partLeaf("b"), part("b", ring(2, 0.6, "b"))});
  ASSERT_EQ(doc.project().functions.size(), 5u);
  EXPECT_EQ(doc.project().construction->root.op, "union");
  doc.apply(SetConstructionOp{{}, "concat"});
  EXPECT_EQ(doc.undoLabel(), "Operation: concat");
  EXPECT_GT(doc.project().transitions[0][3], 0.0);
  // An operation that cannot apply to these operands is refused; the document keeps its state.
  const Project before = doc.project();
  EXPECT_NE(modelErrorText([&] {
              doc.apply(SetConstructionOp{{}, "intersection"});
            }).find("intersection failed"),
            std::string::npos);
  EXPECT_EQ(doc.project(), before);
  // Removing an operand leaves the other in the operation's place.
  doc.apply(RemoveConstructionNode{{1}});
  EXPECT_EQ(doc.project().functions, a.functions);
  EXPECT_EQ(doc.project().construction->root.kind, ConstructionNode::Kind::Part);
  EXPECT_EQ(doc.project().construction->parts.size(), 1u);
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(doc.project(), before);
  ASSERT_TRUE(doc.undo());
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(doc.project().functions, a.functions);
  ASSERT_TRUE(doc.undo());
  EXPECT_FALSE(doc.project().construction);
}

TEST(ConstructionTree, GroupingOperandsMakesANewNode) {
  Project p = defaultNewProject();
  ConstructionTree tree;
  tree.parts = {part("a", ring(3, 0.5, "a")), part("b", ring(2, 0.6, "b")), part("c", ring(4, 0.4, "c"))};
  tree.root = opNode("union", {partLeaf("a"), partLeaf("b"), partLeaf("c")});
  p.construction = tree;
  reevaluateConstruction(p);
  Document doc(p);
  doc.apply(GroupConstructionNodes{{}, {0, 1}, "concat"});
  const ConstructionNode& root = doc.project().construction->root;
  ASSERT_EQ(root.children.size(), 2u);
  EXPECT_EQ(root.children[0].op, "concat");
  EXPECT_EQ(root.children[1].part, "c");
  EXPECT_EQ(doc.undoLabel(), "Combine with concat");
  EXPECT_EQ(doc.project().functions, threePartTree().functions);
}

TEST(ConstructionTree, ReloadedLeavesAreOneUndoStep) {
  Project p = defaultNewProject();
  ConstructionNode leaf = fileLeaf("t.gridifs");
  leaf.loaded = std::make_shared<const Project>(ring(3, 0.5, "t"));
  p.construction = ConstructionTree{{}, leaf};
  reevaluateConstruction(p);
  Document doc(p);
  ConstructionTree edited = *p.construction;
  edited.root.loaded = std::make_shared<const Project>(ring(3, 0.8, "t"));
  doc.apply(ReloadConstructionLeaves{edited});
  EXPECT_NEAR(doc.project().functions[0].placement.translate.x, 0.8, 1e-12);
  EXPECT_EQ(doc.undoLabel(), "Leaf edited");
  ASSERT_TRUE(doc.undo());
  EXPECT_NEAR(doc.project().functions[0].placement.translate.x, 0.5, 1e-12);
}

TEST(ConstructionTree, FigureExampleIsTheValueOfItsTree) {
  const fs::path file = fs::path(GRIDIFS_ASSETS) / "matrices" / "construction_tree.gridifs";
  const fs::path leaves = file.parent_path() / "construction_tree_leaves";
  const Project p = loadProject(file);
  auto leaf = [&](const char* name) { return loadProject(leaves / (std::string(name) + ".gridifs")); };
  const Project expected =
      combineProjects(combineProjects(leaf("gasket"), leaf("arc"), CombineOp::Product),
                      combineProjects(leaf("wave"), leaf("bow"), CombineOp::Shuffle), CombineOp::Union);
  EXPECT_EQ(p.functions, expected.functions);
  EXPECT_EQ(p.space, expected.space);
  ASSERT_TRUE(p.construction);
  EXPECT_EQ(p.construction->root.op, "union");
  // The functions saved in the file are the tree's value (older readers see the same IFS).
  std::ifstream in(file);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(parseProject(text).functions, p.functions);
}
