#pragma once
// A user's Wavefront OBJ file with its MTL material libraries as a Scene (DESIGN.md §3), imported
// with Debian's tinyobjloader, so that files such as those of the McGuire Computer Graphics
// Archive load as distributed. The result is the glTF importer's (GltfImport; gltf_frame animates
// it), with the same camera and light choices (an OBJ file has neither, so they are given or
// placed around the bounds) and the same --ground.
//
// Geometry: every face of every group and object (g, o), triangulated by tinyobjloader (quads
// and polygons as fans / by its ear clipping), negative (relative) indices, texture coordinates
// (OBJ's v points up: v' = 1 - v), normals (non-unit ones normalized; missing or zero ones
// replaced by the face's normal: flat shading). Lines and points have no surface and are skipped.
//
// MTL -> material (MaterialModel::kVertexAlbedo, drawn double-sided: OBJ says nothing about
// which side is the front, and files of that archive mix windings):
//   diffuse albedo  = Kd (x map_Kd, sRGB)
//   specular F0     = Ks with its luminance clamped to [0,1] (scaled down when above 1, then each
//                     channel clamped); 0.04 when the material has no Ks statement
//   GGX alpha       = sqrt(2 / (Ns + 2)), clamped to [1e-3, 1] (the shader's range): a
//                     Blinn-Phong lobe of exponent Ns has the width of a Beckmann distribution
//                     of alpha^2 = 2 / (Ns + 2), and GGX of the same alpha matches Beckmann near
//                     the peak (Walter et al. 2007), which is where the RSM's flux lies
//   cut-out         = d < 1 or map_d: alpha mask at 0.5 (the renderer does not blend); the alpha
//                     is d x map_d (its alpha channel if it has one, else its first channel)
//   normal map      = map_bump / bump / norm, read as a tangent-space normal map; tangents are
//                     computed from the texture coordinates (OBJ has none)
// A face without a material (no usemtl, a missing .mtl, a usemtl the libraries lack) is grey
// (albedo 0.5, F0 0.04, alpha 0.5); a missing .mtl is a note, not an error.
// Not mapped (each listed in the notes): Ka/map_Ka, Ke/map_Ke, map_Ks, map_Ns, disp, refl,
// illum models, Tf/Ni (transmission, refraction), vertex colours.
//
// Errors (InputError "OBJ file F: ...", F escaped as in the glTF importer, with the line of the
// .obj or .mtl it stands on): a face index of 0 or outside the positions, texture coordinates or
// normals defined before it, a non-finite position coordinate, a missing or undecodable texture,
// a file without faces, tinyobjloader's own parse errors.
#include <filesystem>

#include "harness/scene/gltf_scene.hpp"

namespace vsgl {

// Loads and converts the OBJ file and its material libraries (mtllib, looked for beside it).
// `camera.camera` (a camera of the file) is an error: OBJ has no cameras. Throws InputError or
// UsageError as import_gltf does.
GltfImport import_obj(const std::filesystem::path& file, const GltfCameraChoice& camera = {},
                      const GltfLightChoice& light = {}, bool ground = false);

}  // namespace vsgl
