#ifndef KMEANS_SUM_PUSH_GLSL
#define KMEANS_SUM_PUSH_GLSL
// Push constants of the k-means `sum` kernels (C++: SumPush in harness/generators/kmeans/kmeans_generator.cpp).
layout(push_constant) uniform Push {
  uint width;
  uint height;
  uint texels;       // W * H (sorted elements)
  uint clusters;     // N
  uint chunk;        // elements per piece of the segmented sum
  uint camera_view;  // 1: G-buffer, 0: RSM
  uint space3d;      // 0: kmeans_2d, 1: kmeans_3d
  uint square_size;  // S
  vec4 source_position;
} pc;
#endif  // KMEANS_SUM_PUSH_GLSL
