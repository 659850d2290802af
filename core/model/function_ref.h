#pragma once
// Which function of a project an edit addresses: one of the IFS's functions (by index), or the
// final function, which is no member of the loop but is edited like one (its grid, its
// operation stack, its selection and placement). Every panel reaches the function it edits
// through one FunctionRef, so the final function needs no panels of its own.
#include <string>

#include "model/project.h"

namespace gridifs {

class FunctionRef {
 public:
  /// Function `index` of the IFS.
  constexpr explicit FunctionRef(int index = 0) : index_(index < 0 ? 0 : index) {}
  /// The final function (Project::final_function).
  static constexpr FunctionRef finalFunction() {
    FunctionRef ref;
    ref.index_ = kFinal;
    return ref;
  }

  bool isFinal() const { return index_ == kFinal; }
  /// The index in Project::functions; meaningless for the final function.
  int index() const { return index_; }

  /// Whether `project` has the function this refers to.
  bool existsIn(const Project& project) const;
  /// The function itself. Throws ModelError when `project` has no such function.
  Function& in(Project& project) const;
  const Function& in(const Project& project) const;
  /// Its JSON path in a project file: "functions[2]" or "final" (keyframe tracks, messages).
  std::string path() const;

  bool operator==(const FunctionRef&) const = default;

 private:
  static constexpr int kFinal = -1;
  int index_ = 0;
};

}  // namespace gridifs
