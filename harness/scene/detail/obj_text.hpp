#pragma once
// OBJ import, the text pass before tinyobjloader: tinyobjloader (Debian 2.0.0rc10) accepts a
// face index past the vertices read so far (it only warns, with the last line's number, and
// later indexes its arrays with it), reads "nan" as 0 and "1e999" as infinity, and does not say
// on which line a material statement stood. So every line is read here first, split as
// tinyobjloader splits it, and an out-of-range index or a non-finite coordinate is an error
// naming its line; the .mtl files' statements are located for messages and for what
// tinyobjloader cannot tell apart (Ks absent from Ks 0 0 0).
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "harness/scene/detail/gltf_accessors.hpp"

namespace vsgl::obj {

struct ObjText {
  uint64_t positions = 0, texcoords = 0, normals = 0;
  uint64_t faces = 0;        // f statements with 3 or more corners
  uint64_t lines_points = 0;  // l and p statements (no surface)
  std::vector<std::string> mtllibs;  // every name on every mtllib line, in order
};

// Reads the .obj text; an error (through `r`) names the line of an index 0, an index outside
// the positions/texture coordinates/normals defined before it, or a non-finite coordinate.
ObjText scan_obj(std::string_view text, const gltf::Reporter& r);

// Where each statement of each material of a .mtl file stands (1-based lines).
struct MtlMaterialLines {
  int newmtl = 0;
  std::map<std::string, int> statements;  // keyword (Ks, map_Kd, bump, ...) -> its line
};
struct MtlText {
  std::map<std::string, MtlMaterialLines> materials;  // by name
};
MtlText scan_mtl(std::string_view text);

}  // namespace vsgl::obj
