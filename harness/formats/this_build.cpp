// this_build() (formats/run_header.hpp), apart from run_header.cpp: it needs the build's generated
// data (core/build_info), which the loaders' fuzz build (tests/fuzz) does not make, while the
// header's readers and writers are what the loaders use.
#include "harness/formats/run_header.hpp"

#include "harness/core/build_info.hpp"
#include "harness/core/version.hpp"

namespace vsgl {

BuildRecord this_build() {
  const BuildInfo b = build_info();
#ifdef NDEBUG
  constexpr bool kAssertions = false;
#else
  constexpr bool kAssertions = true;
#endif
  return {kVersionString, b.git_commit, b.git_dirty, compiler_description(), kAssertions};
}

}  // namespace vsgl
