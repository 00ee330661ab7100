#pragma once
// TEST-ONLY hook of the atomic writer (harness/core/atomic_file.cpp; DESIGN.md §10, §12: no
// half-written output): lets a test kill a real run at a known point of writing a known file,
// deterministically.
//
//   VSGL_TEST_PAUSE_AT=POINT:FILE_NAME[:N]   VSGL_TEST_PAUSE_NOTIFY=/some/marker
//
// When the writer reaches POINT while writing a file whose name (not path) is FILE_NAME, the N-th
// time this process writes a file of that name (1 when not given: outputs rewritten as a run goes,
// such as a sweep's sweep.json after each point, are stopped at a chosen write), it creates the
// marker file (holding its pid) and then sleeps until it is killed. Points:
//   partial   half of the bytes are in the temporary file (not flushed, not renamed)
//   complete  the temporary file is complete and flushed, not yet renamed over the target
//   renamed   the target has been replaced, the directory is not yet synced
// Unset (always, outside tests): no effect beyond one getenv per file written.
#include <filesystem>
#include <string_view>

namespace vsgl {

// Counts one more write of `target` (the atomic writer calls it once as each write begins).
void test_pause_count_write(const std::filesystem::path& target);

// True when VSGL_TEST_PAUSE_AT names this point, this target's file name and this write of it.
bool test_pause_wanted(std::string_view point, const std::filesystem::path& target);

// If wanted: notifies and sleeps for good (the test's SIGKILL ends the process). Else returns.
void test_pause_point(std::string_view point, const std::filesystem::path& target);

}  // namespace vsgl
