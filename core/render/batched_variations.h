#pragma once
// The variation stages of a compiled IFS's functions as one BatchedVariations
// (variations/variation_lanes.h), which runs them for the chaos kernel's four chains at once.
#include <memory>

#include "variations/variation_lanes.h"

namespace gridifs {

struct CompiledIfs;

/// The batched stage of `ifs`, or null when its chaos game cannot run it: no function has
/// variations, or one has a pre-variation, or the IFS walks a transition matrix, has condensation
/// sets or is a free-form IFS, or its functions hold more than 32 distinct terms.
std::shared_ptr<const BatchedVariations> batchVariations(const CompiledIfs& ifs);

}  // namespace gridifs
