#pragma once
// Evaluated grids of a project's functions, kept until a function changes: an edit of one
// function re-evaluates that function only. The Document owns one; the compiled render snapshot
// and the deterministic algorithm read through it, so they need a Project and this cache, not
// the undo Document.
//
// Thread-safety: not thread-safe (the cache fills lazily); use it on the thread that owns it.
// The grids it returns are immutable and may be shared with any thread.
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "model/grid.h"
#include "model/project.h"

namespace gridifs {

class EvaluationCache {
 public:
  /// The evaluated (distorted and placed) grid of `project.functions[index]` at `project.time`
  /// (a time-independent function is not re-evaluated when only the time changes). Throws ModelError
  /// with a path such as `functions[1].ops[2].x`.
  std::shared_ptr<const Grid> function(const Project& project, std::size_t index) const;
  /// The same for the final function; null when the project has none.
  std::shared_ptr<const Grid> finalFunction(const Project& project) const;

 private:
  struct Entry {
    Function function;
    double time = 0.0;  // compared only for functions whose grid depends on the time
    std::shared_ptr<const Grid> grid;
  };
  std::shared_ptr<const Grid> cached(const Function& fn, std::size_t slot, const std::string& path, double time) const;

  mutable std::vector<std::optional<Entry>> entries_;  // slot 0: final function; slot i + 1: function i
};

}  // namespace gridifs
