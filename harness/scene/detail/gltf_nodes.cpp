#include "harness/scene/detail/gltf_nodes.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <numbers>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "harness/core/portable_float.hpp"
#include "harness/scene/detail/gltf_materials.hpp"
#include "harness/scene/scene_textures.hpp"

namespace vsgl::gltf {
namespace {

glm::dmat4 node_local_matrix(const tinygltf::Node& node) {
  if (node.matrix.size() == 16) return glm::make_mat4(node.matrix.data());
  glm::dmat4 t(1.0), rot(1.0), s(1.0);
  if (node.translation.size() == 3) t = glm::translate(glm::dmat4(1.0), glm::make_vec3(node.translation.data()));
  if (node.rotation.size() == 4) {
    const glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);  // w, x, y, z
    rot = glm::mat4_cast(glm::normalize(q));
  }
  if (node.scale.size() == 3) s = glm::scale(glm::dmat4(1.0), glm::make_vec3(node.scale.data()));
  return t * rot * s;
}

int node_light(const tinygltf::Node& node) {
  const auto ext = node.extensions.find("KHR_lights_punctual");
  if (ext == node.extensions.end() || !ext->second.IsObject() || !ext->second.Has("light")) return -1;
  const tinygltf::Value& v = ext->second.Get("light");
  return v.IsInt() ? v.Get<int>() : (v.IsNumber() ? static_cast<int>(v.GetNumberAsDouble()) : -1);
}

// The primitive's triangles as vertex indices into its n vertices (strips and fans unrolled),
// every index checked.
std::vector<uint32_t> triangle_indices(const Importer& imp, const tinygltf::Primitive& prim, int mode, std::size_t n,
                                       const std::string& what) {
  const tinygltf::Model& m = imp.model();
  const Reporter& r = imp.reporter();
  std::vector<uint32_t> source;  // vertex indices in primitive order
  if (prim.indices >= 0) {
    const std::vector<double> idx = imp.read_accessor(prim.indices, 1, what + " indices");
    const int ctype = m.accessors[static_cast<std::size_t>(prim.indices)].componentType;
    if (ctype != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && ctype != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        ctype != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
      r.fail(what + " indices: component type " + std::to_string(ctype) + " is not an unsigned integer type");
    source.reserve(idx.size());
    for (std::size_t i = 0; i < idx.size(); ++i) {
      if (idx[i] >= static_cast<double>(n))
        r.fail(what + ": index " + std::to_string(i) + " is " + std::to_string(static_cast<uint64_t>(idx[i])) +
               ", out of range for its " + std::to_string(n) + " vertices");
      source.push_back(static_cast<uint32_t>(idx[i]));
    }
  } else {
    source.resize(n);
    for (std::size_t i = 0; i < n; ++i) source[i] = static_cast<uint32_t>(i);
  }
  std::vector<uint32_t> tris;
  if (mode == TINYGLTF_MODE_TRIANGLES) {
    if (source.size() % 3 != 0)
      r.fail(what + ": " + std::to_string(source.size()) + (prim.indices >= 0 ? " indices" : " vertices") +
             " are not a whole number of triangles");
    tris = source;
  } else {
    for (std::size_t i = 2; i < source.size(); ++i) {
      if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
        const bool even = i % 2 == 0;  // every other triangle of a strip is flipped to keep its winding
        tris.insert(tris.end(), {source[i - 2], even ? source[i - 1] : source[i], even ? source[i] : source[i - 1]});
      } else {
        tris.insert(tris.end(), {source[0], source[i - 1], source[i]});
      }
    }
  }
  return tris;
}

// Normals: missing ones give flat shading (glTF), bad ones (zero, non-finite) the
// area-weighted normal of the vertex's triangles.
void repair_normals(Conversion& conv, std::vector<SceneVertex>& verts, std::vector<uint32_t>& tris, bool has_normals) {
  const std::size_t n = verts.size();
  if (!has_normals) {
    std::vector<SceneVertex> flat;
    flat.reserve(tris.size());
    for (std::size_t t = 0; t < tris.size(); t += 3) {
      const glm::vec3 a = verts[tris[t]].position, b = verts[tris[t + 1]].position, c = verts[tris[t + 2]].position;
      glm::vec3 fn = glm::cross(b - a, c - a);
      const float len = glm::length(fn);
      fn = len > 0.0f ? fn / len : glm::vec3(0.0f, 1.0f, 0.0f);
      for (int k = 0; k < 3; ++k) {
        flat.push_back(verts[tris[t + static_cast<std::size_t>(k)]]);
        flat.back().normal = fn;
      }
    }
    verts = std::move(flat);
    for (std::size_t i = 0; i < tris.size(); ++i) tris[i] = static_cast<uint32_t>(i);
  } else {
    std::vector<glm::vec3> accumulated(n, glm::vec3(0.0f));
    bool any_bad = false;
    for (const SceneVertex& v : verts) any_bad = any_bad || v.normal == glm::vec3(0.0f);
    if (any_bad) {
      for (std::size_t t = 0; t < tris.size(); t += 3) {
        const glm::vec3 a = verts[tris[t]].position, b = verts[tris[t + 1]].position, c = verts[tris[t + 2]].position;
        const glm::vec3 fn = glm::cross(b - a, c - a);  // length = twice the area: area weighting
        for (int k = 0; k < 3; ++k) accumulated[tris[t + static_cast<std::size_t>(k)]] += fn;
      }
      for (std::size_t i = 0; i < n; ++i) {
        if (verts[i].normal != glm::vec3(0.0f)) continue;
        ++conv.normals_replaced;
        const float len = glm::length(accumulated[i]);
        verts[i].normal = len > 0.0f ? accumulated[i] / len : glm::vec3(0.0f, 1.0f, 0.0f);
      }
    }
  }
}

void convert_primitive(Conversion& conv, const Importer& imp, const NodeInstance& inst, int mesh_index, std::size_t p) {
  const tinygltf::Model& m = imp.model();
  const Reporter& r = imp.reporter();
  const tinygltf::Mesh& mesh = m.meshes[static_cast<std::size_t>(mesh_index)];
  const tinygltf::Primitive& prim = mesh.primitives[p];
  const std::string what = "mesh " + std::to_string(mesh_index) + " " + quote_name(mesh.name) + " primitive " + std::to_string(p);
  const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
  if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN) {
    ++conv.skipped_non_triangle;  // points and lines have no surface to capture
    return;
  }
  // An attribute's accessor index, -1 when the primitive has no such attribute. An index outside
  // the accessors is an error here, before anything reads the accessor's type (found by fuzz_gltf:
  // an optional attribute's accessor type was read out of bounds).
  const auto attr = [&](const char* name) {
    const auto it = prim.attributes.find(name);
    if (it == prim.attributes.end()) return -1;
    imp.accessor(it->second, what + " " + name);
    return it->second;
  };
  const int pos_acc = attr("POSITION");
  if (pos_acc < 0) r.fail(what + " has no POSITION attribute");
  const std::vector<double> pos = imp.read_accessor(pos_acc, 3, what + " POSITION");
  const std::size_t n = pos.size() / 3;
  for (std::size_t i = 0; i < n; ++i)
    if (!finite3({pos[3 * i], pos[3 * i + 1], pos[3 * i + 2]}))
      r.fail(what + " POSITION: vertex " + std::to_string(i) + " is not finite (" + std::to_string(pos[3 * i]) + ", " +
             std::to_string(pos[3 * i + 1]) + ", " + std::to_string(pos[3 * i + 2]) + ")");
  std::vector<uint32_t> tris = triangle_indices(imp, prim, mode, n, what);
  if (tris.empty()) return;

  const auto optional_attr = [&](const char* name, int comps_a, int comps_b) -> std::pair<std::vector<double>, int> {
    const int acc = attr(name);
    if (acc < 0) return {{}, 0};
    const int comps = type_components(m.accessors[static_cast<std::size_t>(acc)].type);
    const int want = comps == comps_b ? comps_b : comps_a;
    std::vector<double> v = imp.read_accessor(acc, want, what + " " + name);
    if (v.size() / static_cast<std::size_t>(want) != n)
      r.fail(what + " " + std::string(name) + ": " + std::to_string(v.size() / static_cast<std::size_t>(want)) +
             " elements, but POSITION has " + std::to_string(n));
    return {std::move(v), want};
  };
  const auto [normals, nc] = optional_attr("NORMAL", 3, 3);
  const auto [uvs, uc] = optional_attr("TEXCOORD_0", 2, 2);
  const auto [tangents, tc] = optional_attr("TANGENT", 4, 4);
  const auto [colours, cc] = optional_attr("COLOR_0", 3, 4);
  (void)nc;
  (void)uc;
  (void)tc;

  const uint32_t material = material_for(conv, m, prim.material, what, r);
  const Material& mat = conv.scene.materials[material];
  const glm::dmat4& world = inst.world;
  const glm::dmat3 linear(world);
  const glm::dmat3 normal_matrix = glm::inverseTranspose(linear);
  const bool mirrored = glm::determinant(linear) < 0.0;

  std::vector<SceneVertex> verts(n);
  for (std::size_t i = 0; i < n; ++i) {
    SceneVertex& v = verts[i];
    const glm::dvec4 wp = world * glm::dvec4(pos[3 * i], pos[3 * i + 1], pos[3 * i + 2], 1.0);
    if (!finite3(glm::dvec3(wp)))
      r.fail(what + ": vertex " + std::to_string(i) + " is not finite after its node transform");
    v.position = glm::vec3(wp);
    v.normal = glm::vec3(0.0f);
    if (!normals.empty()) {
      const glm::dvec3 nn = normal_matrix * glm::dvec3(normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]);
      const double len = glm::length(nn);
      if (std::isfinite(len) && len > 1e-12) {
        const double raw = glm::length(glm::dvec3(normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]));
        if (std::abs(raw - 1.0) > 1e-3) ++conv.normals_normalized;
        v.normal = glm::vec3(nn / len);
      }
    }
    v.diffuse = glm::vec3(1.0f);  // vertex colour (metallic-roughness model)
    if (!colours.empty()) {
      const std::size_t k = static_cast<std::size_t>(cc) * i;
      v.diffuse = glm::clamp(glm::vec3(static_cast<float>(colours[k]), static_cast<float>(colours[k + 1]),
                                       static_cast<float>(colours[k + 2])),
                             0.0f, 1.0f);
    }
    v.specular = glm::vec3(0.04f);
    v.roughness = 1.0f;
    if (!uvs.empty()) v.uv = glm::vec2(static_cast<float>(uvs[2 * i]), static_cast<float>(uvs[2 * i + 1]));
    if (!tangents.empty()) {
      const glm::dvec3 t = linear * glm::dvec3(tangents[4 * i], tangents[4 * i + 1], tangents[4 * i + 2]);
      const double len = glm::length(t);
      const double w = tangents[4 * i + 3] < 0.0 ? -1.0 : 1.0;
      if (std::isfinite(len) && len > 1e-12) v.tangent = glm::vec4(glm::vec3(t / len), static_cast<float>(mirrored ? -w : w));
    }
    v.material = material;
  }
  if (mirrored)  // a mirroring transform turns counter-clockwise triangles clockwise
    for (std::size_t t = 0; t < tris.size(); t += 3) std::swap(tris[t + 1], tris[t + 2]);

  repair_normals(conv, verts, tris, !normals.empty());
  if (mat.normal_texture >= 0 && tangents.empty()) {
    compute_tangents(verts, tris);
    conv.tangents_computed += verts.size();
  }

  SceneMesh& out = conv.scene.mesh;
  const auto base = static_cast<uint32_t>(out.vertices.size());
  if (out.vertices.size() + verts.size() > std::numeric_limits<uint32_t>::max())
    r.fail("has more than 2^32 vertices in its default scene");
  out.vertices.insert(out.vertices.end(), verts.begin(), verts.end());
  for (uint32_t i : tris) out.indices.push_back(base + i);
}

CameraDesc framing_camera(glm::vec3 lo, glm::vec3 hi, float fov_y_deg) {
  const glm::vec3 centre = 0.5f * (lo + hi);
  const float radius = std::max(0.5f * glm::length(hi - lo), 1e-3f);
  // From the front (+z) and somewhat above: the usual glTF orientation (y up, facing +z).
  const glm::vec3 dir = glm::normalize(glm::vec3(0.35f, 0.45f, 1.0f));
  const float distance = radius / portable::sin(glm::radians(0.5f * fov_y_deg)) * 1.05f;
  CameraDesc c;
  c.position = centre + dir * distance;
  c.target = centre;
  c.up = glm::vec3(0.0f, 1.0f, 0.0f);
  c.fov_y_deg = fov_y_deg;
  c.near_plane = std::max(0.5f * (distance - radius), 1e-3f * (distance + radius));
  c.far_plane = 1.5f * (distance + radius);
  return c;
}

float far_for(glm::vec3 eye, glm::vec3 lo, glm::vec3 hi) {
  float far = 0.0f;
  for (int k = 0; k < 8; ++k) {
    const glm::vec3 corner((k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y, (k & 4) ? hi.z : lo.z);
    far = std::max(far, glm::length(corner - eye));
  }
  return far * 1.05f + 1e-3f;
}

std::string vec_text(glm::vec3 v) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.4g, %.4g, %.4g)", static_cast<double>(v.x), static_cast<double>(v.y),
                static_cast<double>(v.z));
  return buf;
}

}  // namespace

std::vector<NodeInstance> scene_nodes(const tinygltf::Model& m, const Reporter& r, std::vector<std::string>& notes) {
  std::vector<int> roots;
  if (!m.scenes.empty()) {
    int s = m.defaultScene;
    if (s < 0 || static_cast<std::size_t>(s) >= m.scenes.size()) {
      if (m.scenes.size() > 1) notes.push_back("no default scene: scene 0 of " + std::to_string(m.scenes.size()) + " drawn");
      s = 0;
    }
    roots = m.scenes[static_cast<std::size_t>(s)].nodes;
  } else {
    std::vector<bool> child(m.nodes.size(), false);
    for (const tinygltf::Node& node : m.nodes)
      for (int c : node.children)
        if (c >= 0 && static_cast<std::size_t>(c) < m.nodes.size()) child[static_cast<std::size_t>(c)] = true;
    for (std::size_t i = 0; i < m.nodes.size(); ++i)
      if (!child[i]) roots.push_back(static_cast<int>(i));
  }
  std::vector<NodeInstance> out;
  std::vector<bool> on_path(m.nodes.size(), false);
  const std::function<void(int, const glm::dmat4&)> visit = [&](int index, const glm::dmat4& parent) {
    if (index < 0 || static_cast<std::size_t>(index) >= m.nodes.size())
      r.fail("node " + std::to_string(index) + " does not exist (" + std::to_string(m.nodes.size()) + " nodes)");
    if (on_path[static_cast<std::size_t>(index)]) r.fail("node " + std::to_string(index) + " is its own ancestor (a cycle)");
    if (out.size() > 10'000'000) r.fail("instantiates more than 10 million nodes");
    on_path[static_cast<std::size_t>(index)] = true;
    const tinygltf::Node& node = m.nodes[static_cast<std::size_t>(index)];
    const glm::dmat4 world = parent * node_local_matrix(node);
    out.push_back({index, world});
    for (int c : node.children) visit(c, world);
    on_path[static_cast<std::size_t>(index)] = false;
  };
  for (int root : roots) visit(root, glm::dmat4(1.0));
  return out;
}

NodeContents convert_nodes(Conversion& conv, const Importer& imp, const std::vector<NodeInstance>& nodes) {
  const tinygltf::Model& m = imp.model();
  const Reporter& r = imp.reporter();
  NodeContents out;
  for (const NodeInstance& inst : nodes) {
    const tinygltf::Node& node = m.nodes[static_cast<std::size_t>(inst.node)];
    if (node.mesh >= 0) {
      if (static_cast<std::size_t>(node.mesh) >= m.meshes.size())
        r.fail("node " + std::to_string(inst.node) + " refers to mesh " + std::to_string(node.mesh) + " of " +
               std::to_string(m.meshes.size()));
      const tinygltf::Mesh& mesh = m.meshes[static_cast<std::size_t>(node.mesh)];
      for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
        if (!mesh.primitives[p].targets.empty()) conv.unmapped.insert("morph targets (rest pose drawn)");
        convert_primitive(conv, imp, inst, node.mesh, p);
      }
    }
    if (node.skin >= 0) conv.unmapped.insert("skins (rest pose drawn)");
    if (node.camera >= 0 && static_cast<std::size_t>(node.camera) < m.cameras.size())
      out.cameras.push_back({node.camera, inst.node, inst.world});
    const int light = node_light(node);
    if (light >= 0 && static_cast<std::size_t>(light) < m.lights.size()) out.lights.push_back({light, inst.node, inst.world});
  }
  return out;
}

CameraDesc choose_camera(const Importer& imp, const std::vector<CameraInstance>& cameras,
                         const GltfCameraChoice& choice, const SceneBounds& b, std::string& source) {
  const tinygltf::Model& m = imp.model();
  const Reporter& r = imp.reporter();
  CameraDesc cam;
  const auto camera_from = [&](const CameraInstance& c) {
    const tinygltf::Camera& src = m.cameras[static_cast<std::size_t>(c.camera)];
    const std::string label = "camera " + std::to_string(c.camera) + " " + quote_name(src.name);
    if (src.type != "perspective")
      r.fail(label + " is " + escape_name(src.type) + "; only perspective cameras are supported (use --eye/--look-at)");
    const glm::dmat3 linear(c.world);
    CameraDesc d;
    d.position = glm::vec3(c.world[3]);
    const glm::vec3 forward = glm::normalize(glm::vec3(linear * glm::dvec3(0.0, 0.0, -1.0)));
    d.up = glm::normalize(glm::vec3(linear * glm::dvec3(0.0, 1.0, 0.0)));
    if (!finite3(glm::dvec3(forward)) || !finite3(glm::dvec3(d.up))) r.fail(label + " has a degenerate node transform");
    d.target = d.position + forward * std::max(glm::length(b.centre - d.position), 1e-3f);
    d.fov_y_deg = static_cast<float>(src.perspective.yfov * 180.0 / std::numbers::pi);
    if (!(d.fov_y_deg > 0.1f && d.fov_y_deg < 179.0f)) r.fail(label + " has a field of view of " + std::to_string(d.fov_y_deg) + " degrees");
    d.near_plane = static_cast<float>(src.perspective.znear > 0.0 ? src.perspective.znear : 1e-3 * static_cast<double>(b.radius));
    // The file's far plane (infinite when absent), cut to the farthest corner of the bounds: a
    // far plane a million times the near one would waste the depth buffer's precision.
    d.far_plane = far_for(d.position, b.far_lo, b.far_hi);
    if (src.perspective.zfar > src.perspective.znear) d.far_plane = std::min(d.far_plane, static_cast<float>(src.perspective.zfar));
    if (!(d.far_plane > d.near_plane)) r.fail(label + " sees nothing of the scene: its near plane lies beyond the bounds");
    source = "the file's " + label + " on node " + std::to_string(c.node) +
             " (aspect ratio from the G-buffer size)";
    return d;
  };
  if (choice.camera) {
    const std::string& want = *choice.camera;
    const CameraInstance* found = nullptr;
    const bool numeric = !want.empty() && std::all_of(want.begin(), want.end(), [](char ch) { return ch >= '0' && ch <= '9'; });
    for (const CameraInstance& c : cameras) {
      const tinygltf::Camera& src = m.cameras[static_cast<std::size_t>(c.camera)];
      const bool match = numeric ? std::to_string(c.camera) == want
                                 : src.name == want || m.nodes[static_cast<std::size_t>(c.node)].name == want;
      if (match) {
        found = &c;
        break;
      }
    }
    if (found == nullptr) {
      std::string list;
      for (const CameraInstance& c : cameras)
        list += (list.empty() ? "" : ", ") + std::to_string(c.camera) + " " +
                quote_name(m.cameras[static_cast<std::size_t>(c.camera)].name);
      r.fail("has no camera " + quote_name(want) + " in its default scene (cameras: " + (list.empty() ? "none" : list) + ")");
    }
    cam = camera_from(*found);
  } else if (choice.eye || choice.look_at || choice.fov_y_deg) {
    cam = framing_camera(b.lo, b.hi, choice.fov_y_deg.value_or(50.0f));
    if (choice.eye) cam.position = *choice.eye;
    if (choice.look_at) cam.target = *choice.look_at;
    if (glm::length(cam.target - cam.position) < 1e-6f) throw UsageError("--eye and --look-at are the same point");
    const glm::vec3 fwd = glm::normalize(cam.target - cam.position);
    if (std::abs(fwd.y) > 0.999f) cam.up = glm::vec3(0.0f, 0.0f, -1.0f);
    const float far = far_for(cam.position, b.far_lo, b.far_hi);
    cam.far_plane = far;
    cam.near_plane = std::max(1e-4f * far, 1e-3f * b.radius);
    source = "the command line: eye " + vec_text(cam.position) + ", look-at " + vec_text(cam.target) +
             ", fov " + std::to_string(static_cast<int>(std::lround(cam.fov_y_deg))) + " degrees";
  } else if (!cameras.empty()) {
    cam = camera_from(cameras.front());
  } else {
    cam = framing_camera(b.lo, b.hi, 50.0f);
    source = "automatic framing of the bounds " + vec_text(b.lo) + " - " + vec_text(b.hi) + " (no camera in the file)";
  }
  return cam;
}

SpotLightDesc choose_light(const Importer& imp, const std::vector<LightInstance>& lights, const GltfLightChoice& choice,
                           const SceneBounds& b, std::string& source) {
  const tinygltf::Model& m = imp.model();
  const Reporter& r = imp.reporter();
  SpotLightDesc light;
  const LightInstance* file_spot = nullptr;
  std::size_t other_lights = 0;
  for (const LightInstance& l : lights) {
    if (m.lights[static_cast<std::size_t>(l.light)].type == "spot") {
      if (file_spot == nullptr) file_spot = &l;
    } else {
      ++other_lights;
    }
  }
  if (file_spot != nullptr) {
    const tinygltf::Light& src = m.lights[static_cast<std::size_t>(file_spot->light)];
    const glm::dmat3 linear(file_spot->world);
    light.position = glm::vec3(file_spot->world[3]);
    light.direction = glm::normalize(glm::vec3(linear * glm::dvec3(0.0, 0.0, -1.0)));
    light.cone_half_angle_deg = static_cast<float>(src.spot.outerConeAngle * 180.0 / std::numbers::pi);
    glm::vec3 colour(1.0f);
    if (src.color.size() == 3) colour = glm::vec3(glm::make_vec3(src.color.data()));
    light.intensity = colour * static_cast<float>(src.intensity);  // candela read as W/sr
    source = "the file's spot light " + std::to_string(file_spot->light) + " " + quote_name(src.name) +
             " on node " + std::to_string(file_spot->node);
  } else {
    // Above the centre, at twice the bounds' radius, aimed straight down; the cone covers the
    // bounds, and the intensity gives an irradiance of pi W/m^2 at the centre.
    const float height = 2.0f * b.radius;
    light.position = b.centre + glm::vec3(0.0f, height, 0.0f);
    light.direction = glm::vec3(0.0f, -1.0f, 0.0f);
    light.cone_half_angle_deg = 30.0f;
    light.intensity = glm::vec3(std::numbers::pi_v<float> * height * height);
    source = "an automatic spot above the centre of the bounds" +
             std::string(other_lights > 0 ? " (the file's point/directional lights are not spots)" : " (no spot light in the file)");
  }
  if (choice.position || choice.direction || choice.cone_half_angle_deg || choice.intensity) {
    if (choice.position) light.position = *choice.position;
    if (choice.direction) {
      if (!(glm::length(*choice.direction) > 1e-6f)) throw UsageError("--light-dir must not be zero");
      light.direction = glm::normalize(*choice.direction);
    }
    if (choice.cone_half_angle_deg) light.cone_half_angle_deg = *choice.cone_half_angle_deg;
    if (choice.intensity) light.intensity = *choice.intensity;
    source += ", with --light-pos/--light-dir/--cone/--intensity applied";
  }
  if (!(light.cone_half_angle_deg > 0.5f && light.cone_half_angle_deg <= 85.0f))
    r.fail("the spot light's cone half angle is " + std::to_string(light.cone_half_angle_deg) +
           " degrees; it must lie in (0.5, 85] (the RSM is a perspective view of twice that angle)");
  light.up = spot_light_up(light.direction);
  light.far_plane = far_for(light.position, b.far_lo, b.far_hi);
  light.near_plane = std::max(1e-4f * light.far_plane, 1e-3f * b.radius);
  source += ": position " + vec_text(light.position) + ", direction " + vec_text(light.direction) +
            ", cone " + std::to_string(static_cast<int>(std::lround(light.cone_half_angle_deg))) +
            " degrees, intensity " + vec_text(light.intensity) + " W/sr";
  return light;
}

}  // namespace vsgl::gltf
