// The test kernels (kernels/test_*.comp) are not in the shipped programs' table of embedded
// shaders: this test binary adds theirs before any test runs (tests/hooks/test_kernels.hpp).
#include "hooks/test_kernels.hpp"

namespace {

const bool kTestKernelsAdded = (vsgl::test::add_test_kernels(), true);

}  // namespace
