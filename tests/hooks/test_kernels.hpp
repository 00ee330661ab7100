#pragma once
// TEST BUILD ONLY: the test kernels (kernels/test_*.comp, the library vsgl_test_kernels) are not
// in the shipped programs' table of embedded shaders; the test suite and the test build of
// vsgl-bench add theirs (harness/vk/shader_registry.hpp add_embedded_shaders) before they run.
namespace vsgl::test {

// Adds the test kernels' table once; later calls do nothing.
void add_test_kernels();

}  // namespace vsgl::test
