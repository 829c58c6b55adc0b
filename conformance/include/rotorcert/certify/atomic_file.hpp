// Writing a file so that no reader ever sees a part of it (reports, vectors, render results).
#pragma once

#include <filesystem>
#include <string>

namespace rotorcert::certify {

/// Writes `contents` to `file` atomically: a temporary file in the same directory, flushed,
/// then renamed over the target. Readers see the old file or the new one, never a part.
void write_atomically(const std::filesystem::path& file, const std::string& contents);

}  // namespace rotorcert::certify
