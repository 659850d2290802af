#include "edit/operation_edits.h"

#include <map>

#include "base/errors.h"
#include "edit/edit_refs.h"
#include "model/selection.h"

namespace gridifs {
namespace {

/// The keyframe tracks follow the operations when the stack changes order.
std::string opsPath(FunctionRef function) { return function.path() + ".ops"; }

/// Whether MoveNodes may extend the last operation of `f` instead of appending one.
bool extendsLastNodes(const Function& f) {
  return !f.ops.empty() && std::holds_alternative<NodesOp>(f.ops.back().params) && !f.ops.back().muted &&
         f.ops.back().selection.empty();
}

Index3 nodeIndex(std::size_t n, const Index3& r) {
  const int i = int(n % std::size_t(r[0]));
  const int j = int((n / std::size_t(r[0])) % std::size_t(r[1]));
  const int k = int(n / (std::size_t(r[0]) * std::size_t(r[1])));
  return {i, j, k};
}

}  // namespace

Operation newOperation(const OperationSpec& spec, const Selection& selection, Center::Kind center, const Vec3& point,
                       const Grid& grid) {
  Operation op;
  op.selection = selection;
  op.center.kind = center;
  op.center.point = point;
  Vec3 anchor = point;
  if (center != Center::Kind::Point) {
    const auto mask = selection.empty() ? std::vector<unsigned char>() : selectionMask(selection, grid.resolution());
    bool useMask = false;
    for (unsigned char m : mask) useMask |= m != 0;
    Vec3 sum(0.0);
    std::size_t n = 0;
    for (std::size_t i = 0; i < grid.nodeCount(); ++i)
      if (!useMask || mask[i]) {
        sum += grid.nodes()[i];
        ++n;
      }
    anchor = n ? sum / double(n) : Vec3(0.0);
  }
  op.params = spec.defaults;
  if (spec.placeAt) spec.placeAt(op.params, anchor);
  return op;
}

void AddOperation::apply(Project& project) const {
  auto& ops = function.in(project).ops;
  if (at < 0 || std::size_t(at) > ops.size())
    throw ModelError(function.path() + ".ops[" + std::to_string(at) + "]", "no place for an operation");
  ops.insert(ops.begin() + at, operation);
  const int a = at;
  remapTrackIndices(project.tracks, opsPath(function), [a](int i) { return i >= a ? i + 1 : i; });
}

std::string AddOperation::label() const { return std::string("Add ") + operationSpec(operation.params).title; }

void RemoveOperation::apply(Project& project) const {
  operationAt(project, function, index);
  auto& ops = function.in(project).ops;
  ops.erase(ops.begin() + index);
  const int o = index;
  remapTrackIndices(project.tracks, opsPath(function), [o](int i) { return i == o ? -1 : i > o ? i - 1 : i; });
}

void MoveOperation::apply(Project& project) const {
  std::swap(operationAt(project, function, from), operationAt(project, function, to));
  const int a = from, b = to;
  remapTrackIndices(project.tracks, opsPath(function), [a, b](int i) { return i == a ? b : i == b ? a : i; });
}

std::string MoveOperation::label() const { return to < from ? "Move operation up" : "Move operation down"; }

void DuplicateOperation::apply(Project& project) const {
  const Operation copy = operationAt(project, function, index);
  auto& ops = function.in(project).ops;
  ops.insert(ops.begin() + index + 1, copy);
  const int o = index;
  remapTrackIndices(project.tracks, opsPath(function), [o](int i) { return i > o ? i + 1 : i; });
}

void SetOperationMuted::apply(Project& project) const { operationAt(project, function, index).muted = muted; }

std::string SetOperationMuted::label() const { return muted ? "Mute operation" : "Unmute operation"; }

void SetOperation::apply(Project& project) const { operationAt(project, function, index) = operation; }

void SetOperationSelection::apply(Project& project) const {
  operationAt(project, function, index).selection = selection;
}

void PlaceCenter::apply(Project& project) const { operationAt(project, function, index).center.point = point; }

int nodeMoveOperation(const Function& start) { return int(start.ops.size()) - (extendsLastNodes(start) ? 1 : 0); }

void MoveNodes::apply(Project& project) const {
  Function& target = function.in(project);
  Function fn = start;
  if (!extendsLastNodes(fn)) {
    fn.ops.emplace_back();
    fn.ops.back().params.emplace<NodesOp>();
  }
  auto& moves = std::get<NodesOp>(fn.ops.back().params).moves;
  std::map<Index3, std::size_t> where;
  for (std::size_t m = 0; m < moves.size(); ++m) where[moves[m].index] = m;
  for (std::size_t n = 0; n < mask.size(); ++n) {
    if (!mask[n]) continue;
    const Index3 idx = nodeIndex(n, fn.resolution);
    if (auto it = where.find(idx); it != where.end())
      moves[it->second].displacement += displacement;
    else
      moves.push_back({idx, displacement});
  }
  target = std::move(fn);
}

}  // namespace gridifs
