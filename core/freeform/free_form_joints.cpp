#include "freeform/free_form_joints.h"

#include <cmath>
#include <optional>
#include <sstream>

#include "freeform/free_form.h"
#include "freeform/free_form_basis.h"

namespace gridifs {
namespace {

using Row = std::vector<double>;

double distance(const Row& a, const Row& b) {
  double d = 0.0;
  for (std::size_t j = 0; j < a.size() && j < b.size(); ++j) d += std::abs(a[j] - b[j]);
  return d;
}

/// c with c·T = c and Σc = 1 (the piece's fixed point); power iteration when the system is
/// singular (1 a multiple eigenvalue).
Row fixedPoint(const BarycentricMatrix& t) {
  const std::size_t m = t.size();
  BarycentricMatrix a(m, Row(m)), b(m, Row{0.0});
  for (std::size_t i = 0; i < m; ++i)
    for (std::size_t j = 0; j < m; ++j) a[i][j] = t[j][i] - (i == j ? 1.0 : 0.0);
  a[m - 1].assign(m, 1.0);
  b[m - 1][0] = 1.0;
  try {
    const BarycentricMatrix s = solveLinear(a, b);
    Row c(m);
    for (std::size_t i = 0; i < m; ++i) c[i] = s[i][0];
    return c;
  } catch (const ModelError&) {
    Row c(m, 1.0 / double(m));
    for (int k = 0; k < 2000; ++k) c = applyMatrix(c, t);
    return c;
  }
}

/// The points of an edge: `start` mapped by every word of depth ≤ 3 over `pieces` (the edge's
/// pieces in order), and `end`. Word w1…wd maps c to c·T_wd···T_w1, the point of address w1…wd.
std::vector<Row> edgePoints(const Row& start, const Row& end, const std::vector<const BarycentricMatrix*>& pieces) {
  std::vector<Row> out{start, end};
  std::vector<std::vector<std::size_t>> words{{}};
  for (int depth = 1; depth <= 3; ++depth) {
    std::vector<std::vector<std::size_t>> longer;
    for (const auto& w : words)
      for (std::size_t p = 0; p < pieces.size(); ++p) {
        longer.push_back(w);
        longer.back().push_back(p);
      }
    words = longer;
    for (const auto& w : words) {
      Row c = start;
      for (auto it = w.rbegin(); it != w.rend(); ++it) c = applyMatrix(c, *pieces[*it]);
      out.push_back(c);
    }
  }
  return out;
}

double edgeGap(const std::vector<Row>& a, const BarycentricMatrix& ta, const std::vector<Row>& b,
               const BarycentricMatrix& tb) {
  double gap = 0.0;
  for (std::size_t k = 0; k < a.size() && k < b.size(); ++k)
    gap = std::max(gap, distance(applyMatrix(a[k], ta), applyMatrix(b[k], tb)));
  return gap;
}

struct PatchLayout {
  std::size_t columns = 0, rows = 0;
  std::vector<std::size_t> at;  // function index of piece (I, K) at I·rows + K
};

/// The functions as a full grid of pieces named qIK, if they are one.
std::optional<PatchLayout> patchLayout(const Project& project) {
  PatchLayout layout;
  for (const Function& f : project.functions) {
    if (f.name.size() != 3 || f.name[0] != 'q' || !std::isdigit(static_cast<unsigned char>(f.name[1])) ||
        !std::isdigit(static_cast<unsigned char>(f.name[2])))
      return std::nullopt;
    layout.columns = std::max<std::size_t>(layout.columns, std::size_t(f.name[1] - '0') + 1);
    layout.rows = std::max<std::size_t>(layout.rows, std::size_t(f.name[2] - '0') + 1);
  }
  if (layout.columns * layout.rows != project.functions.size()) return std::nullopt;
  layout.at.assign(project.functions.size(), project.functions.size());
  for (std::size_t i = 0; i < project.functions.size(); ++i) {
    const std::string& n = project.functions[i].name;
    std::size_t& slot = layout.at[std::size_t(n[1] - '0') * layout.rows + std::size_t(n[2] - '0')];
    if (slot != project.functions.size()) return std::nullopt;  // a name twice
    slot = i;
  }
  return layout;
}

void addPatchJoints(const Project& project, const PatchLayout& g, std::vector<FreeFormJoint>& out) {
  auto t = [&](std::size_t i, std::size_t k) -> const BarycentricMatrix& {
    return project.functions[g.at[i * g.rows + k]].matrix;
  };
  const std::size_t a = g.columns - 1, b = g.rows - 1;
  const Row c00 = fixedPoint(t(0, 0)), c10 = fixedPoint(t(a, 0)), c01 = fixedPoint(t(0, b)), c11 = fixedPoint(t(a, b));
  std::vector<const BarycentricMatrix*> left, right, bottom, top;
  for (std::size_t k = 0; k <= b; ++k) left.push_back(&t(0, k)), right.push_back(&t(a, k));
  for (std::size_t i = 0; i <= a; ++i) bottom.push_back(&t(i, 0)), top.push_back(&t(i, b));
  const auto leftEdge = edgePoints(c00, c01, left), rightEdge = edgePoints(c10, c11, right);
  const auto bottomEdge = edgePoints(c00, c10, bottom), topEdge = edgePoints(c01, c11, top);
  for (std::size_t i = 0; i <= a; ++i)
    for (std::size_t k = 0; k <= b; ++k) {
      if (i < a)
        out.push_back({g.at[i * g.rows + k], g.at[(i + 1) * g.rows + k], true,
                       edgeGap(rightEdge, t(i, k), leftEdge, t(i + 1, k))});
      if (k < b)
        out.push_back(
            {g.at[i * g.rows + k], g.at[i * g.rows + k + 1], true, edgeGap(topEdge, t(i, k), bottomEdge, t(i, k + 1))});
    }
}

bool usable(const Project& project) {
  if (!project.space || project.functions.size() < 2) return false;
  const std::size_t m = project.space->control_points.size();
  for (const Function& f : project.functions) {
    if (f.kind != FunctionKind::Matrix || f.matrix.size() != m) return false;
    for (const auto& row : f.matrix)
      if (row.size() != m) return false;
  }
  return true;
}

}  // namespace

std::vector<FreeFormJoint> freeFormJoints(const Project& project) {
  std::vector<FreeFormJoint> out;
  if (!usable(project)) return out;
  if (const auto layout = patchLayout(project)) {
    addPatchJoints(project, *layout, out);
    return out;
  }
  const auto& fs = project.functions;
  const Row first = fixedPoint(fs.front().matrix), last = fixedPoint(fs.back().matrix);
  for (std::size_t i = 0; i + 1 < fs.size(); ++i)
    out.push_back({i, i + 1, false, distance(applyMatrix(last, fs[i].matrix), applyMatrix(first, fs[i + 1].matrix))});
  return out;
}

std::vector<FreeFormJoint> failingJoints(const Project& project) {
  std::vector<FreeFormJoint> out;
  for (const FreeFormJoint& j : freeFormJoints(project))
    if (!(j.gap <= kJointTolerance)) out.push_back(j);
  return out;
}

std::vector<FreeFormJoint> brokenJoints(const Project& before, const Project& after) {
  std::vector<FreeFormJoint> out;
  const auto held = freeFormJoints(before);
  for (const FreeFormJoint& j : failingJoints(after))
    for (const FreeFormJoint& h : held)
      if (h.first == j.first && h.second == j.second && h.edge == j.edge && h.gap <= kJointTolerance) out.push_back(j);
  return out;
}

std::string describeJoint(const Project& project, const FreeFormJoint& joint) {
  auto name = [&](std::size_t i) {
    return i < project.functions.size() ? project.functions[i].name : "function " + std::to_string(i);
  };
  std::ostringstream s;
  s.precision(3);
  if (joint.edge)
    s << name(joint.first) << " | " << name(joint.second) << ": the pieces differ along their shared edge (gap "
      << joint.gap << "); a fractal patch needs them equal";
  else
    s << name(joint.first) << " -> " << name(joint.second) << ": the end of " << name(joint.first)
      << " is not the start of " << name(joint.second) << " (gap " << joint.gap
      << "); a fractal curve needs them equal";
  return s.str();
}

}  // namespace gridifs
