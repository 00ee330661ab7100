#pragma once
// The image the shading pass produces and the quality metrics and PNG output read.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace vsgl {

// Linear radiance, row-major, row 0 = top: (rgb, 1) where the G-buffer has a surface, (0,0,0,0)
// where it has none.
struct RadianceImage {
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<glm::vec4> pixels;
};

}  // namespace vsgl
