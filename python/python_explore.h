#pragma once
// gridifs.random and gridifs.mutate: the explore verbs' draws (core/explore/explore.h) for
// scripts, each judged worth looking at as `gridifs random` and `gridifs mutate` judge them.
#include <pybind11/pybind11.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "python/python_project.h"

namespace gridifs::python {

std::unique_ptr<PythonProject> randomProject(const std::string& style, std::optional<std::uint64_t> seed,
                                             int functions);

std::unique_ptr<PythonProject> mutatedProject(const PythonProject& parent, std::optional<std::uint64_t> seed,
                                              double strength, const std::vector<std::string>& keep,
                                              const PythonProject* mate);

}  // namespace gridifs::python
