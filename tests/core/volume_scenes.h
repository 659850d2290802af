#pragma once
// The volume scene several volume tests share: two median functions, a sphere and a box.

namespace gridifs::test_support {

inline const char* const kTwoMedians = R"({
  "format": "gridifs", "version": 1,
  "functions": [
    {"name": "A", "kind": "median", "weight": 2,
     "set": {"primitive": "sphere", "center": [-0.45, 0, 0], "radius": 0.3}},
    {"name": "B", "kind": "median", "weight": 1, "rotate": 0.0, "color": [0.2, 0.4, 1],
     "set": {"primitive": "box", "center": [0.45, 0, 0], "size": [0.4, 0.4, 0.4]}}
  ],
  "volume": {"resolution": 32, "iterations": 200, "skip": 20, "seed": 3, "samples": 100000}
})";

}  // namespace gridifs::test_support
