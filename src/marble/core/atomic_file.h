#pragma once
// Every file marble writes goes through here: the bytes go to a temporary in the same
// folder, are flushed, and the temporary is renamed over the target, so a reader never
// sees a half-written file and an old file survives a failed write.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <string_view>

namespace marble {

// Writes `bytes` to `path` atomically. Throws InputError naming the path on failure;
// on failure no temporary is left behind and an existing file is untouched.
void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes);

// Test hook: called after the temporary is written and before the rename; throwing from
// it simulates a crash/disk-full mid-write. Null in normal use.
void setAtomicWriteFaultHookForTesting(std::function<void()> hook);

}  // namespace marble
