#ifndef KMEANS_SUM_PUSH_GLSL
#define KMEANS_SUM_PUSH_GLSL
// Push constants of the k-means `sum` kernels (interface/kmeans.h).
#include "interface/kmeans.h"
layout(push_constant) uniform PushBlock { KmeansSumPush pc; };
#endif  // KMEANS_SUM_PUSH_GLSL
