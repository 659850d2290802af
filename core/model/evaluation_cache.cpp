#include "model/evaluation_cache.h"

#include "model/stack_evaluator.h"

namespace gridifs {

std::shared_ptr<const Grid> EvaluationCache::cached(const Function& fn, std::size_t slot, const std::string& path,
                                                    double time) const {
  if (entries_.size() <= slot) entries_.resize(slot + 1);
  auto& entry = entries_[slot];
  if (entry && entry->function == fn && (entry->time == time || !dependsOnTime(fn))) return entry->grid;
  entry.reset();  // a failed evaluation leaves no stale grid behind
  auto grid = evaluateFunctionAt(fn, path, time);
  entry = Entry{fn, time, grid};
  return grid;
}

std::shared_ptr<const Grid> EvaluationCache::function(const Project& project, std::size_t index) const {
  return cached(project.functions.at(index), index + 1, "functions[" + std::to_string(index) + "]", project.time);
}

std::shared_ptr<const Grid> EvaluationCache::finalFunction(const Project& project) const {
  if (!project.final_function) return nullptr;
  return cached(*project.final_function, 0, "final", project.time);
}

}  // namespace gridifs
