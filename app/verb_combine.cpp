// gridifs combine A.gridifs B.gridifs --op union|concat|product|shuffle|intersection|composition|matrix-union -o
// C.gridifs: two projects as one (core/construction/ifs_combination.h says what each operation builds).
#include "app/cli.h"
#include "app/render_setup.h"
#include "construction/ifs_combination.h"
#include "io/project_io.h"

namespace gridifs::cli {
namespace {

int runCombine(const std::string& first, const std::string& second, const std::string& opName, const std::string& out) {
  CombineOp op;
  if (!parseCombineOp(opName, op))
    throw CliError(kBadInput,
                   "--op must be union, concat, product, shuffle, intersection, composition or matrix-union, not \"" +
                       opName + "\"");
  checkOutputPath(out, {"gridifs"}, "the combined project");
  const Project a = loadForVerb(first), b = loadForVerb(second);
  Project combined;
  try {
    combined = combineProjects(a, b, op);
  } catch (const ModelError& e) {
    throw CliError(kBadInput, "cannot combine " + first + " and " + second + " with " + opName + ": " + e.what());
  }
  try {
    saveProject(combined, out);
  } catch (const IoError& e) {
    throw CliError(kFailure, e.what());
  } catch (const ModelError& e) {
    throw CliError(kFailure, out + ": " + e.what());
  }
  return kSuccess;
}

const VerbRegistration kCombine{
    {"combine",
     "A.gridifs B.gridifs --op union|concat|product|shuffle|intersection|composition|matrix-union -o C.gridifs: two "
     "projects as one",
     [](CLI::App& app) {
       auto a = std::make_shared<std::string>();
       auto b = std::make_shared<std::string>();
       auto op = std::make_shared<std::string>();
       auto out = std::make_shared<std::string>();
       app.add_option("A", *a, "first project (.gridifs)")->required();
       app.add_option("B", *b, "second project (.gridifs)")->required();
       app.add_option("--op", *op,
                      "union: both attractors (block matrix); concat: the concatenation of the two languages; "
                      "product, shuffle: the tensor product or sum (of two free-form projects: their sum); "
                      "intersection, matrix-union: entrywise on matrices with the same states (functions "
                      "match by name); composition: the product of the two IFS matrices")
           ->required();
       app.add_option("-o,--output", *out, "output project (.gridifs)")->required();
       return [=] { return runCombine(*a, *b, *op, *out); };
     }}};

}  // namespace
}  // namespace gridifs::cli
