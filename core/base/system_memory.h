#pragma once
// How much memory the machine can still give this process, so that a job whose buffers would not
// fit is refused before it allocates (and before the kernel's out-of-memory killer picks a
// victim). Thread-safe; never throws.
#include <cstdint>
#include <optional>
#include <string>

namespace gridifs {

/// The kernel's estimate of memory available without swapping (Linux: MemAvailable in
/// /proc/meminfo), or nullopt where it cannot be read.
std::optional<std::uint64_t> availableMemoryBytes();

/// "1.5 GiB", "320 MiB": a byte count for a sentence.
std::string describeBytes(std::uint64_t bytes);

}  // namespace gridifs
