// Push constants and work-group sizes of the test kernels (kernels/test_*.comp; hosts: tests/,
// tests/hooks/debug_slowdown.cpp). See interop.h for how C++ and GLSL share them.
#ifndef VSGL_INTERFACE_TESTING_H
#define VSGL_INTERFACE_TESTING_H
#include "interop.h"

VSGL_INTERFACE_BEGIN

VSGL_CONST uint kTestGroupSize = 64u;  // every test kernel is 1D

// test_division.comp, test_vsgl_math.comp: the number of cases.
struct TestCountPush {
  uint count;
};
VSGL_LAYOUT(TestCountPush, 4);

// test_workload.comp: `iterations` hash steps in each of `count` invocations.
struct TestWorkloadPush {
  uint count;
  uint iterations;
};
VSGL_LAYOUT(TestWorkloadPush, 8);

VSGL_INTERFACE_END

#endif  // VSGL_INTERFACE_TESTING_H
