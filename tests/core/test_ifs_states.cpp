// IFS matrices with states in a project (Thollot, Zair, Tosan & Vandorpe 1997, §3.2): the file
// format, validation with JSON paths, and the attractor ⋃_{i∈Q_I, j∈Q_F} Ã(H̃)_ij as the chaos
// game and the deterministic algorithm build it. With four maps f_a(p) = 0.4·p + 0.6·v_a toward the
// corners v_a of a tetrahedron the copies f_a(T) are disjoint, so a point's address is read off its
// position, outermost map first, and the words a render produces can be compared with the words
// the matrix accepts.
#include <gtest/gtest.h>

#include <array>
#include <map>
#include <set>

#include "deterministic_samples.h"
#include "freeform/state_expansion.h"
#include "freeform/transition_matrix.h"
#include "io/project_io.h"
#include "mesh/deterministic_ifs.h"
#include "model_error_text.h"
#include "render/chaos_renderer.h"
#include "render/compiled_ifs.h"
#include "schema/validation.h"

using namespace gridifs;
using namespace gridifs::test_support;

namespace {

using Prefix = std::array<int, 3>;

constexpr double kScale = 0.4;

/// Four maps f_a(p) = 0.4·p + 0.6·v_a: λ_a ≥ 0.6 on f_a(T), every other λ_b ≤ 0.4.
Project cornersProject() {
  Project p = sierpinskiProject();
  for (std::size_t a = 0; a < 4; ++a) {
    p.functions[a].placement.scale = Vec3(kScale);
    p.functions[a].placement.translate = (1.0 - kScale) * tetrahedronCorners()[a];
  }
  return p;
}

/// The level-1 cell holding p (λ_a > 1/2 in the tetrahedron's barycentric coordinates), else −1.
int cellOf(Vec3 p) {
  for (int i = 0; i < 4; ++i)
    if ((1.0 + glm::dot(p, tetrahedronCorners()[std::size_t(i)])) / 4.0 > 0.5) return i;
  return -1;
}

/// The first three maps of p's address (outermost first), or nullopt outside the cells.
std::optional<Prefix> addressPrefix(Vec3 p) {
  Prefix out{};
  for (int k = 0; k < 3; ++k) {
    const int a = cellOf(p);
    if (a < 0) return std::nullopt;
    out[std::size_t(k)] = a;
    p = (p - (1.0 - kScale) * tetrahedronCorners()[std::size_t(a)]) / kScale;  // f_a⁻¹
  }
  return out;
}

/// How often each address prefix occurs among the chaos game's points.
std::map<Prefix, int> renderedPrefixes(const Project& p, std::int64_t samples, int* classified = nullptr) {
  RenderJob job = RenderJob::fromProject(p, 2);
  job.samples = samples;
  std::map<Prefix, int> counts;
  int n = 0;
  generatePoints(*compileIfs(p), job, [&](const PointBatch& b, const RenderStats&) {
    for (std::size_t i = 0; i < b.count; ++i)
      if (auto prefix = addressPrefix({b.xyz[3 * i], b.xyz[3 * i + 1], b.xyz[3 * i + 2]})) {
        ++counts[*prefix];
        ++n;
      }
    return true;
  });
  if (classified) *classified = n;
  return counts;
}

/// The 3-letter prefixes of the words the matrix accepts (each extends to words of every length).
std::set<Prefix> acceptedPrefixes(const Project& p) {
  std::set<Prefix> out;
  for (const FunctionWord& w : acceptedWords(trimmed(ifsMatrixOf(p)), 8))
    if (w.size() >= 3) out.insert({int(w[0]), int(w[1]), int(w[2])});
  return out;
}

Project withStates(IfsStates s) {
  Project p = cornersProject();
  p.states = std::move(s);
  return p;
}

std::string statesLoadError(const std::string& statesJson, bool transitions = false) {
  std::string text = serializeProject(sierpinskiProject());
  text.insert(text.rfind('}'), std::string(",\"states\": ") + statesJson +
                                   (transitions ? ",\"transitions\": [[1,1,1,1],[1,1,1,1],[1,1,1,1],[1,1,1,1]]" : "") +
                                   "\n");
  return modelErrorText([&] { parseProject(text); });
}

}  // namespace

TEST(IfsStates, JsonRoundTripWithIndicesAndNames) {
  std::string text = serializeProject(sierpinskiProject());
  text.insert(
      text.rfind('}'),
      ",\"states\": {\"matrix\": [[[0, \"corner1\"], [2]], [[], [0, 2, 3]]], \"initial\": [0], \"final\": [1]}\n");
  const Project p = parseProject(text);
  ASSERT_TRUE(p.states);
  EXPECT_EQ(p.states->matrix[0][0], (std::vector<std::uint32_t>{0, 1}));
  EXPECT_EQ(p.states->matrix[1][1], (std::vector<std::uint32_t>{0, 2, 3}));
  EXPECT_EQ(p.states->initial, std::vector<std::uint32_t>{0});
  EXPECT_EQ(parseProject(serializeProject(p)), p);
  EXPECT_EQ(serializeProject(sierpinskiProject()).find("states"), std::string::npos);  // absent stays absent
}

TEST(IfsStates, BadInputNamesTheJsonPath) {
  EXPECT_NE(statesLoadError(R"({"matrix": [[[0], [1]], [[2]]], "initial": [0], "final": [1]})")
                .find("states.matrix[1]: expected 2 entries"),
            std::string::npos);
  EXPECT_NE(statesLoadError(R"({"matrix": [[[0], [1]], [[2, 1, 7], [3]]], "initial": [0], "final": [1]})")
                .find("states.matrix[1][0][2]: function 7 does not exist"),
            std::string::npos);
  EXPECT_NE(statesLoadError(R"({"matrix": [[["nope"]]], "initial": [0], "final": [0]})")
                .find("states.matrix[0][0][0]: no function is named \"nope\""),
            std::string::npos);
  EXPECT_NE(statesLoadError(R"({"matrix": [[[0]]], "initial": [], "final": [0]})").find("states.initial: the initial"),
            std::string::npos);
  EXPECT_NE(statesLoadError(R"({"matrix": [[[0]]], "initial": [0], "final": [3]})")
                .find("states.final[0]: state 3 does not exist"),
            std::string::npos);
  EXPECT_NE(statesLoadError(R"({"matrix": [[[0]]], "initial": [0], "final": [0]})", true)
                .find("states: a project has either states or transitions"),
            std::string::npos);
  EXPECT_NE(statesLoadError(R"({"matrix": [[[], []], [[], []]], "initial": [0], "final": [1]})")
                .find("states: the state matrix has no path"),
            std::string::npos);
  EXPECT_NE(statesLoadError(R"({"matrix": [[[], [0]], [[], []]], "initial": [0], "final": [1]})")
                .find("only finitely many words"),
            std::string::npos);
  EXPECT_NE(statesLoadError(R"({"matrix": [], "initial": [0], "final": [0]})").find("states.matrix: the matrix needs"),
            std::string::npos);
}

TEST(IfsStates, EquivalentToATransitionMatrix) {
  // No function twice in a row, as transitions and as the states ifsMatrixOf builds from them.
  Project t = cornersProject();
  t.transitions.assign(4, std::vector<double>(4, 1.0));
  for (int i = 0; i < 4; ++i) t.transitions[std::size_t(i)][std::size_t(i)] = 0.0;
  Project s = cornersProject();
  setIfsMatrix(s, ifsMatrixOf(t));
  ASSERT_TRUE(s.states);
  EXPECT_TRUE(s.transitions.empty());
  validateProject(s);
  int nt = 0, ns = 0;
  const auto ct = renderedPrefixes(t, 200000, &nt), cs = renderedPrefixes(s, 200000, &ns);
  const auto allowed = acceptedPrefixes(s);
  EXPECT_EQ(allowed.size(), 4u * 3u * 3u);
  for (const auto& counts : {ct, cs})
    for (const auto& [prefix, count] : counts)
      EXPECT_TRUE(allowed.count(prefix)) << prefix[0] << prefix[1] << prefix[2];
  for (const Prefix& prefix : allowed) {
    EXPECT_GT(ct.count(prefix) ? ct.at(prefix) : 0, nt / 36 / 3);
    EXPECT_GT(cs.count(prefix) ? cs.at(prefix) : 0, ns / 36 / 3);
  }
}

TEST(IfsStates, InitialStatesConstrainTheOutermostMap) {
  // From state 0 only f_0, into state 1 which reads anything: the attractor is f_0(A), the corner
  // copy (state 0 has no entry into it: its maps are peeks).
  Project corner = withStates({{{{}, {0}}, {{}, {0, 1, 2, 3}}}, {0}, {1}});
  validateProject(corner);
  int n = 0;
  const auto counts = renderedPrefixes(corner, 200000, &n);
  EXPECT_GT(n, 20000);
  std::set<Prefix> seen;
  for (const auto& [prefix, count] : counts) {
    EXPECT_EQ(prefix[0], 0);
    seen.insert(prefix);
  }
  EXPECT_EQ(seen.size(), 16u);  // 0 then any two maps
  // Words f_0^k f_1 (f_2 | f_3)^ω: state 1 is not initial, so its maps are hidden until a word
  // leaves state 0. The reverse reading would put f_2 and f_3 outermost.
  Project hidden = withStates({{{{0}, {1}}, {{}, {2, 3}}}, {0}, {1}});
  const auto allowed = acceptedPrefixes(hidden);
  EXPECT_EQ(allowed,
            (std::set<Prefix>{{0, 0, 0}, {0, 0, 1}, {0, 1, 2}, {0, 1, 3}, {1, 2, 2}, {1, 2, 3}, {1, 3, 2}, {1, 3, 3}}));
  const auto hc = renderedPrefixes(hidden, 400000, &n);
  EXPECT_GT(n, 1000);
  for (const auto& [prefix, count] : hc) EXPECT_TRUE(allowed.count(prefix)) << prefix[0] << prefix[1] << prefix[2];
  for (const Prefix& prefix : {Prefix{1, 2, 3}, Prefix{1, 3, 2}, Prefix{0, 1, 2}})
    EXPECT_GT(hc.count(prefix) ? hc.at(prefix) : 0, 10);
}

TEST(IfsStates, FinalStatesConstrainWhichWordsGoOn) {
  // State 0 reads f_0, f_1 and may go to state 1 with f_2; state 1 reads f_3. With Q_F = {0} a
  // word never leaves state 0 (the edge v_0 v_1); with Q_F = {1} it may, once.
  Project stay = withStates({{{{0, 1}, {2}}, {{}, {3}}}, {0}, {0}});
  for (const auto& [prefix, count] : renderedPrefixes(stay, 100000))
    for (int a : prefix) EXPECT_LT(a, 2);
  Project leave = withStates({{{{0, 1}, {2}}, {{}, {3}}}, {0}, {1}});
  std::set<int> letters;
  for (const auto& [prefix, count] : renderedPrefixes(leave, 200000)) {
    EXPECT_TRUE(acceptedPrefixes(leave).count(prefix));
    letters.insert(prefix.begin(), prefix.end());
  }
  EXPECT_EQ(letters, (std::set<int>{0, 1, 2, 3}));
}

TEST(IfsStates, DeterministicBuildsTheAcceptedWords) {
  BaseMeshSpec spec;
  spec.shape = BaseShape::Cube;
  const MeshCounts base = countMesh(refineBase(loadCoarseBase(spec), spec));
  DeterministicOptions options;
  options.depth = 3;
  // The corner: f_0 then any two maps, 16 copies all inside f_0(X) = [0.2, 1]^3.
  const Project corner = withStates({{{{}, {0}}, {{}, {0, 1, 2, 3}}}, {0}, {1}});
  const DeterministicMesh out = runDeterministic(snapshotDeterministicIfs(corner), spec, options);
  EXPECT_EQ(out.plan.copies, 16u);
  EXPECT_EQ(out.mesh.n_faces(), 16u * base.faces);
  for (auto v : out.mesh.vertices())
    for (int d = 0; d < 3; ++d) EXPECT_GE(out.mesh.point(v)[d], -1e-5f);
  // f_0^k f_1 (f_2 | f_3)*: the eight prefixes of length 3.
  const Project hidden = withStates({{{{0}, {1}}, {{}, {2, 3}}}, {0}, {1}});
  EXPECT_EQ(runDeterministic(snapshotDeterministicIfs(hidden), spec, options).plan.copies, 8u);
}

TEST(IfsStates, FunctionListEditsRenumberTheStates) {
  Project p = withStates({{{{0, 1}, {2}}, {{}, {3}}}, {0}, {1}});
  eraseFunction(p, 1);
  EXPECT_EQ(p.states->matrix[0][0], std::vector<std::uint32_t>{0});
  EXPECT_EQ(p.states->matrix[0][1], std::vector<std::uint32_t>{1});
  EXPECT_EQ(p.states->matrix[1][1], std::vector<std::uint32_t>{2});
  swapFunctions(p, 0, 2);
  EXPECT_EQ(p.states->matrix[0][0], std::vector<std::uint32_t>{2});
  validateProject(p);
}
