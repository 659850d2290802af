// Index-box selections combined left to right from the empty set (Gröller & Wegenkittl 1994, §4.4).
#include <gtest/gtest.h>

#include <random>
#include <set>
#include <tuple>

#include "model/selection.h"

using namespace gridifs;

namespace {
using Node = std::tuple<int, int, int>;

std::set<Node> boxSet(const SelectionBox& b, const Index3& res) {
  std::set<Node> s;
  for (int k = 0; k < res[2]; ++k)
    for (int j = 0; j < res[1]; ++j)
      for (int i = 0; i < res[0]; ++i)
        if (i >= std::min(b.i[0], b.i[1]) && i <= std::max(b.i[0], b.i[1]) && j >= std::min(b.j[0], b.j[1]) &&
            j <= std::max(b.j[0], b.j[1]) && k >= std::min(b.k[0], b.k[1]) && k <= std::max(b.k[0], b.k[1]))
          s.insert({i, j, k});
  return s;
}
}  // namespace

TEST(Selection, EmptySelectionMeansEveryNode) {
  const auto mask = selectionMask({}, {3, 4, 5});
  ASSERT_EQ(mask.size(), 60u);
  for (auto m : mask) EXPECT_EQ(m, 1);
}

TEST(Selection, BooleanCombinationsMatchSetAlgebra) {
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> coord(0, 6), opPick(0, 3);
  const Index3 res{6, 5, 7};
  for (int trial = 0; trial < 200; ++trial) {
    Selection sel;
    std::set<Node> expected;
    const int boxes = 1 + trial % 5;
    for (int b = 0; b < boxes; ++b) {
      SelectionBox box{{coord(rng), coord(rng)},
                       {coord(rng), coord(rng)},
                       {coord(rng), coord(rng)},
                       static_cast<SelectionOp>(opPick(rng))};
      sel.push_back(box);
      const std::set<Node> s = boxSet(box, res);
      std::set<Node> next;
      switch (box.op) {
        case SelectionOp::Or:
          next = expected;
          next.insert(s.begin(), s.end());
          break;
        case SelectionOp::And:
          for (const Node& n : expected)
            if (s.count(n)) next.insert(n);
          break;
        case SelectionOp::Xor:
          for (const Node& n : expected)
            if (!s.count(n)) next.insert(n);
          for (const Node& n : s)
            if (!expected.count(n)) next.insert(n);
          break;
        case SelectionOp::Minus:
          for (const Node& n : expected)
            if (!s.count(n)) next.insert(n);
          break;
      }
      expected = next;
    }
    const auto mask = selectionMask(sel, res);
    for (int k = 0; k < res[2]; ++k)
      for (int j = 0; j < res[1]; ++j)
        for (int i = 0; i < res[0]; ++i)
          ASSERT_EQ(mask[i + res[0] * (j + res[1] * k)] != 0, expected.count({i, j, k}) == 1) << trial;
  }
}

TEST(Selection, BoxesBeyondTheGridAreClamped) {
  Selection sel{{{2, 100}, {0, 0}, {0, 0}, SelectionOp::Or}};
  const auto mask = selectionMask(sel, {4, 2, 2});
  EXPECT_EQ(mask[0], 0);
  EXPECT_EQ(mask[2], 1);
  EXPECT_EQ(mask[3], 1);
  Selection outside{{{50, 60}, {0, 1}, {0, 1}, SelectionOp::Or}};
  for (auto m : selectionMask(outside, {4, 2, 2})) EXPECT_EQ(m, 0);
}

TEST(Selection, AndOnTheEmptySetSelectsNothing) {
  Selection sel{{{0, 3}, {0, 3}, {0, 3}, SelectionOp::And}};
  for (auto m : selectionMask(sel, {4, 4, 4})) EXPECT_EQ(m, 0);
}
