#pragma once
// TEST BUILD ONLY (tests/hooks/, never linked into the shipped programs): the atomic writer's
// observer (harness/core/atomic_write_observer.hpp) that lets a kill test stop a real run at a
// known point of writing a known file, deterministically (DESIGN.md §10, §12: no half-written
// output).
//
//   VSGL_TEST_PAUSE_AT=POINT:FILE_NAME[:N]   VSGL_TEST_PAUSE_NOTIFY=/some/marker
//
// When the writer reaches POINT while writing a file whose name (not path) is FILE_NAME, the N-th
// time this process writes a file of that name (1 when not given: outputs rewritten as a run goes,
// such as a sweep's sweep.json after each point, are stopped at a chosen write), it creates the
// marker file (holding its pid) and then sleeps until it is killed. Points: partial, complete,
// renamed (AtomicWriteStage).
#include "harness/core/atomic_write_observer.hpp"

namespace vsgl::test {

// Installs the observer when VSGL_TEST_PAUSE_AT is set and well formed; else leaves the writer
// alone. Returns whether it installed it.
bool install_pause_at_write_from_environment();

}  // namespace vsgl::test
