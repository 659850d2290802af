// The transition matrix (Thollot, Zair, Tosan & Vandorpe §3.2; flam3's xaos): file format,
// validation, the chaos game's Markov chain and the deterministic algorithm's allowed words.
#include <gtest/gtest.h>

#include <array>
#include <map>
#include <set>

#include "deterministic_samples.h"
#include "freeform/transition_matrix.h"
#include "io/project_io.h"
#include "mesh/deterministic_ifs.h"
#include "model_error_text.h"
#include "render/chaos_renderer.h"
#include "render/compiled_ifs.h"

using namespace gridifs;
using namespace gridifs::test_support;

namespace {

Project noRepeatSierpinski() {
  Project p = sierpinskiProject();
  p.transitions.assign(4, std::vector<double>(4, 1.0));
  for (int i = 0; i < 4; ++i) p.transitions[std::size_t(i)][std::size_t(i)] = 0.0;
  return p;
}

/// Barycentric coordinates in the regular tetrahedron of tetrahedronCorners(): λ_i = (1 + p·v_i)/4.
std::array<double, 4> barycentric(Vec3 p) {
  std::array<double, 4> l{};
  for (int i = 0; i < 4; ++i) l[std::size_t(i)] = (1.0 + glm::dot(p, tetrahedronCorners()[std::size_t(i)])) / 4.0;
  return l;
}

/// The level-1 cell f_a(T) holding p when p is clearly inside one (λ_a > 1/2 + margin), else −1.
int cellWithMargin(Vec3 p, double margin) {
  const auto l = barycentric(p);
  for (int i = 0; i < 4; ++i)
    if (l[std::size_t(i)] > 0.5 + margin) return i;
  return -1;
}

std::string transitionsError(const std::string& text) {
  return test_support::modelErrorText([&] { parseProject(text); });
}

}  // namespace

TEST(Transitions, JsonRoundTrip) {
  Project p = noRepeatSierpinski();
  p.transitions[1][2] = 2.5;
  const Project back = parseProject(serializeProject(p));
  EXPECT_EQ(back.transitions, p.transitions);
  EXPECT_EQ(back, p);
  // Absent stays absent (version-1 files are unchanged).
  const std::string plain = serializeProject(sierpinskiProject());
  EXPECT_EQ(plain.find("transitions"), std::string::npos);
  EXPECT_TRUE(parseProject(plain).transitions.empty());
}

TEST(Transitions, BadMatricesAreRefusedWithAJsonPath) {
  const std::string base = serializeProject(sierpinskiProject());
  auto with = [&](const std::string& matrix) {
    std::string text = base;
    text.insert(text.rfind('}'), ",\"transitions\": " + matrix + "\n");
    return transitionsError(text);
  };
  EXPECT_NE(with("[[1,1,1,1],[1,1,1,1],[1,1,1,1]]").find("transitions: expected 4 rows"), std::string::npos);
  EXPECT_NE(with("[[1,1,1,1],[1,1,1],[1,1,1,1],[1,1,1,1]]").find("transitions[1]: expected 4 entries"),
            std::string::npos);
  EXPECT_NE(with("[[1,1,1,1],[1,1,-1,1],[1,1,1,1],[1,1,1,1]]").find("transitions[1][2]"), std::string::npos);
  EXPECT_NE(with("[[1,1,1,1],[1,1,1,1],[0,0,0,0],[1,1,1,1]]").find("transitions[2]: function 2 can be followed by no"),
            std::string::npos);
  EXPECT_NE(with("[[1,1,1,1],[1,1,\"x\",1],[1,1,1,1],[1,1,1,1]]").find("transitions[1][2]: expected a number"),
            std::string::npos);
  EXPECT_NE(with("{\"a\": 1}").find("transitions: expected an array"), std::string::npos);
  EXPECT_NE(with("[[1,1,1,1],[1,1,1,1],[1,1,1,1],[1,1,1,1e400]]").size(), 0u);  // not representable
  // A row may rely only on unmuted functions.
  Project p = noRepeatSierpinski();
  p.functions[3].muted = true;
  p.transitions[2] = {0, 0, 0, 1};
  EXPECT_THROW(validateProject(p), ModelError);
  p.transitions[2] = {1, 0, 0, 1};
  EXPECT_NO_THROW(validateProject(p));
  p.transitions[3] = {0, 0, 0, 0};  // a muted function's row does not matter
  EXPECT_NO_THROW(validateProject(p));
}

TEST(Transitions, ChaosGameVisitsOnlyAllowedLevelTwoCells) {
  const Project p = noRepeatSierpinski();
  const auto ifs = compileIfs(p);
  ASSERT_EQ(ifs->transitionAlias.size(), 5u * 4u);
  // The kernel's walk: row 0 is the first-function row (last in transitionAlias), row i + 1 the
  // row after function i, and each entry points at the row after its outcome.
  ASSERT_EQ(ifs->transitionWalk.size(), 5u * 4u);
  for (std::uint32_t c = 0; c < 4; ++c) {
    EXPECT_EQ(ifs->transitionWalk[c].threshold, ifs->transitionAlias[16 + c].threshold);
    EXPECT_EQ(ifs->transitionWalk[c].alias, ifs->transitionAlias[16 + c].alias);
    for (std::uint32_t row = 0; row < 5; ++row) {
      const TransitionStep& e = ifs->transitionWalk[4 * row + c];
      EXPECT_EQ(e.keepRow, 4 * (c + 1));
      EXPECT_EQ(e.aliasRow, 4 * (e.alias + 1));
    }
  }
  RenderJob job = RenderJob::fromProject(p, 2);
  job.samples = 400000;
  std::map<std::pair<int, int>, int> cells;
  int classified = 0;
  generatePoints(*ifs, job, [&](const PointBatch& b, const RenderStats&) {
    for (std::size_t i = 0; i < b.count; ++i) {
      const Vec3 q(b.xyz[3 * i], b.xyz[3 * i + 1], b.xyz[3 * i + 2]);
      const int a = cellWithMargin(q, 1e-4);  // last applied
      if (a < 0) continue;
      const int c = cellWithMargin(2.0 * q - tetrahedronCorners()[std::size_t(a)], 1e-4);  // applied before
      if (c < 0) continue;
      ++cells[{c, a}];
      ++classified;
    }
    return true;
  });
  EXPECT_GT(classified, 300000);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ((cells.count({i, i})), 0u) << "f_" << i << "∘f_" << i << " is forbidden";
    for (int j = 0; j < 4; ++j)
      if (i != j) {
        EXPECT_GT((cells[{i, j}]), classified / 24) << i << " then " << j;  // each allowed cell ~1/12
      }
  }
}

TEST(Transitions, UnrestrictedMatrixKeepsTheFastPathAndTheSameImage) {
  Project ones = sierpinskiProject();
  ones.transitions.assign(4, std::vector<double>(4, 1.0));
  EXPECT_TRUE(compileIfs(ones)->transitionAlias.empty());
  RenderJob job = RenderJob::fromProject(ones, 2);
  job.samples = 20000;
  std::vector<float> a, b;
  generatePoints(*compileIfs(ones), job, [&](const PointBatch& pb, const RenderStats&) {
    a.insert(a.end(), pb.xyz, pb.xyz + 3 * pb.count);
    return true;
  });
  generatePoints(*compileIfs(sierpinskiProject()), job, [&](const PointBatch& pb, const RenderStats&) {
    b.insert(b.end(), pb.xyz, pb.xyz + 3 * pb.count);
    return true;
  });
  EXPECT_EQ(a, b);
}

TEST(Transitions, DeterministicBuildsOnlyAllowedWords) {
  const Project p = noRepeatSierpinski();
  BaseMeshSpec spec;
  spec.shape = BaseShape::Cube;
  const MeshCounts base = countMesh(refineBase(loadCoarseBase(spec), spec));
  for (int depth = 0; depth <= 4; ++depth) {
    DeterministicOptions options;
    options.depth = depth;
    const DeterministicMesh out = runDeterministic(snapshotDeterministicIfs(p), spec, options);
    const std::uint64_t words = depth == 0 ? 1 : 4 * std::uint64_t(std::pow(3, depth - 1));
    EXPECT_EQ(out.plan.copies, words) << depth;
    EXPECT_EQ(out.mesh.n_faces(), words * base.faces) << depth;
    EXPECT_EQ(out.plan.total, countMesh(out.mesh));
    // Every copy's address has no repeated neighbouring digits, and each allowed word appears once.
    const auto address = addressProperty(out.mesh);
    std::set<int> seen;
    for (std::size_t f = 0; f < out.mesh.n_faces(); f += base.faces) {
      const int code = out.mesh.property(address, IfsMesh::FaceHandle(int(f)));
      seen.insert(code);
      const auto digits = decodeAddress(std::uint64_t(code), 4, depth);
      for (std::size_t k = 1; k < digits.size(); ++k) EXPECT_NE(digits[k - 1], digits[k]);
    }
    EXPECT_EQ(seen.size(), words);
  }
  // The copy f_a∘f_b(A) is where the composition puts it: check one vertex of one copy.
  DeterministicOptions options;
  options.depth = 2;
  const DeterministicMesh out = runDeterministic(snapshotDeterministicIfs(p), spec, options);
  const auto address = addressProperty(out.mesh);
  const IfsMesh base2 = refineBase(loadCoarseBase(spec), spec);
  for (std::size_t c = 0; c < 12; ++c) {
    const auto digits =
        decodeAddress(std::uint64_t(out.mesh.property(address, IfsMesh::FaceHandle(int(c * base.faces)))), 4, 2);
    const auto& v = tetrahedronCorners();
    const auto p0 = base2.point(IfsMesh::VertexHandle(0));
    const Vec3 inner = 0.5 * (Vec3(p0[0], p0[1], p0[2]) + v[std::size_t(digits[1])]);
    const Vec3 expected = 0.5 * (inner + v[std::size_t(digits[0])]);
    const auto got = out.mesh.point(IfsMesh::VertexHandle(int(c * base.vertices)));
    EXPECT_NEAR(got[0], expected.x, 1e-5);
    EXPECT_NEAR(got[1], expected.y, 1e-5);
    EXPECT_NEAR(got[2], expected.z, 1e-5);
  }
}

TEST(Transitions, StrongConnectivity) {
  EXPECT_EQ(transitionComponents(noRepeatSierpinski()).size(), 1u);
  Project p = sierpinskiProject();
  // 0 ↔ 1 and 2 ↔ 3, with 1 → 2 but nothing back: two components.
  p.transitions = {{0, 1, 0, 0}, {1, 0, 1, 0}, {0, 0, 0, 1}, {0, 0, 1, 0}};
  const auto components = transitionComponents(p);
  ASSERT_EQ(components.size(), 2u);
  EXPECT_EQ(components[0], (std::vector<std::size_t>{0, 1}));
  EXPECT_EQ(components[1], (std::vector<std::size_t>{2, 3}));
}

TEST(Transitions, FunctionListEditsKeepTheMatrixSquare) {
  Project p = noRepeatSierpinski();
  p.transitions[0][1] = 3.0;
  insertFunction(p, 1, p.functions[0]);
  ASSERT_EQ(p.transitions.size(), 5u);
  EXPECT_EQ(p.transitions[0][2], 3.0);  // old column 1 moved to 2
  EXPECT_EQ(p.transitions[1], std::vector<double>(5, 1.0));
  EXPECT_NO_THROW(validateProject(p));
  const Project before = [] {
    Project q = noRepeatSierpinski();
    q.transitions[0][1] = 3.0;
    return q;
  }();
  eraseFunction(p, 1);
  EXPECT_EQ(p.transitions, before.transitions);
  swapFunctions(p, 0, 1);
  EXPECT_EQ(p.transitions[1][0], 3.0);
  EXPECT_EQ(p.transitions[0][0], 0.0);
  EXPECT_NO_THROW(validateProject(p));
}
