#include "render/batched_variations.h"

#include "render/compiled_ifs.h"

namespace gridifs {

std::shared_ptr<const BatchedVariations> batchVariations(const CompiledIfs& ifs) {
  if (ifs.functions.empty() || !ifs.transitionWalk.empty() || ifs.barycentricSize != 0) return nullptr;
  bool anyStage = false;
  for (const CompiledFunction& f : ifs.functions) {
    if ((f.variations && f.variations->anyPre) || !f.points.empty() || !f.matrix.empty()) return nullptr;
    anyStage |= f.variations != nullptr;
  }
  if (!anyStage) return nullptr;
  auto out = std::make_shared<BatchedVariations>();
  // Slots in order of first appearance, so a lone function sums its terms in its own order. A
  // slot is a body and its occurrence within the function (the same variation twice is two).
  struct Key {
    std::int32_t body;
    int occurrence;
  };
  std::vector<Key> keys;
  std::vector<std::vector<int>> termSlots(ifs.functions.size());
  for (std::size_t f = 0; f < ifs.functions.size(); ++f) {
    if (!ifs.functions[f].variations) continue;
    const CompiledVariations& v = *ifs.functions[f].variations;
    for (std::size_t i = 0; i < v.kernelTerms.size(); ++i) {
      const std::int32_t body = v.kernelTerms[i].body;
      int occurrence = 0;
      for (std::size_t j = 0; j < i; ++j) occurrence += v.kernelTerms[j].body == body;
      std::size_t s = 0;
      while (s < keys.size() && !(keys[s].body == body && keys[s].occurrence == occurrence)) ++s;
      if (s == keys.size()) {
        if (keys.size() == 32) return nullptr;
        keys.push_back({body, occurrence});
        BatchedVariations::Slot slot;
        slot.lanes = laneVariationBodyIndex(v.terms[i].variation->name);
        slot.scalar = kernelVariationBody(body);
        slot.writesZ = v.kernelTerms[i].writesZ;
        slot.params = !v.terms[i].variation->params.empty();
        if (!slot.scalar) return nullptr;
        out->slots.push_back(slot);
      }
      termSlots[f].push_back(int(s));
    }
  }
  const std::size_t count = out->slots.size(), n = ifs.functions.size();
  out->weights.assign(n * count, 0.0f);
  out->params.assign(n * count, nullptr);
  out->slotMask.assign(n, 0);
  out->coefs.resize(n);
  out->postColumns.assign(n * 16, 0.0f);
  out->hasPost.assign(n, 0);
  out->flatten.assign(n, 0);
  out->keepsGridImage.assign(n, 0);
  for (std::size_t f = 0; f < n; ++f) {
    if (!ifs.functions[f].variations) {
      out->keepsGridImage[f] = 1;
      out->anyKeepsGridImage = true;
      continue;
    }
    const CompiledVariations& v = *ifs.functions[f].variations;
    for (std::size_t i = 0; i < v.kernelTerms.size(); ++i) {
      const std::size_t s = std::size_t(termSlots[f][i]);
      out->weights[f * count + s] = float(v.kernelTerms[i].weight);
      out->params[f * count + s] = v.kernelTerms[i].params;
      out->slotMask[f] |= 1u << s;
      out->flatten[f] |= v.kernelTerms[i].flatten;
    }
    out->coefs[f] = &v.coefs;
    out->hasPost[f] = v.hasPost;
    out->anyPost |= v.hasPost;
    out->anyFlatten |= out->flatten[f] != 0;
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 3; ++r) out->postColumns[f * 16 + std::size_t(c) * 4 + std::size_t(r)] = float(v.post[r][c]);
  }
  for (std::size_t s = 0; s < count; ++s) {
    const double* first = nullptr;
    for (std::size_t f = 0; f < n && !first; ++f) first = out->params[f * count + s];
    for (std::size_t f = 0; f < n; ++f)
      if (!out->params[f * count + s]) out->params[f * count + s] = first;
  }
  return out;
}

}  // namespace gridifs
