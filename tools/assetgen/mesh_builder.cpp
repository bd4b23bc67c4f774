// tools/assetgen/mesh_builder.cpp — lofting, orientation and .glb output through tinygltf.
#include "mesh_builder.h"
#include <cmath>
#include <cstring>
#include <sstream>
#include <stdexcept>
#include <glm/common.hpp>
#include <glm/vec2.hpp>
#include <glm/geometric.hpp>
#include <tiny_gltf.h>
#include "core/file_writer.h"
#include "core/json.h"

namespace arc::assetgen {
namespace {

constexpr double kPi = 3.14159265358979323846;

double signed_power(double v, double e) { return v < 0.0 ? -std::pow(-v, e) : std::pow(v, e); }

bool degenerate(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  return glm::length(glm::cross(b - a, c - a)) < 1e-9;
}

void push(Solid& s, int m, glm::dvec3 a, glm::dvec3 b, glm::dvec3 c) {
  if (!degenerate(a, b, c)) s.tris.push_back({m, a, b, c});
}

template <typename T>
void append_bytes(std::vector<unsigned char>& buf, const std::vector<T>& values) {
  const size_t at = buf.size();
  buf.resize(at + values.size() * sizeof(T));
  std::memcpy(buf.data() + at, values.data(), values.size() * sizeof(T));
  while (buf.size() % 4) buf.push_back(0);
}

int add_view(tinygltf::Model& m, size_t offset, size_t length, int target) {
  tinygltf::BufferView v;
  v.buffer = 0;
  v.byteOffset = offset;
  v.byteLength = length;
  v.target = target;
  m.bufferViews.push_back(v);
  return int(m.bufferViews.size() - 1);
}

int add_accessor(tinygltf::Model& m, int view, int component, int type, size_t count) {
  tinygltf::Accessor a;
  a.bufferView = view;
  a.componentType = component;
  a.type = type;
  a.count = count;
  m.accessors.push_back(a);
  return int(m.accessors.size() - 1);
}

// Box projection: the triangle's points on the plane its normal faces most, in tiles.
glm::vec2 box_uv(const glm::dvec3& p, const glm::dvec3& n, double metres_per_tile) {
  const glm::dvec3 a = glm::abs(n);
  glm::dvec2 uv = a.x >= a.y && a.x >= a.z ? glm::dvec2(p.z, p.y) : a.y >= a.z ? glm::dvec2(p.x, p.z) : glm::dvec2(p.x, p.y);
  return glm::vec2(uv / metres_per_tile);
}

// One primitive of the triangles of material `mat` (none: nothing added): positions, flat
// normals, box-projected UVs when the model has a detail texture, and the smallest index type.
void add_primitive(tinygltf::Model& m, tinygltf::Mesh& mesh, const std::vector<Tri>& tris, int mat, double uv_tile) {
  std::vector<unsigned char>& buf = m.buffers[0].data;
  std::vector<float> pos, nrm, uv;
  std::vector<uint32_t> idx32;
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (const auto& t : tris) {
    if (t.material != mat) continue;
    const glm::dvec3 nd = glm::normalize(glm::cross(t.b - t.a, t.c - t.a));
    const glm::vec3 n(nd);
    for (const glm::dvec3& p : {t.a, t.b, t.c}) {
      const glm::vec3 pf(p);
      lo = glm::min(lo, pf);
      hi = glm::max(hi, pf);
      pos.insert(pos.end(), {pf.x, pf.y, pf.z});
      nrm.insert(nrm.end(), {n.x, n.y, n.z});
      if (uv_tile > 0.0) {
        const glm::vec2 st = box_uv(p, nd, uv_tile);
        uv.insert(uv.end(), {st.x, st.y});
      }
      idx32.push_back(uint32_t(idx32.size()));
    }
  }
  if (idx32.empty()) return;
  const size_t count = idx32.size();
  tinygltf::Primitive prim;
  prim.mode = TINYGLTF_MODE_TRIANGLES;
  prim.material = mat;
  size_t at = buf.size();
  append_bytes(buf, pos);
  prim.attributes["POSITION"] = add_accessor(m, add_view(m, at, count * 12, TINYGLTF_TARGET_ARRAY_BUFFER),
                                             TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, count);
  m.accessors.back().minValues = {lo.x, lo.y, lo.z};
  m.accessors.back().maxValues = {hi.x, hi.y, hi.z};
  at = buf.size();
  append_bytes(buf, nrm);
  prim.attributes["NORMAL"] = add_accessor(m, add_view(m, at, count * 12, TINYGLTF_TARGET_ARRAY_BUFFER),
                                           TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, count);
  if (!uv.empty()) {
    at = buf.size();
    append_bytes(buf, uv);
    prim.attributes["TEXCOORD_0"] = add_accessor(m, add_view(m, at, count * 8, TINYGLTF_TARGET_ARRAY_BUFFER),
                                                 TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2, count);
  }
  at = buf.size();
  // The smallest index type that fits keeps the files small and exercises the u16 path.
  if (count <= 65535) {
    std::vector<uint16_t> idx16(idx32.begin(), idx32.end());
    append_bytes(buf, idx16);
    prim.indices = add_accessor(m, add_view(m, at, count * 2, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER),
                                TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_SCALAR, count);
  } else {
    append_bytes(buf, idx32);
    prim.indices = add_accessor(m, add_view(m, at, count * 4, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER),
                                TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, count);
  }
  mesh.primitives.push_back(prim);
}

// The detail texture as image 0 / texture 0: PNG bytes in the binary buffer, repeating.
void add_detail_image(tinygltf::Model& m, const std::string& png) {
  std::vector<unsigned char>& buf = m.buffers[0].data;
  const size_t at = buf.size();
  buf.insert(buf.end(), png.begin(), png.end());
  while (buf.size() % 4) buf.push_back(0);
  tinygltf::Image image;
  image.name = "hull_detail";
  image.mimeType = "image/png";
  image.bufferView = add_view(m, at, png.size(), 0);
  m.images.push_back(image);
  tinygltf::Sampler sampler;
  sampler.magFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
  sampler.minFilter = TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR;
  sampler.wrapS = sampler.wrapT = TINYGLTF_TEXTURE_WRAP_REPEAT;
  m.samplers.push_back(sampler);
  tinygltf::Texture texture;
  texture.sampler = 0;
  texture.source = 0;
  m.textures.push_back(texture);
}

}  // namespace

Ring ring_z(double z, double w, double h, int sides, double cx, double cy, double exponent) {
  Ring r;
  for (int i = 0; i < sides; ++i) {
    // Offset by half a step so the section has a flat top and bottom, not a ridge.
    const double a = 2.0 * kPi * (i + 0.5) / sides;
    r.push_back({cx + w * signed_power(std::cos(a), 2.0 / exponent), cy + h * signed_power(std::sin(a), 2.0 / exponent), z});
  }
  return r;
}

Ring circle_z(double z, double r, int sides, double cx, double cy) { return ring_z(z, r, r, sides, cx, cy, 2.0); }

Ring wing_section(double x, double y, double z_le, double chord, double thickness) {
  const double t = thickness * 0.5;
  return {{x, y, z_le},
          {x, y + t, z_le + 0.3 * chord},
          {x, y + 0.6 * t, z_le + 0.75 * chord},
          {x, y, z_le + chord},
          {x, y - 0.6 * t, z_le + 0.75 * chord},
          {x, y - t, z_le + 0.3 * chord}};
}

Solid loft(const std::vector<Ring>& rings, const std::vector<int>& segment_materials, int start_cap, int end_cap) {
  if (rings.size() < 2 || segment_materials.empty()) throw std::logic_error("loft needs two rings and a material");
  const size_t n = rings[0].size();
  Solid s;
  for (size_t i = 0; i + 1 < rings.size(); ++i) {
    if (rings[i].size() != n || rings[i + 1].size() != n) throw std::logic_error("loft rings differ in size");
    const int m = segment_materials[std::min(i, segment_materials.size() - 1)];
    for (size_t j = 0; j < n; ++j) {
      const size_t k = (j + 1) % n;
      push(s, m, rings[i][j], rings[i][k], rings[i + 1][k]);
      push(s, m, rings[i][j], rings[i + 1][k], rings[i + 1][j]);
    }
  }
  auto centroid = [](const Ring& r) {
    glm::dvec3 c(0.0);
    for (const auto& p : r) c += p;
    return c / double(r.size());
  };
  const Ring& first = rings.front();
  const Ring& last = rings.back();
  const glm::dvec3 c0 = centroid(first), c1 = centroid(last);
  for (size_t j = 0; j < n; ++j) {
    const size_t k = (j + 1) % n;
    push(s, start_cap, c0, first[k], first[j]);
    push(s, end_cap, c1, last[j], last[k]);
  }
  return outward(std::move(s));
}

Solid box(glm::dvec3 lo, glm::dvec3 hi, int material) {
  Ring a = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z}};
  Ring b = a;
  for (auto& p : b) p.z = hi.z;
  return loft({a, b}, {material}, material, material);
}

Solid outward(Solid s) {
  double volume = 0.0;
  for (const auto& t : s.tris) volume += glm::dot(t.a, glm::cross(t.b, t.c));
  if (volume < 0.0)
    for (auto& t : s.tris) std::swap(t.b, t.c);
  return s;
}

Solid mirror_x(const Solid& s) {
  Solid m;
  for (const auto& t : s.tris) {
    auto f = [](glm::dvec3 p) { return glm::dvec3(-p.x, p.y, p.z); };
    m.tris.push_back({t.material, f(t.a), f(t.c), f(t.b)});
  }
  return m;
}

Solid translated(const Solid& s, glm::dvec3 offset) {
  Solid m = s;
  for (auto& t : m.tris) {
    t.a += offset;
    t.b += offset;
    t.c += offset;
  }
  return m;
}

void MeshBuilder::set_detail_texture(std::string png_bytes, double metres_per_tile) {
  detail_png_ = std::move(png_bytes);
  metres_per_tile_ = metres_per_tile;
}

void MeshBuilder::add(const Solid& s) { tris_.insert(tris_.end(), s.tris.begin(), s.tris.end()); }

void MeshBuilder::add_tri(int material, glm::dvec3 a, glm::dvec3 b, glm::dvec3 c) {
  if (!degenerate(a, b, c)) tris_.push_back({material, a, b, c});
}

void MeshBuilder::write_glb(const std::string& path, const std::string& name, const std::vector<MaterialDef>& materials) const {
  tinygltf::Model m;
  m.asset.version = "2.0";
  m.asset.generator = "arcfire-assetgen";
  m.buffers.emplace_back();
  tinygltf::Mesh mesh;
  mesh.name = name;
  const bool detail = !detail_png_.empty();
  for (size_t mat = 0; mat < materials.size(); ++mat) add_primitive(m, mesh, tris_, int(mat), detail ? metres_per_tile_ : 0.0);
  if (detail) add_detail_image(m, detail_png_);
  for (const auto& def : materials) {
    tinygltf::Material mat;
    mat.name = def.name;
    mat.pbrMetallicRoughness.baseColorFactor = {def.base_color.r, def.base_color.g, def.base_color.b, def.base_color.a};
    mat.pbrMetallicRoughness.metallicFactor = def.metallic;
    mat.pbrMetallicRoughness.roughnessFactor = def.roughness;
    if (detail && def.detail) mat.pbrMetallicRoughness.baseColorTexture.index = 0;
    mat.emissiveFactor = {def.emissive.r, def.emissive.g, def.emissive.b};
    if (def.team_color > 0.0f)
      mat.extras = tinygltf::Value(tinygltf::Value::Object{{"arcfire_team_color", tinygltf::Value(double(def.team_color))}});
    m.materials.push_back(mat);
  }
  m.meshes.push_back(mesh);
  tinygltf::Node node;
  node.name = name;
  node.mesh = 0;
  m.nodes.push_back(node);
  tinygltf::Scene scene;
  scene.name = name;
  scene.nodes = {0};
  m.scenes.push_back(scene);
  m.defaultScene = 0;

  std::ostringstream out;
  tinygltf::TinyGLTF writer;
  if (!writer.WriteGltfSceneToStream(&m, out, false, true)) throw std::runtime_error(path + ": tinygltf could not write the model");
  write_file_atomic(path, out.str());
}

}  // namespace arc::assetgen
