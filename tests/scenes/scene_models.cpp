// tests/scenes/scene_models.cpp — the shared wall, box, sprite and particle builders.
#include "scene_models.h"

#include <cmath>
#include <cstdint>
#include <utility>

#include <glm/geometric.hpp>

namespace arc::scenes {

ModelData wall_model(float w, float h, glm::vec4 base, glm::vec3 emissive) {
  ModelData m;
  MeshPrimitive p;
  p.positions = {{-w / 2, -h / 2, 0}, {w / 2, -h / 2, 0}, {w / 2, h / 2, 0}, {-w / 2, h / 2, 0}};
  p.normals.assign(4, glm::vec3(0, 0, 1));
  p.indices = {0, 1, 2, 0, 2, 3};
  p.material = 0;
  m.primitives.push_back(p);
  m.materials.push_back({base, emissive, -1, -1});
  m.radius = std::sqrt(w * w + h * h) / 2;
  return m;
}

ModelData box_model(glm::vec3 hf, glm::vec4 base, glm::vec3 emissive) {
  ModelData m;
  MeshPrimitive p;
  const glm::vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int a = 0; a < 3; ++a)
    for (float s : {-1.0f, 1.0f}) {
      glm::vec3 n = axes[a] * s, u = axes[(a + 1) % 3], v = axes[(a + 2) % 3];
      uint32_t base_index = uint32_t(p.positions.size());
      for (auto [cu, cv] : {std::pair{-1.f, -1.f}, {1.f, -1.f}, {1.f, 1.f}, {-1.f, 1.f}}) {
        p.positions.push_back((n + u * cu + v * cv) * hf);
        p.normals.push_back(n);
      }
      p.indices.insert(p.indices.end(), {base_index, base_index + 1, base_index + 2, base_index, base_index + 2, base_index + 3});
    }
  p.material = 0;
  m.primitives.push_back(p);
  m.materials.push_back({base, emissive, -1, -1});
  m.radius = glm::length(hf);
  return m;
}

Image soft_sprite(int size) {
  Image img;
  img.width = img.height = size;
  img.premultiplied = true;
  img.rgba.resize(size_t(size) * size * 4);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      float dx = (x + 0.5f) / size * 2 - 1, dy = (y + 0.5f) / size * 2 - 1;
      float r2 = dx * dx + dy * dy;
      float a = r2 >= 1 ? 0.0f : std::pow(1 - r2, 1.5f);
      uint8_t v = uint8_t(std::lround(a * 255));
      for (int c = 0; c < 4; ++c) img.rgba[(size_t(y) * size + x) * 4 + c] = v;
    }
  return img;
}

ParticleInstance particle(glm::vec3 pos, float size, glm::vec3 rgb, float alpha, float burn, SoftEdge soft) {
  ParticleInstance p{};
  p.pos[0] = pos.x;
  p.pos[1] = pos.y;
  p.pos[2] = pos.z;
  p.size = size;
  p.color[0] = rgb.r * alpha;
  p.color[1] = rgb.g * alpha;
  p.color[2] = rgb.b * alpha;
  p.color[3] = alpha;
  p.burn = burn;
  p.soft_edge = uint8_t(soft);
  p.billboard = uint8_t(Billboard::CameraFacing);
  return p;
}

}  // namespace arc::scenes
