// assets/model.cpp — glTF 2.0 (.gltf/.glb) into ModelData, checking every index and byte range
// before it is read, so a malformed file is an InputError and never an out-of-bounds read.
#include <cmath>
#include <cstring>
#include <filesystem>
#include <set>
#include <string>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <tiny_gltf.h>
#include "assets/gltf_claims.h"
#include "assets/image_codec.h"
#include "assets/image_decode.h"
#include "assets/model.h"
#include "core/error.h"
#include "core/input_file.h"
#include "core/input_limits.h"

namespace arc {
namespace {

// Deeper node chains than this are a malformed (or hostile) file, not a real model.
constexpr int kMaxNodeDepth = 256;

uint32_t read_u32(const std::string& bytes, size_t at) {
  uint32_t v = 0;
  std::memcpy(&v, bytes.data() + at, 4);
  return v;  // glb is little-endian, as is every target platform
}

// tinygltf trusts the chunk lengths in a .glb more than it should; check the container first.
void validate_glb_container(const std::string& path, const std::string& bytes) {
  const size_t size = bytes.size();
  if (size < 12) throw InputError(path + ": truncated .glb: " + std::to_string(size) + " bytes, the header alone needs 12");
  if (bytes.compare(0, 4, "glTF") != 0) throw InputError(path + ": not a binary glTF file (the first 4 bytes must be 'glTF')");
  const uint32_t version = read_u32(bytes, 4);
  if (version != 2) throw InputError(path + ": .glb container version " + std::to_string(version) + " is not supported (only 2)");
  const uint64_t length = read_u32(bytes, 8);
  if (length > size)
    throw InputError(path + ": truncated .glb: header says " + std::to_string(length) + " bytes, file has " + std::to_string(size));
  if (length != size)
    throw InputError(path + ": .glb header length " + std::to_string(length) + " does not match the file size " + std::to_string(size));
  if (size < 20) throw InputError(path + ": truncated .glb: no room for the JSON chunk header");
  const uint64_t json_len = read_u32(bytes, 12);
  if (read_u32(bytes, 16) != 0x4E4F534Au) throw InputError(path + ": the first .glb chunk must be of type JSON");
  if (20 + json_len > length) throw InputError(path + ": truncated .glb: the JSON chunk runs past the end of the file");
  uint64_t at = 20 + json_len;
  if (at == length) return;
  if (at + 8 > length) throw InputError(path + ": truncated .glb: incomplete chunk header after the JSON chunk");
  const uint64_t bin_len = read_u32(bytes, size_t(at));
  if (read_u32(bytes, size_t(at + 4)) != 0x004E4942u) throw InputError(path + ": the second .glb chunk must be of type BIN");
  if (at + 8 + bin_len > length) throw InputError(path + ": truncated .glb: the BIN chunk runs past the end of the file");
}

// What the image loader callback needs: the model's name and the decoded bytes so far.
struct ImageBudget {
  std::string model_path;
  size_t decoded_bytes = 0;
  std::string codec_error;  // the image codec module could not be loaded: not the model's fault
};

// Embedded and external images are decoded through OpenImageIO, like every other image.
bool decode_gltf_image(tinygltf::Image* image, const int index, std::string* err, std::string*, int, int,
                       const unsigned char* bytes, int size, void* user) {
  ImageBudget& budget = *static_cast<ImageBudget*>(user);
  const std::string& model_path = budget.model_path;
  std::string ext = ".png";
  if (size >= 2 && bytes[0] == 0xFF && bytes[1] == 0xD8) ext = ".jpg";
  try {
    Image decoded = decode_image_memory(bytes, size_t(size > 0 ? size : 0),
                                        model_path + "#image" + std::to_string(index) + ext);
    budget.decoded_bytes += decoded.rgba.size();
    if (budget.decoded_bytes > kMaxModelImageBytes)
      throw InputError(model_path + ": the model's images decode to more than " + std::to_string(kMaxModelImageBytes >> 20) +
                       " MiB of RGBA8 together, the limit");
    image->width = decoded.width;
    image->height = decoded.height;
    image->component = 4;
    image->bits = 8;
    image->pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
    image->image = std::move(decoded.rgba);
    return true;
  } catch (const ImageCodecUnavailable& e) {
    budget.codec_error = e.what();
    return false;
  } catch (const InputError& e) {
    if (err) *err += e.what();
    return false;
  }
}

// External buffers and images go through core/input_file.h like every input: a URI naming a
// FIFO, a device, a loop or a huge file is refused with what it is. Names are taken as written
// (no ~ or $VAR expansion), and "exists" means "names something", so the reader says what.
bool external_file_exists(const std::string& file, void*) { return input_path_exists(file); }
std::string external_file_path(const std::string& file, void*) { return file; }
// tinygltf takes an image it cannot read for a warning; the first refusal is kept here so the
// model is refused with it, buffer or image.
bool read_external_file(std::vector<unsigned char>* out, std::string* err, const std::string& file, void* user) {
  try {
    const std::string bytes = read_input_file(file, kMaxModelFileBytes, "an external glTF buffer or image");
    out->assign(bytes.begin(), bytes.end());
    return true;
  } catch (const InputError& e) {
    std::string& refused = *static_cast<std::string*>(user);
    if (refused.empty()) refused = std::string("external file ") + e.what();
    if (err) *err += std::string("external file ") + e.what();
    return false;
  }
}

size_t component_size(int type) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;
  }
}

size_t component_count(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    case TINYGLTF_TYPE_MAT2: return 4;
    case TINYGLTF_TYPE_MAT3: return 9;
    case TINYGLTF_TYPE_MAT4: return 16;
    default: return 0;
  }
}

// A checked window onto one accessor's bytes: element i starts at base + i*stride.
struct AccessorView {
  const uint8_t* base = nullptr;
  size_t stride = 0;
  size_t count = 0;
  int component_type = 0;
  size_t components = 0;
  bool normalized = false;

  double component(size_t i, size_t c) const {
    const uint8_t* p = base + i * stride + c * component_size(component_type);
    switch (component_type) {
      case TINYGLTF_COMPONENT_TYPE_BYTE: { int8_t v; std::memcpy(&v, p, 1); return normalized ? std::fmax(v / 127.0, -1.0) : v; }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? *p / 255.0 : *p;
      case TINYGLTF_COMPONENT_TYPE_SHORT: { int16_t v; std::memcpy(&v, p, 2); return normalized ? std::fmax(v / 32767.0, -1.0) : v; }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: { uint16_t v; std::memcpy(&v, p, 2); return normalized ? v / 65535.0 : v; }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: { uint32_t v; std::memcpy(&v, p, 4); return v; }
      default: { float v; std::memcpy(&v, p, 4); return v; }
    }
  }
  uint32_t index(size_t i) const {
    const uint8_t* p = base + i * stride;
    switch (component_type) {
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return *p;
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: { uint16_t v; std::memcpy(&v, p, 2); return v; }
      default: { uint32_t v; std::memcpy(&v, p, 4); return v; }
    }
  }
};

class GltfReader {
 public:
  GltfReader(std::string path, const tinygltf::Model& gltf) : path_(std::move(path)), gltf_(gltf) {}

  ModelData read() {
    ModelData out;
    out.path = path_;
    read_images(out);
    read_materials(out);
    for (int root : scene_roots()) visit_node(out, root, glm::dmat4(1.0), 0);
    if (out.primitives.empty()) fail("the default scene contains no triangle meshes");
    compute_bounds(out);
    return out;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const { throw InputError(path_ + ": " + what); }

  template <typename T>
  void check_index(int index, const std::vector<T>& list, const std::string& what) const {
    if (index < 0 || size_t(index) >= list.size())
      fail(what + " " + std::to_string(index) + " does not exist (the file has " + std::to_string(list.size()) + ")");
  }

  std::vector<int> scene_roots() const {
    if (!gltf_.scenes.empty()) {
      const int scene = gltf_.defaultScene >= 0 ? gltf_.defaultScene : 0;
      check_index(scene, gltf_.scenes, "default scene");
      return gltf_.scenes[size_t(scene)].nodes;
    }
    // Without scenes every node that is nobody's child is a root.
    std::vector<bool> is_child(gltf_.nodes.size(), false);
    for (const auto& n : gltf_.nodes)
      for (int c : n.children)
        if (c >= 0 && size_t(c) < is_child.size()) is_child[size_t(c)] = true;
    std::vector<int> roots;
    for (size_t i = 0; i < is_child.size(); ++i)
      if (!is_child[i]) roots.push_back(int(i));
    return roots;
  }

  static std::string node_label(const tinygltf::Node& node, int index) {
    return "node " + std::to_string(index) + (node.name.empty() ? std::string() : " '" + node.name + "'");
  }

  glm::dmat4 local_transform(const tinygltf::Node& node, int index) const {
    const std::string what = node_label(node, index);
    if (!node.matrix.empty()) {
      if (node.matrix.size() != 16) fail(what + ": 'matrix' must have 16 numbers");
      for (double v : node.matrix)
        if (!std::isfinite(v)) fail(what + ": 'matrix' contains NaN or infinity");
      return glm::make_mat4(node.matrix.data());  // glTF matrices are column-major, as glm's
    }
    glm::dmat4 m(1.0);
    if (!node.translation.empty()) {
      if (node.translation.size() != 3) fail(what + ": 'translation' must have 3 numbers");
      m[3] = glm::dvec4(node.translation[0], node.translation[1], node.translation[2], 1.0);
    }
    if (!node.rotation.empty()) {
      if (node.rotation.size() != 4) fail(what + ": 'rotation' must be a quaternion of 4 numbers (x, y, z, w)");
      glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
      const double len = glm::length(q);
      if (!(len > 1e-12) || !std::isfinite(len)) fail(what + ": 'rotation' must be a non-zero finite quaternion");
      m = m * glm::mat4_cast(q / len);
    }
    if (!node.scale.empty()) {
      if (node.scale.size() != 3) fail(what + ": 'scale' must have 3 numbers");
      m = m * glm::dmat4(glm::dvec4(node.scale[0], 0, 0, 0), glm::dvec4(0, node.scale[1], 0, 0),
                         glm::dvec4(0, 0, node.scale[2], 0), glm::dvec4(0, 0, 0, 1));
    }
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r)
        if (!std::isfinite(m[c][r])) fail(what + ": transform contains NaN or infinity");
    return m;
  }

  void visit_node(ModelData& out, int index, const glm::dmat4& parent, int depth) {
    check_index(index, gltf_.nodes, "node");
    if (depth > kMaxNodeDepth) fail("node hierarchy deeper than " + std::to_string(kMaxNodeDepth) + " levels (a cycle?)");
    if (on_path_.count(index)) fail("node " + std::to_string(index) + " is its own ancestor (cycle in 'children')");
    // glTF gives a node one parent; a node shared by several would multiply the work with each level.
    if (!visited_.insert(index).second)
      fail("node " + std::to_string(index) + " is reached twice (a node may have only one parent and appear once in a scene)");
    on_path_.insert(index);
    const tinygltf::Node& node = gltf_.nodes[size_t(index)];
    const glm::dmat4 world = parent * local_transform(node, index);
    check_world(node, index, world);
    if (node.mesh >= 0) {
      check_index(node.mesh, gltf_.meshes, "mesh");
      const auto& mesh = gltf_.meshes[size_t(node.mesh)];
      for (size_t p = 0; p < mesh.primitives.size(); ++p) {
        out.primitives.push_back(read_primitive(mesh.primitives[p], node.mesh, int(p), world, out));
        check_gltf_placed_vertices(out.primitives.back().positions, path_ + ": " + node_label(node, index) + ": mesh " +
                                                                        std::to_string(node.mesh) + " primitive " + std::to_string(p));
        count_output(out.primitives.back());
      }
    }
    for (int child : node.children) visit_node(out, child, world, depth + 1);
    on_path_.erase(index);
  }

  void check_world(const tinygltf::Node& node, int index, const glm::dmat4& world) const {
    const char* what = !node.matrix.empty() ? "matrix" : !node.scale.empty() ? "scale" : !node.translation.empty() ? "translation" : "rotation";
    check_gltf_world_transform(world, path_ + ": " + node_label(node, index) + ": " + what);
  }

  // Meshes placed by several nodes are copied once per node: bound the model as it is built.
  void count_output(const MeshPrimitive& prim) {
    vertices_ += prim.positions.size();
    indices_ += prim.indices.size();
    if (vertices_ > kMaxModelVertices || indices_ > kMaxModelIndices)
      fail("the model has more than " + std::to_string(kMaxModelVertices) + " vertices or " + std::to_string(kMaxModelIndices) +
           " indices after placing every node's mesh, the limit");
  }

  AccessorView view_accessor(int index, const std::string& what) const {
    check_index(index, gltf_.accessors, what + " accessor");
    const auto& acc = gltf_.accessors[size_t(index)];
    const std::string name = what + " accessor " + std::to_string(index);
    if (acc.sparse.isSparse) fail(name + ": sparse accessors are not supported");
    if (acc.bufferView < 0) fail(name + ": has no bufferView");
    check_index(acc.bufferView, gltf_.bufferViews, name + ": bufferView");
    const auto& bv = gltf_.bufferViews[size_t(acc.bufferView)];
    check_index(bv.buffer, gltf_.buffers, "bufferView " + std::to_string(acc.bufferView) + ": buffer");
    const auto& buffer = gltf_.buffers[size_t(bv.buffer)];
    const uint64_t buffer_size = buffer.data.size();
    if (uint64_t(bv.byteOffset) > buffer_size || uint64_t(bv.byteLength) > buffer_size - bv.byteOffset)
      fail("bufferView " + std::to_string(acc.bufferView) + " (bytes " + std::to_string(bv.byteOffset) + " + " +
           std::to_string(bv.byteLength) + ") exceeds buffer " + std::to_string(bv.buffer) + " of " +
           std::to_string(buffer_size) + " bytes");
    AccessorView v;
    v.component_type = acc.componentType;
    v.components = component_count(acc.type);
    v.normalized = acc.normalized;
    v.count = acc.count;
    if (v.count == 0) fail(name + ": count is 0; allowed: at least 1 element (glTF accessors are never empty)");
    const size_t csize = component_size(acc.componentType);
    if (csize == 0 || v.components == 0) fail(name + ": unknown componentType or type");
    const uint64_t element = csize * v.components;
    v.stride = bv.byteStride ? bv.byteStride : element;
    if (v.stride < element) fail(name + ": byteStride " + std::to_string(v.stride) + " is smaller than one element");
    const uint64_t view_len = bv.byteLength;
    // count is bounded by the view length first, so the product below cannot overflow.
    if (v.count > view_len || uint64_t(acc.byteOffset) > view_len ||
        (v.count - 1) * v.stride + element > view_len - acc.byteOffset)
      fail(name + " (offset " + std::to_string(acc.byteOffset) + ", " + std::to_string(v.count) + " elements of " +
           std::to_string(element) + " bytes, stride " + std::to_string(v.stride) + ") exceeds bufferView " +
           std::to_string(acc.bufferView) + " of " + std::to_string(view_len) + " bytes");
    v.base = buffer.data.data() + bv.byteOffset + acc.byteOffset;
    return v;
  }

  std::vector<glm::vec3> read_vec3(int accessor, const std::string& what) const {
    AccessorView v = view_accessor(accessor, what);
    if (v.components != 3 || v.component_type != TINYGLTF_COMPONENT_TYPE_FLOAT)
      fail(what + " accessor " + std::to_string(accessor) + " must be VEC3 of FLOAT");
    std::vector<glm::vec3> out(v.count);
    for (size_t i = 0; i < v.count; ++i) {
      out[i] = glm::vec3(float(v.component(i, 0)), float(v.component(i, 1)), float(v.component(i, 2)));
      if (!std::isfinite(out[i].x) || !std::isfinite(out[i].y) || !std::isfinite(out[i].z))
        fail(what + " accessor " + std::to_string(accessor) + " contains NaN or infinity");
    }
    return out;
  }

  std::vector<glm::vec2> read_uvs(int accessor, const std::string& what) const {
    AccessorView v = view_accessor(accessor, what);
    const bool ok_type = v.component_type == TINYGLTF_COMPONENT_TYPE_FLOAT ||
                         (v.normalized && (v.component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                           v.component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT));
    if (v.components != 2 || !ok_type)
      fail(what + " accessor " + std::to_string(accessor) + " must be VEC2 of FLOAT or normalized UNSIGNED_BYTE/SHORT");
    std::vector<glm::vec2> out(v.count);
    for (size_t i = 0; i < v.count; ++i) {
      out[i] = glm::vec2(float(v.component(i, 0)), float(v.component(i, 1)));
      if (!std::isfinite(out[i].x) || !std::isfinite(out[i].y))
        fail(what + " accessor " + std::to_string(accessor) + " contains NaN or infinity");
    }
    return out;
  }

  MeshPrimitive read_primitive(const tinygltf::Primitive& prim, int mesh, int p, const glm::dmat4& world,
                               const ModelData& model) const {
    const std::string name = "mesh " + std::to_string(mesh) + " primitive " + std::to_string(p);
    if (prim.mode != -1 && prim.mode != TINYGLTF_MODE_TRIANGLES)
      fail(name + ": primitive mode " + std::to_string(prim.mode) + " is not supported (only 4, triangles)");
    if (!prim.targets.empty()) fail(name + ": morph targets are not supported");
    MeshPrimitive out;
    auto pos = prim.attributes.find("POSITION");
    if (pos == prim.attributes.end()) fail(name + ": has no POSITION attribute");
    out.positions = read_vec3(pos->second, name + ": POSITION");
    const size_t n = out.positions.size();
    if (auto it = prim.attributes.find("NORMAL"); it != prim.attributes.end()) {
      out.normals = read_vec3(it->second, name + ": NORMAL");
      if (out.normals.size() != n) fail(name + ": NORMAL count differs from POSITION count");
    }
    if (auto it = prim.attributes.find("TEXCOORD_0"); it != prim.attributes.end()) {
      out.uvs = read_uvs(it->second, name + ": TEXCOORD_0");
      if (out.uvs.size() != n) fail(name + ": TEXCOORD_0 count differs from POSITION count");
    }
    if (prim.indices >= 0) {
      AccessorView v = view_accessor(prim.indices, name + ": indices");
      const bool int_type = v.component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                            v.component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
                            v.component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
      if (v.components != 1 || !int_type)
        fail(name + ": indices must be SCALAR of UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT");
      out.indices.resize(v.count);
      for (size_t i = 0; i < v.count; ++i) {
        out.indices[i] = v.index(i);
        if (out.indices[i] >= n)
          fail(name + ": index " + std::to_string(out.indices[i]) + " at position " + std::to_string(i) +
               " is out of range (the primitive has " + std::to_string(n) + " vertices)");
      }
    } else {
      out.indices.resize(n);
      for (size_t i = 0; i < n; ++i) out.indices[i] = uint32_t(i);
    }
    if (out.indices.size() % 3 != 0)
      fail(name + ": " + std::to_string(out.indices.size()) + " indices is not a whole number of triangles");
    if (prim.material >= 0) check_index(prim.material, model.materials, name + ": material");
    out.material = prim.material;
    if (out.normals.empty()) make_flat(out);
    apply_transform(out, world);
    return out;
  }

  // Files without normals get faceted ones: every triangle gets its own three vertices.
  static void make_flat(MeshPrimitive& prim) {
    MeshPrimitive flat;
    flat.material = prim.material;
    const size_t count = prim.indices.size();
    flat.positions.reserve(count);
    flat.normals.reserve(count);
    for (size_t t = 0; t + 2 < count; t += 3) {
      const glm::vec3 a = prim.positions[prim.indices[t]], b = prim.positions[prim.indices[t + 1]],
                      c = prim.positions[prim.indices[t + 2]];
      glm::vec3 nrm = glm::cross(b - a, c - a);
      const float len = glm::length(nrm);
      nrm = len > 0.0f ? nrm / len : glm::vec3(0.0f, 1.0f, 0.0f);
      for (int k = 0; k < 3; ++k) {
        const uint32_t src = prim.indices[t + size_t(k)];
        flat.positions.push_back(prim.positions[src]);
        flat.normals.push_back(nrm);
        if (!prim.uvs.empty()) flat.uvs.push_back(prim.uvs[src]);
        flat.indices.push_back(uint32_t(t + size_t(k)));
      }
    }
    prim = std::move(flat);
  }

  static void apply_transform(MeshPrimitive& prim, const glm::dmat4& world) {
    const glm::dmat3 linear(world);
    const glm::dmat3 normal_matrix = glm::transpose(glm::inverse(linear));
    for (auto& p : prim.positions) p = glm::vec3(world * glm::dvec4(glm::dvec3(p), 1.0));
    for (auto& nrm : prim.normals) {
      glm::dvec3 t = normal_matrix * glm::dvec3(nrm);
      const double len = glm::length(t);
      nrm = len > 1e-30 && std::isfinite(len) ? glm::vec3(t / len) : glm::vec3(0.0f, 1.0f, 0.0f);
    }
    // A mirroring transform turns front faces into back faces unless the winding flips too.
    if (glm::determinant(linear) < 0.0)
      for (size_t t = 0; t + 2 < prim.indices.size(); t += 3) std::swap(prim.indices[t + 1], prim.indices[t + 2]);
  }

  int texture_image(int texture, const std::string& what) const {
    if (texture < 0) return -1;
    check_index(texture, gltf_.textures, what + " texture");
    const int source = gltf_.textures[size_t(texture)].source;
    if (source < 0) fail(what + " texture " + std::to_string(texture) + " has no image source");
    check_index(source, gltf_.images, what + " texture " + std::to_string(texture) + ": image");
    return source;
  }

  void read_materials(ModelData& out) const {
    for (size_t i = 0; i < gltf_.materials.size(); ++i) {
      const auto& m = gltf_.materials[i];
      const std::string name = "material " + std::to_string(i);
      Material mat;
      const auto& bc = m.pbrMetallicRoughness.baseColorFactor;
      if (bc.size() != 4) fail(name + ": baseColorFactor must have 4 numbers");
      mat.base_color = glm::vec4(float(bc[0]), float(bc[1]), float(bc[2]), float(bc[3]));
      if (m.emissiveFactor.size() != 3) fail(name + ": emissiveFactor must have 3 numbers");
      mat.emissive = glm::vec3(float(m.emissiveFactor[0]), float(m.emissiveFactor[1]), float(m.emissiveFactor[2]));
      mat.metallic = float(m.pbrMetallicRoughness.metallicFactor);
      mat.roughness = float(m.pbrMetallicRoughness.roughnessFactor);
      if (!(mat.metallic >= 0.0f && mat.metallic <= 1.0f && mat.roughness >= 0.0f && mat.roughness <= 1.0f))
        fail(name + ": metallicFactor and roughnessFactor must be numbers in [0, 1]");
      if (auto ext = m.extensions.find("KHR_materials_emissive_strength"); ext != m.extensions.end()) {
        const auto& strength = ext->second.Get("emissiveStrength");
        if (strength.IsNumber()) mat.emissive *= float(strength.GetNumberAsDouble());
      }
      for (float v : {mat.base_color.r, mat.base_color.g, mat.base_color.b, mat.base_color.a, mat.emissive.r,
                      mat.emissive.g, mat.emissive.b})
        if (!std::isfinite(v) || v < 0.0f) fail(name + ": colour factors must be finite and non-negative");
      // Regions painted in the team colour of the ship that wears the model (tools/assetgen).
      if (m.extras.Has("arcfire_team_color")) {
        const auto& team = m.extras.Get("arcfire_team_color");
        if (!team.IsNumber() || !(team.GetNumberAsDouble() >= 0.0 && team.GetNumberAsDouble() <= 1.0))
          fail(name + ": extras.arcfire_team_color must be a number in [0, 1]");
        mat.team_color = float(team.GetNumberAsDouble());
      }
      mat.base_color_image = texture_image(m.pbrMetallicRoughness.baseColorTexture.index, name + ": base colour");
      mat.emissive_image = texture_image(m.emissiveTexture.index, name + ": emissive");
      out.materials.push_back(mat);
    }
  }

  void read_images(ModelData& out) const {
    for (size_t i = 0; i < gltf_.images.size(); ++i) {
      const auto& src = gltf_.images[i];
      if (src.width <= 0 || src.height <= 0 || src.component != 4 || src.bits != 8 ||
          src.image.size() != size_t(src.width) * size_t(src.height) * 4)
        fail("image " + std::to_string(i) + " could not be decoded");
      Image img;
      img.width = src.width;
      img.height = src.height;
      img.rgba = src.image;
      out.images.push_back(std::move(img));
    }
  }

  static void compute_bounds(ModelData& out) {
    bool first = true;
    float r2 = 0.0f;
    for (const auto& prim : out.primitives)
      for (const auto& p : prim.positions) {
        out.bounds_min = first ? p : glm::min(out.bounds_min, p);
        out.bounds_max = first ? p : glm::max(out.bounds_max, p);
        first = false;
        r2 = std::fmax(r2, glm::dot(p, p));
      }
    out.radius = std::sqrt(r2);
  }

  std::string path_;
  const tinygltf::Model& gltf_;
  std::set<int> on_path_;
  std::set<int> visited_;
  size_t vertices_ = 0, indices_ = 0;
};

}  // namespace

ModelData load_model(const std::string& path) {
  return parse_model(read_input_file(path, kMaxModelFileBytes, "a glTF model"), path);
}

ModelData parse_model(const std::string& bytes, const std::string& path) {
  check_text_size(bytes.size(), path, kMaxModelFileBytes, "a glTF model");
  const std::string ext = std::filesystem::path(path).extension().string();
  const bool binary = bytes.compare(0, 4, "glTF") == 0 || ext == ".glb" || ext == ".GLB";
  if (binary) {
    validate_glb_container(path, bytes);
    check_json_text(bytes.data() + 20, read_u32(bytes, 12), path + " (JSON chunk)", kModelJsonLimits);
    check_gltf_claims(bytes.data() + 20, read_u32(bytes, 12), path);
  } else {
    check_json_text(bytes, path, kModelJsonLimits);
    check_gltf_claims(bytes.data(), bytes.size(), path);
  }

  tinygltf::TinyGLTF loader;
  ImageBudget budget{path, 0, {}};
  loader.SetImageLoader(&decode_gltf_image, &budget);
  std::string refused;
  tinygltf::FsCallbacks fs{&external_file_exists, &external_file_path, &read_external_file, &tinygltf::WriteWholeFile, &refused};
  loader.SetFsCallbacks(fs);
  tinygltf::Model gltf;
  std::string err, warn;
  const std::string base_dir = std::filesystem::path(path).parent_path().string();
  const bool ok = binary ? loader.LoadBinaryFromMemory(&gltf, &err, &warn, reinterpret_cast<const unsigned char*>(bytes.data()),
                                                       unsigned(bytes.size()), base_dir)
                         : loader.LoadASCIIFromString(&gltf, &err, &warn, bytes.data(), unsigned(bytes.size()), base_dir);
  if (!budget.codec_error.empty()) throw ImageCodecUnavailable(budget.codec_error);
  if (!refused.empty()) throw InputError(path + ": " + refused);
  if (!ok) {
    while (!err.empty() && (err.back() == '\n' || err.back() == '\r')) err.pop_back();
    for (char& c : err)
      if (c == '\n' || c == '\r') c = ' ';
    throw InputError(path + ": invalid glTF: " + (err.empty() ? std::string("unknown error") : err));
  }
  return GltfReader(path, gltf).read();
}

}  // namespace arc
