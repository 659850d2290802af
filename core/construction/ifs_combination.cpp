#include "construction/ifs_combination.h"

#include <algorithm>

#include "freeform/free_form.h"
#include "freeform/ifs_matrix_ops.h"
#include "freeform/state_expansion.h"
#include "schema/validation.h"

namespace gridifs {
namespace {

[[noreturn]] void fail(const std::string& message) { throw ModelError("", message); }

using Matrix = std::vector<std::vector<double>>;

/// The transition matrix, or all ones when the project has none.
Matrix transitionsOrOnes(const Project& p) {
  if (!p.transitions.empty()) return p.transitions;
  return Matrix(p.functions.size(), std::vector<double>(p.functions.size(), 1.0));
}

double activeWeight(const Project& p) {
  double total = 0.0;
  for (const Function& f : p.functions)
    if (!f.muted) total += f.weight;
  return total > 0.0 ? total : 1.0;
}

void checkCount(std::size_t n, const char* what) {
  if (n > std::size_t(limits::kMaxFunctions))
    fail(std::string("the ") + what + " would have " + std::to_string(n) + " functions, more than the limit of " +
         std::to_string(limits::kMaxFunctions));
}

/// `t` (m_own × m_own) placed at `offset` in a total × total matrix; the other rows go to the
/// centroid of this block so every row still sums to 1.
Matrix embed(const Matrix& t, std::size_t offset, std::size_t total) {
  const std::size_t m = t.size();
  Matrix out(total, std::vector<double>(total, 0.0));
  for (std::size_t i = 0; i < total; ++i) {
    if (i >= offset && i < offset + m)
      for (std::size_t j = 0; j < m; ++j) out[i][offset + j] = t[i - offset][j];
    else
      for (std::size_t j = 0; j < m; ++j) out[i][offset + j] = 1.0 / double(m);
  }
  return out;
}

Project unionOrConcat(const Project& a, const Project& b, bool concat) {
  const std::size_t na = a.functions.size(), nb = b.functions.size();
  checkCount(na + nb, "combined IFS");
  Project out = a;
  out.functions.clear();
  const double wa = activeWeight(a), wb = activeWeight(b);
  std::size_t ma = 0, total = 0;
  if (a.space) {
    ma = a.space->control_points.size();
    total = ma + b.space->control_points.size();
    if (total > std::size_t(limits::kMaxControlPoints))
      fail("the combined space would have " + std::to_string(total) + " control points, more than the limit of " +
           std::to_string(limits::kMaxControlPoints));
    out.space->control_points.insert(out.space->control_points.end(), b.space->control_points.begin(),
                                     b.space->control_points.end());
  }
  for (const Function& f : a.functions) {
    Function g = f;
    g.weight = f.weight / wa;
    if (a.space) g.matrix = embed(f.matrix, 0, total);
    out.functions.push_back(std::move(g));
  }
  for (const Function& f : b.functions) {
    Function g = f;
    g.weight = f.weight / wb;
    if (b.space) g.matrix = embed(f.matrix, ma, total);
    out.functions.push_back(std::move(g));
  }
  const Matrix ta = transitionsOrOnes(a), tb = transitionsOrOnes(b);
  out.transitions.assign(na + nb, std::vector<double>(na + nb, 0.0));
  for (std::size_t i = 0; i < na; ++i) {
    for (std::size_t j = 0; j < na; ++j) out.transitions[i][j] = ta[i][j];
    if (concat)
      for (std::size_t j = 0; j < nb; ++j) out.transitions[i][na + j] = 1.0;
  }
  for (std::size_t i = 0; i < nb; ++i)
    for (std::size_t j = 0; j < nb; ++j) out.transitions[na + i][na + j] = tb[i][j];
  return out;
}

Vec3 mix(Vec3 x, Vec3 y) { return 0.5 * (x + y); }

/// The m_A·m_B control points p_i + q_k (index i·m_B + k).
FreeFormSpace sumSpace(const FreeFormSpace& a, const FreeFormSpace& b) {
  const std::size_t m = a.control_points.size() * b.control_points.size();
  if (m > std::size_t(limits::kMaxControlPoints))
    fail("the product space would have " + std::to_string(a.control_points.size()) + " × " +
         std::to_string(b.control_points.size()) + " = " + std::to_string(m) +
         " control points, more than the limit of " + std::to_string(limits::kMaxControlPoints));
  FreeFormSpace out;
  for (const Vec3& p : a.control_points)
    for (const Vec3& q : b.control_points) out.control_points.push_back(p + q);
  return out;
}

Project product(const Project& a, const Project& b) {
  const std::size_t na = a.functions.size(), nb = b.functions.size();
  checkCount(na * nb, "product");
  Project out = a;
  out.space = sumSpace(*a.space, *b.space);
  out.functions.clear();
  const double wa = activeWeight(a), wb = activeWeight(b);
  for (const Function& f : a.functions)
    for (const Function& g : b.functions) {
      Function h;
      h.name = f.name + "×" + g.name;
      h.kind = FunctionKind::Matrix;
      h.matrix = kroneckerProduct(f.matrix, g.matrix);
      h.weight = (f.weight / wa) * (g.weight / wb);
      h.color = mix(f.color, g.color);
      h.palette_index = 0.5 * (f.palette_index + g.palette_index);
      h.color_speed = 0.5 * (f.color_speed + g.color_speed);
      h.muted = f.muted || g.muted;
      out.functions.push_back(std::move(h));
    }
  out.transitions.clear();
  if (!a.transitions.empty() || !b.transitions.empty()) {
    const Matrix ta = transitionsOrOnes(a), tb = transitionsOrOnes(b);
    out.transitions.assign(na * nb, std::vector<double>(na * nb, 0.0));
    for (std::size_t i = 0; i < na; ++i)
      for (std::size_t k = 0; k < nb; ++k)
        for (std::size_t j = 0; j < na; ++j)
          for (std::size_t l = 0; l < nb; ++l) out.transitions[i * nb + k][j * nb + l] = ta[i][j] * tb[k][l];
  }
  return out;
}

Project shuffle(const Project& a, const Project& b) {
  if (!a.transitions.empty() || !b.transitions.empty())
    fail(
        "shuffle cannot keep transition matrices (the interleaved words forget which function came last in each "
        "project); remove them or use product");
  const std::size_t na = a.functions.size(), nb = b.functions.size();
  checkCount(na + nb, "shuffle");
  Project out = a;
  out.space = sumSpace(*a.space, *b.space);
  out.functions.clear();
  const double wa = activeWeight(a), wb = activeWeight(b);
  const Matrix ia = identityMatrix(a.space->control_points.size()), ib = identityMatrix(b.space->control_points.size());
  for (const Function& f : a.functions) {
    Function h = f;
    h.matrix = kroneckerProduct(f.matrix, ib);
    h.weight = f.weight / wa;
    out.functions.push_back(std::move(h));
  }
  for (const Function& g : b.functions) {
    Function h = g;
    h.matrix = kroneckerProduct(ia, g.matrix);
    h.weight = g.weight / wb;
    out.functions.push_back(std::move(h));
  }
  out.transitions.clear();
  return out;
}

/// Both function lists (weights normalised per project) for an operation on the two matrices:
/// `byName` makes B's functions that share a name with one of A's that function. Free-form
/// projects must share their control points. `mapB` receives each B function's new index.
Project joinFunctions(const Project& a, const Project& b, bool byName, std::vector<std::uint32_t>& mapB,
                      const char* name) {
  if (a.space && a.space->control_points != b.space->control_points)
    fail(std::string(name) +
         " of two free-form projects needs the same control points (their functions then act on the same space)");
  Project out = a;
  out.functions.clear();
  out.transitions.clear();
  out.states.reset();
  const double wa = activeWeight(a), wb = activeWeight(b);
  for (const Function& f : a.functions) {
    Function g = f;
    g.weight = f.weight / wa;
    out.functions.push_back(std::move(g));
  }
  mapB.clear();
  for (const Function& f : b.functions) {
    std::size_t same = a.functions.size();
    if (byName)
      for (std::size_t k = 0; k < a.functions.size() && same == a.functions.size(); ++k)
        if (a.functions[k].name == f.name) same = k;
    if (same < a.functions.size()) {
      mapB.push_back(std::uint32_t(same));
      continue;
    }
    mapB.push_back(std::uint32_t(out.functions.size()));
    Function g = f;
    g.weight = f.weight / wb;
    out.functions.push_back(std::move(g));
  }
  checkCount(out.functions.size(), "combined IFS");
  return out;
}

using MatrixOp = IfsMatrix (*)(const IfsMatrix&, const IfsMatrix&);

/// `concat A B` lets A's chains continue into B's maps, as it always has: B's maps are applied to
/// A's points, so the words read B's part first (outermost): the paper's H̃_B ◇ H̃_A.
IfsMatrix concatBThenA(const IfsMatrix& a, const IfsMatrix& b) { return concatenation(b, a); }

/// The result of `op` on the two projects' matrices, stored as states. Throws ModelError (empty
/// path) when the operation does not apply or its result has no attractor.
void storeStates(Project& out, const Project& a, const Project& b, const std::vector<std::uint32_t>& mapB, MatrixOp op,
                 const char* name) {
  const IfsMatrix ma = ifsMatrixOf(a), mb = relabel(ifsMatrixOf(b), mapB);
  const IfsMatrix result = op(ma, mb);
  requireAttractor(result, name);
  setIfsMatrix(out, result);
}

Project matrixCombination(const Project& a, const Project& b, CombineOp op) {
  const char* name = combineOpName(op);
  std::vector<std::uint32_t> mapB;
  const bool byName = op == CombineOp::Intersection || op == CombineOp::MatrixUnion;
  MatrixOp fn = nullptr;
  switch (op) {
    case CombineOp::Union:
      fn = blockUnion;
      break;
    case CombineOp::Concat:
      fn = concatBThenA;
      break;
    case CombineOp::Product:
      fn = tensorProduct;
      break;
    case CombineOp::Shuffle:
      fn = tensorSum;
      break;
    case CombineOp::Intersection:
      fn = matrixIntersection;
      break;
    case CombineOp::Composition:
      fn = matrixComposition;
      break;
    case CombineOp::MatrixUnion:
      fn = matrixUnion;
      break;
  }
  Project out;
  if (op == CombineOp::Union && a.space) {
    // Different spaces are fine for a union: the functions embed as unionOrConcat embeds them.
    Project sa = a, sb = b;
    sa.transitions.clear(), sb.transitions.clear(), sa.states.reset(), sb.states.reset();
    out = unionOrConcat(sa, sb, false);
    out.transitions.clear();
    mapB.clear();
    for (std::size_t k = 0; k < b.functions.size(); ++k) mapB.push_back(std::uint32_t(a.functions.size() + k));
  } else if (op == CombineOp::Shuffle && a.space) {
    Project sa = a, sb = b;
    sa.transitions.clear(), sb.transitions.clear(), sa.states.reset(), sb.states.reset();
    out = shuffle(sa, sb);
    mapB.clear();
    for (std::size_t k = 0; k < b.functions.size(); ++k) mapB.push_back(std::uint32_t(a.functions.size() + k));
  } else {
    out = joinFunctions(a, b, byName, mapB, name);
  }
  storeStates(out, a, b, mapB, fn, name);
  return out;
}

}  // namespace

const char* combineOpName(CombineOp op) {
  switch (op) {
    case CombineOp::Union:
      return "union";
    case CombineOp::Concat:
      return "concat";
    case CombineOp::Product:
      return "product";
    case CombineOp::Shuffle:
      return "shuffle";
    case CombineOp::Intersection:
      return "intersection";
    case CombineOp::Composition:
      return "composition";
    case CombineOp::MatrixUnion:
      return "matrix-union";
  }
  return "union";
}

bool parseCombineOp(const std::string& name, CombineOp& out) {
  for (CombineOp op : {CombineOp::Union, CombineOp::Concat, CombineOp::Product, CombineOp::Shuffle,
                       CombineOp::Intersection, CombineOp::Composition, CombineOp::MatrixUnion})
    if (name == combineOpName(op)) {
      out = op;
      return true;
    }
  return false;
}

Project combineProjects(const Project& a, const Project& b, CombineOp op) {
  const bool freeA = isFreeForm(a), freeB = isFreeForm(b);
  if (freeA != freeB)
    fail(std::string("the first project is a ") + (freeA ? "free-form (control point)" : "grid") +
         " IFS and the second a " + (freeB ? "free-form (control point)" : "grid") +
         " one; combine needs two of the same kind");
  if (a.final_function != b.final_function)
    fail(
        "the two projects have different final functions, and the combination can apply only one; make them equal "
        "or remove one");
  const char* name = combineOpName(op);
  const bool stated = a.states || b.states;
  Project out;
  switch (op) {
    case CombineOp::Union:
      out = stated ? matrixCombination(a, b, op) : unionOrConcat(a, b, false);
      break;
    case CombineOp::Concat:
      // Grid projects without states keep the concat they always had (A's chains may continue
      // into B's maps); the rest is the paper's concatenation of the matrices.
      out = !stated && !freeA ? unionOrConcat(a, b, true) : matrixCombination(a, b, op);
      break;
    case CombineOp::Product:
      if (freeA && stated)
        fail("product of free-form projects steps both IFSs at once and cannot follow states; use shuffle");
      out = freeA ? product(a, b) : matrixCombination(a, b, op);
      break;
    case CombineOp::Shuffle:
      out = freeA && !stated ? shuffle(a, b) : matrixCombination(a, b, op);
      break;
    case CombineOp::Intersection:
    case CombineOp::Composition:
    case CombineOp::MatrixUnion:
      out = matrixCombination(a, b, op);
      break;
  }
  // A's construction tree does not describe the combination (a tree over both is built in the
  // modeller's tree window, or by hand).
  out.construction.reset();
  try {
    validateProject(out);
  } catch (const ModelError& e) {
    fail(std::string("the ") + name + " is not a valid project: " + e.what());
  }
  return out;
}

}  // namespace gridifs
