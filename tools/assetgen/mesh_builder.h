// tools/assetgen/mesh_builder.h — low-poly, flat-shaded meshes from lofted cross-sections.
//
// A Solid is a closed triangle soup tagged with material slots. loft() joins rings of equal
// point count (a ring may collapse to one point for a nose or tip) and caps both ends;
// outward() flips a closed solid whose signed volume is negative, so ring order never matters.
// MeshBuilder collects solids and writes a .glb with one primitive per used material.
//
//   Solid hull = loft({ring_z(-7, 0.01, 0.01, 8), ring_z(0, 1, 0.8, 8)}, {kHull}, kTrim, kTrim);
//   MeshBuilder mb; mb.add(hull); mb.add(mirror_x(wing));
//   mb.set_detail_texture(png_bytes, 6.0);   // optional: panel lines on materials marked `detail`
//   mb.write_glb("assets/models/viper.glb", "viper", materials);
#pragma once
#include <string>
#include <vector>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace arc::assetgen {

using Ring = std::vector<glm::dvec3>;

struct Tri {
  int material;
  glm::dvec3 a, b, c;
};

struct Solid {
  std::vector<Tri> tris;
};

struct MaterialDef {
  std::string name;
  glm::vec4 base_color{1.0f};
  glm::vec3 emissive{0.0f};
  float metallic = 0.0f;
  float roughness = 0.8f;
  float team_color = 0.0f;  // > 0: written as extras.arcfire_team_color (assets/model.h)
  bool detail = false;      // multiplied by the model's detail texture (MeshBuilder::set_detail_texture)
};

// A ring in the plane z = const: a superellipse of half-width w, half-height h around (cx, cy).
// Exponent 2 gives an ellipse, larger values a boxier, chined section.
Ring ring_z(double z, double w, double h, int sides, double cx = 0.0, double cy = 0.0, double exponent = 2.0);
// A thin wing section in the plane x = const: leading edge at z_le, chord along +Z.
Ring wing_section(double x, double y, double z_le, double chord, double thickness);
// A round ring in the plane z = const (engine nacelles, barrels).
Ring circle_z(double z, double r, int sides, double cx, double cy);

// segment_materials[i] is used between rings i and i+1 (the last entry repeats if short).
Solid loft(const std::vector<Ring>& rings, const std::vector<int>& segment_materials, int start_cap, int end_cap);
Solid box(glm::dvec3 lo, glm::dvec3 hi, int material);
Solid outward(Solid s);
Solid mirror_x(const Solid& s);
Solid translated(const Solid& s, glm::dvec3 offset);

class MeshBuilder {
 public:
  void add(const Solid& s);
  void add_tri(int material, glm::dvec3 a, glm::dvec3 b, glm::dvec3 c);
  size_t triangle_count() const { return tris_.size(); }
  // A tiling detail texture (PNG bytes, sRGB colour) embedded in the .glb as the base colour
  // texture of every material marked `detail`; UVs are a box projection of each triangle onto
  // the plane its normal faces most, `metres_per_tile` metres to one repeat.
  void set_detail_texture(std::string png_bytes, double metres_per_tile);
  // Flat normals: every triangle gets its own three vertices. Written atomically.
  void write_glb(const std::string& path, const std::string& name, const std::vector<MaterialDef>& materials) const;

 private:
  std::vector<Tri> tris_;
  std::string detail_png_;
  double metres_per_tile_ = 1.0;
};

}  // namespace arc::assetgen
