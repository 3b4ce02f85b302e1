#pragma once
// Vertex processing (GL 1.1 sections 2.10-2.13, as Mesa's fixed-function
// vertex program computes it on llvmpipe): a captured vertex to clip
// coordinates, its front and back colours (lit, or its own clamped) and its
// fog coordinate. Reads the GL state only through a VertexSnapshot, frozen
// for each piece of a glBegin/glEnd block that Mesa's vbo draws.
#include <array>
#include <cstdint>
#include <span>

#include "pipeline/draw/lighting.hpp"
#include "raster/clip_vertex.hpp"
#include "raster/fog.hpp"
#include "util/vecmath.hpp"

namespace mpr {

// What glVertex captures, processed at glEnd.
struct CapturedVertex {
  Vec4 object;
  Vec4 color;
  Vec3 normal;
  std::uint32_t material;  // index into VertexSnapshot::materials: the materials in force at this vertex
};
static_assert(sizeof(CapturedVertex) == 12 * sizeof(float), "no padding: RecentResults compares its bytes");

// glColorMaterial's face and parameter.
enum class MaterialFaces : std::uint8_t { Front, Back, FrontAndBack };
enum class ColorMaterialParam : std::uint8_t { Emission, Ambient, Diffuse, Specular, AmbientAndDiffuse };

struct VertexSnapshot {
  Mat4 mvp;                 // projection times modelview, as Mesa multiplies them
  Mat4 modelview;
  glm::mat3 normalMatrix;   // Mesa's (GLContext::deriveBlockState)
  bool lighting = false;
  bool normalize = false;   // GL_NORMALIZE
  bool twoSide = false;     // GL_LIGHT_MODEL_TWO_SIDE
  // The colour feeds the tracked material (GL_COLOR_MATERIAL on, and the
  // colour in the draw's vbo vertex format).
  bool colorTracksMaterial = false;
  MaterialFaces colorMaterialFaces = MaterialFaces::FrontAndBack;
  ColorMaterialParam colorMaterialParam = ColorMaterialParam::AmbientAndDiffuse;
  bool lightingUndividedEye = false;  // the kLightingUndividedEye departure
  FogState fog;
  // The materials in force at each glMaterial inside the block (GL 1.1
  // section 2.6.3); a vertex names its own. Not owned.
  std::span<const std::array<Material, 2>> materials;
};

// The vertex through transform and lighting; `lighting` is the draw's
// lighting state, whose materials the vertex replaces.
ClipVertex processVertex(const VertexSnapshot& s, const CapturedVertex& v, LightingState& lighting);

}  // namespace mpr
