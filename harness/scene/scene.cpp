// The procedural scenes of DESIGN.md §3. Units: metres; spot intensity in W/sr. The coordinate frame
// is y-up; rooms are closed boxes whose surfaces face inward, and the camera and the light are
// inside them. Nothing here is random: the scenes are the same bytes on every run.
#include "harness/scene/scene.hpp"

#include <array>
#include <cmath>
#include <map>
#include <mutex>
#include <numbers>

#include "harness/core/error.hpp"
#include "harness/core/portable_float.hpp"
#include "harness/scene/scene_geometry.hpp"
#include "harness/scene/surface_detail.hpp"

namespace vsgl {
namespace {

struct SceneSetup {
  Scene scene;
  SceneMotion motion;
};

glm::vec3 light_up_for(glm::vec3 direction) { return spot_light_up(direction); }

SpotLightDesc spot_light(glm::vec3 position, glm::vec3 direction, float cone_half_angle_deg,
                         glm::vec3 intensity, float far_plane) {
  SpotLightDesc light;
  light.position = position;
  light.direction = glm::normalize(direction);
  light.up = light_up_for(light.direction);
  light.cone_half_angle_deg = cone_half_angle_deg;
  light.intensity = intensity;
  light.near_plane = 0.05f;
  light.far_plane = far_plane;
  return light;
}

CameraDesc camera(glm::vec3 position, glm::vec3 target, float fov_y_deg, float far_plane) {
  CameraDesc c;
  c.position = position;
  c.target = target;
  c.up = glm::vec3(0.0f, 1.0f, 0.0f);
  c.fov_y_deg = fov_y_deg;
  c.near_plane = 0.05f;
  c.far_plane = far_plane;
  return c;
}

// A long hall standing in for Table 1: broad lighting, coloured walls, a glossy floor. Surface
// detail (surface_detail.hpp): polished stone tiles with grout on the floor, dressed stone
// blocks on the walls, speckled stone columns; the ceiling is plain plaster.
SceneSetup make_atrium() {
  constexpr float kHalfWidth = 5.0f, kHeight = 12.0f, kHalfLength = 15.0f;
  Scene scene;
  scene.name = "atrium";
  const DetailMaterial tiles = add_surface_detail(scene, stone_floor_tiles());
  const DetailMaterial ashlar = add_surface_detail(scene, ashlar_wall());
  const DetailMaterial column_stone = add_surface_detail(scene, speckled_stone());
  const SurfaceMaterial red_wall = detailed_surface(ashlar, {0.62f, 0.18f, 0.14f}, glm::vec3(0.04f));
  const SurfaceMaterial green_wall = detailed_surface(ashlar, {0.18f, 0.52f, 0.20f}, glm::vec3(0.04f));
  const SurfaceMaterial neutral_wall = detailed_surface(ashlar, {0.60f, 0.58f, 0.55f}, glm::vec3(0.04f));
  const SurfaceMaterial ceiling{{0.70f, 0.70f, 0.70f}, glm::vec3(0.02f), 0.9f};
  const SurfaceMaterial glossy_floor = detailed_surface(tiles, {0.40f, 0.38f, 0.36f}, glm::vec3(0.40f));
  const SurfaceMaterial stone = detailed_surface(column_stone, {0.72f, 0.68f, 0.60f}, glm::vec3(0.05f));

  SceneMesh& mesh = scene.mesh;
  add_room(mesh, {-kHalfWidth, 0.0f, -kHalfLength}, {kHalfWidth, kHeight, kHalfLength},
           {red_wall, green_wall, glossy_floor, ceiling, neutral_wall, neutral_wall}, 1.0f);

  // Two rows of six columns: a square plinth and capital around a 16-sided shaft.
  constexpr float kRowX = 3.0f, kPlinthHalf = 0.5f, kPlinthHeight = 0.4f, kShaftRadius = 0.35f;
  for (float x : {-kRowX, kRowX}) {
    for (int i = 0; i < 6; ++i) {
      const float z = -12.5f + 5.0f * static_cast<float>(i);
      // The plinth's bottom lies on the floor and the capital's top against the ceiling.
      add_box(mesh, {x - kPlinthHalf, 0.0f, z - kPlinthHalf}, {x + kPlinthHalf, kPlinthHeight, z + kPlinthHalf},
              stone, kBoxAllFaces & ~kBoxNegY);
      add_box(mesh, {x - kPlinthHalf, kHeight - kPlinthHeight, z - kPlinthHalf},
              {x + kPlinthHalf, kHeight, z + kPlinthHalf}, stone, kBoxAllFaces & ~kBoxPosY);
      add_open_cylinder(mesh, {x, kPlinthHeight, z}, kShaftRadius, kHeight - 2.0f * kPlinthHeight, 16, stone);
    }
  }

  // High on the left, aimed down and across at the floor near the right row: about 38 degrees
  // from vertical, so the cone also reaches the green wall and several columns.
  const glm::vec3 light_position(-2.0f, 11.2f, 3.0f);
  const glm::vec3 light_aim(1.5f, 0.0f, -5.0f);
  scene.light = spot_light(light_position, light_aim - light_position, 40.0f, glm::vec3(400.0f), 60.0f);
  scene.camera = camera({0.0f, 1.7f, 13.5f}, {0.0f, 2.5f, -15.0f}, 60.0f, 60.0f);
  return {scene, SceneMotion{0.5f, 1.5f, 1.0f}};
}

// One chair whose front faces `towards` (a horizontal unit axis), seat centred at (x, z):
// seat, backrest on the far side from `towards`, four legs.
void add_chair(SceneMesh& mesh, float x, float z, glm::vec3 towards, const SurfaceMaterial& fabric,
               const SurfaceMaterial& metal) {
  // Chair-local frame: +a = towards, +b = the horizontal axis to its left. The rotations are by
  // multiples of 90 degrees, so boxes stay axis-aligned; corners are mapped and re-sorted.
  const glm::vec3 a = towards, b(-towards.z, 0.0f, towards.x);
  const glm::vec3 centre(x, 0.0f, z);
  auto box = [&](float a0, float a1, float b0, float b1, float y0, float y1, const SurfaceMaterial& m,
                 uint32_t faces_without_bottom) {
    const glm::vec3 p = centre + a0 * a + b0 * b + glm::vec3(0.0f, y0, 0.0f);
    const glm::vec3 q = centre + a1 * a + b1 * b + glm::vec3(0.0f, y1, 0.0f);
    add_box(mesh, glm::min(p, q), glm::max(p, q), m, faces_without_bottom);
  };
  constexpr float kHalfSeat = 0.23f, kSeatTop = 0.47f, kSeatThickness = 0.05f, kLeg = 0.02f;
  box(-kHalfSeat, kHalfSeat, -kHalfSeat, kHalfSeat, kSeatTop - kSeatThickness, kSeatTop, fabric, kBoxAllFaces);
  box(-kHalfSeat, -kHalfSeat + 0.05f, -kHalfSeat, kHalfSeat, kSeatTop, kSeatTop + 0.50f, fabric,
      kBoxAllFaces & ~kBoxNegY);
  for (float la : {-1.0f, 1.0f}) {
    for (float lb : {-1.0f, 1.0f}) {
      const float ca = la * (kHalfSeat - 0.03f), cb = lb * (kHalfSeat - 0.03f);
      // Legs stand on the floor and end under the seat: neither end can be seen.
      box(ca - kLeg, ca + kLeg, cb - kLeg, cb + kLeg, 0.0f, kSeatTop - kSeatThickness, metal,
          kBoxAllFaces & ~(kBoxNegY | kBoxPosY));
    }
  }
}

// A meeting room standing in for Table 2: the spot light concentrated on a glossy table, so the
// BRSM PDF is higher-frequency and more concentrated than in the atrium. Surface detail
// (surface_detail.hpp): a lacquered plank table with growth rings, satin wood pedestals and
// cabinet, carpet tiles, a painted brick accent wall, board-panelled walls, a smudged
// whiteboard; the ceiling, the chairs' fabric and their metal legs are plain.
SceneSetup make_conference() {
  constexpr float kHalfX = 6.0f, kHalfZ = 4.0f, kHeight = 3.5f;
  Scene scene;
  scene.name = "conference";
  const DetailMaterial panels = add_surface_detail(scene, wall_panels());
  const DetailMaterial brick = add_surface_detail(scene, painted_brick());
  const DetailMaterial carpet_detail = add_surface_detail(scene, carpet_tiles());
  const DetailMaterial lacquered = add_surface_detail(scene, wood_grain(0.07f));
  const DetailMaterial satin = add_surface_detail(scene, wood_grain(0.4f));
  const DetailMaterial board = add_surface_detail(scene, smudged_gloss());
  const SurfaceMaterial wall = detailed_surface(panels, {0.70f, 0.68f, 0.62f}, glm::vec3(0.04f));
  const SurfaceMaterial accent_wall = detailed_surface(brick, {0.25f, 0.35f, 0.55f}, glm::vec3(0.04f));
  const SurfaceMaterial carpet = detailed_surface(carpet_detail, {0.30f, 0.28f, 0.26f}, glm::vec3(0.02f));
  const SurfaceMaterial ceiling{{0.80f, 0.80f, 0.80f}, glm::vec3(0.02f), 0.9f};
  const SurfaceMaterial glossy_table = detailed_surface(lacquered, {0.28f, 0.16f, 0.08f}, glm::vec3(0.60f));
  const SurfaceMaterial wood = detailed_surface(satin, {0.45f, 0.30f, 0.18f}, glm::vec3(0.08f));
  const SurfaceMaterial fabric{{0.15f, 0.18f, 0.32f}, glm::vec3(0.03f), 0.8f};
  const SurfaceMaterial metal{{0.05f, 0.05f, 0.05f}, glm::vec3(0.70f), 0.25f};
  const SurfaceMaterial whiteboard = detailed_surface(board, {0.85f, 0.85f, 0.85f}, glm::vec3(0.30f));

  SceneMesh& mesh = scene.mesh;
  add_room(mesh, {-kHalfX, 0.0f, -kHalfZ}, {kHalfX, kHeight, kHalfZ},
           {accent_wall, wall, carpet, ceiling, wall, wall}, 0.5f);

  // The table: a 5 x 2 m top, 5 cm thick, on two pedestals.
  constexpr float kTableTop = 0.75f, kTableHalfX = 2.5f, kTableHalfZ = 1.0f;
  add_box(mesh, {-kTableHalfX, kTableTop - 0.05f, -kTableHalfZ}, {kTableHalfX, kTableTop, kTableHalfZ}, glossy_table);
  for (float x : {-1.6f, 1.6f}) {
    add_box(mesh, {x - 0.3f, 0.0f, -0.4f}, {x + 0.3f, kTableTop - 0.05f, 0.4f}, wood,
            kBoxAllFaces & ~(kBoxNegY | kBoxPosY));
  }

  // Ten chairs: four along each long side, one at each end, all facing the table.
  for (float x : {-1.8f, -0.6f, 0.6f, 1.8f}) {
    add_chair(mesh, x, -1.45f, {0.0f, 0.0f, 1.0f}, fabric, metal);
    add_chair(mesh, x, 1.45f, {0.0f, 0.0f, -1.0f}, fabric, metal);
  }
  add_chair(mesh, -3.0f, 0.0f, {1.0f, 0.0f, 0.0f}, fabric, metal);
  add_chair(mesh, 3.0f, 0.0f, {-1.0f, 0.0f, 0.0f}, fabric, metal);

  // A cabinet against the -x wall and a whiteboard on the -z wall (backs against the walls).
  add_box(mesh, {-kHalfX, 0.0f, -1.5f}, {-kHalfX + 0.5f, 1.0f, 1.5f}, wood, kBoxAllFaces & ~(kBoxNegX | kBoxNegY));
  add_box(mesh, {-2.0f, 1.0f, -kHalfZ}, {2.0f, 2.2f, -kHalfZ + 0.02f}, whiteboard, kBoxAllFaces & ~kBoxNegZ);

  // Just under the ceiling, tilted about 16 degrees onto the table; the 28-degree cone lights a
  // disc of about 1.4 m radius on it.
  const glm::vec3 light_position(-0.6f, 3.2f, 0.4f);
  const glm::vec3 light_aim(0.0f, kTableTop, 0.0f);
  scene.light = spot_light(light_position, light_aim - light_position, 28.0f, glm::vec3(120.0f), 30.0f);
  scene.camera = camera({5.3f, 2.2f, 3.4f}, {0.0f, kTableTop, 0.0f}, 60.0f, 30.0f);
  return {scene, SceneMotion{0.2f, 1.5f, 0.3f}};
}

// The test scene: a 4 x 4 m floor at y = 0, one box on it, one back wall, a spot straight down.
SceneSetup make_tiny() {
  const SurfaceMaterial floor{glm::vec3(0.5f), glm::vec3(0.04f), 0.5f};
  const SurfaceMaterial box{{0.70f, 0.30f, 0.20f}, glm::vec3(0.04f), 0.5f};
  const SurfaceMaterial wall{{0.30f, 0.40f, 0.60f}, glm::vec3(0.04f), 0.5f};

  Scene scene;
  scene.name = "tiny";
  SceneMesh& mesh = scene.mesh;
  add_axis_rect(mesh, {-2.0f, 0.0f, -2.0f}, {2.0f, 0.0f, 2.0f}, {0.0f, 1.0f, 0.0f}, floor, 4.0f);
  // Off the spot axis, so the floor under the light (the cos^3 test) is unoccluded.
  add_box(mesh, {0.5f, 0.0f, -1.5f}, {1.5f, 1.0f, -0.5f}, box, kBoxAllFaces & ~kBoxNegY);
  add_axis_rect(mesh, {-2.0f, 0.0f, -2.0f}, {2.0f, 2.5f, -2.0f}, {0.0f, 0.0f, 1.0f}, wall, 4.0f);

  scene.light = spot_light({0.0f, 3.0f, 0.0f}, {0.0f, -1.0f, 0.0f}, 40.0f, glm::vec3(10.0f), 20.0f);
  scene.camera = camera({0.0f, 2.5f, 4.0f}, {0.0f, 0.3f, 0.0f}, 60.0f, 20.0f);
  return {scene, SceneMotion{0.2f, 1.5f, 0.3f}};
}

// Moves light and camera to phase phi. Applied to every frame, the static one included (phi = 0),
// so frame 0 of a sequence and the static scene come from the same arithmetic on the same inputs.
void apply_motion(Scene& scene, const SceneMotion& motion, float phi) {
  const float s = portable::sin(phi), c1 = 1.0f - portable::cos(phi);  // both exactly 0 at phi = 0

  SpotLightDesc& light = scene.light;
  light.position += motion.light_circle_m * glm::vec3(c1, 0.0f, s);
  // Precession of the axis: tilt it towards its own "right" and "up" by a small vector.
  const glm::vec3 right = glm::cross(light.direction, light.up);
  const float tilt = portable::tan(motion.aim_wobble_deg * std::numbers::pi_v<float> / 180.0f);
  light.direction = glm::normalize(light.direction + tilt * (s * right + c1 * light.up));
  light.up = light_up_for(light.direction);

  CameraDesc& cam = scene.camera;
  const glm::vec3 forward = glm::normalize(cam.target - cam.position);
  const glm::vec3 dolly = motion.camera_dolly_m * 0.5f * c1 * forward;
  cam.position += dolly;
  cam.target += dolly;
}

std::string valid_names_text() {
  std::string text;
  for (const std::string& name : scene_names()) text += (text.empty() ? "" : ", ") + name;
  return text;
}

}  // namespace

glm::vec3 spot_light_up(glm::vec3 direction) {
  glm::vec3 hint(0.0f, 0.0f, -1.0f);
  if (std::abs(glm::dot(hint, direction)) > 0.9f) hint = glm::vec3(1.0f, 0.0f, 0.0f);
  return glm::normalize(hint - glm::dot(hint, direction) * direction);
}

void animate_scene(Scene& scene, const SceneMotion& motion, uint32_t frame, uint32_t frames) {
  if (frames == 0 || frame >= frames) {
    throw InputError("scene '" + scene.name + "': frame " + std::to_string(frame) + " is outside a sequence of " +
                     std::to_string(frames) + " frames (need frames >= 1 and frame < frames)");
  }
  const float phi = 2.0f * std::numbers::pi_v<float> * static_cast<float>(frame) / static_cast<float>(frames);
  apply_motion(scene, motion, phi);
}

std::vector<std::string> scene_names() { return {"atrium", "conference", "tiny"}; }

Scene make_scene(const std::string& name, uint32_t frame, uint32_t frames) {
  // Painting the surface detail takes a good part of a second, and a sequence asks for the same
  // scene once per frame: each scene is built once per process, then copied.
  static std::mutex mutex;
  static std::map<std::string, SceneSetup> built;
  SceneSetup setup;
  {
    const std::lock_guard<std::mutex> lock(mutex);
    auto it = built.find(name);
    if (it == built.end()) {
      if (name == "atrium") {
        setup = make_atrium();
      } else if (name == "conference") {
        setup = make_conference();
      } else if (name == "tiny") {
        setup = make_tiny();
      } else {
        throw InputError("scene: unknown scene '" + name + "' (valid scenes: " + valid_names_text() + ")");
      }
      it = built.emplace(name, setup).first;
    }
    setup = it->second;
  }
  animate_scene(setup.scene, setup.motion, frame, frames);
  return setup.scene;
}

}  // namespace vsgl
