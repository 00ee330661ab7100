#pragma once
// The descriptors of the two FIS generators (DESIGN.md §6.1): one host class, one set of kernels.
#include "harness/generators/generator_descriptor.hpp"
#include "harness/math/fis_params.hpp"

namespace vsgl {

GeneratorDescriptor fis_descriptor(FisVariant variant);

}  // namespace vsgl
