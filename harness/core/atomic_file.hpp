#pragma once
// Crash-safe file replacement: a reader sees either the old file or the new one, never a
// half-written one (DESIGN.md §12). The bytes go to a temporary file in the target's directory,
// are flushed to disk, and the temporary is renamed over the target.
#include <filesystem>
#include <span>
#include <string_view>

namespace vsgl {

// Writes `bytes` to `path` atomically (temporary + fsync + rename + fsync of the directory).
// The directory must exist. Throws InputError naming `path` and the reason; no temporary file
// is left behind on failure.
// A process killed mid-write leaves only its temporary (".NAME.tmp-PID-N", which no reader
// opens); the next write of the same path removes temporaries whose process is gone.
void write_file_atomic(const std::filesystem::path& path, std::span<const char> bytes);

// The same for text (JSON results, sidecars).
void write_text_atomic(const std::filesystem::path& path, std::string_view text);

}  // namespace vsgl
