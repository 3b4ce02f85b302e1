// Vertex processing as Mesa's fixed-function vertex program computes it on
// llvmpipe (ffvertex_prog.c): position, normal, lighting, fog coordinate.
#include "pipeline/draw/vertex_processing.hpp"

#include <algorithm>
#include <cmath>

#include "pipeline/draw/mesa_matrix_inverse.hpp"
#include "raster/llvmpipe_math.hpp"
#include "util/check.hpp"
#include "util/cpu_dispatch.hpp"

namespace mpr {
namespace {

// glm::clamp(c, 0, 1) written out per component (glm's min and max are
// std::min and std::max, NaN kept alike); glm's generic form is not inlined.
[[gnu::always_inline]] inline Vec4 clampColor(const Vec4& c) {
  auto clamp01 = [](float v) { return std::min(std::max(v, 0.0f), 1.0f); };
  return Vec4(clamp01(c.x), clamp01(c.y), clamp01(c.z), clamp01(c.w));
}

}  // namespace

MPR_CPU_CLONES ClipVertex processVertex(const VertexSnapshot& snap, const CapturedVertex& v, LightingState& s) {
  ClipVertex out;
  // Position through the combined matrix, as Mesa's fixed-function program
  // computes it on llvmpipe (measured against llvmpipe's depths).
  const Vec4& o = v.object;
  out.clip = mesaTransformPoint(snap.mvp, o);
  const bool needEye = snap.lighting || snap.fog.enabled;
  // The eye position as the program's get_eye_position computes it.
  const Mat4& mv = snap.modelview;
  const Vec4 eye = needEye ? mesaTransformPoint(mv, o) : Vec4(0.0f);

  Vec4 front, back;
  if (snap.lighting) {
    MPR_DCHECK_LT(v.material, snap.materials.size());
    s.material = snap.materials[v.material];
    if (snap.colorTracksMaterial) {
      // The vertex's own colour feeds the tracked material parameter where
      // the colour varies in the draw (a glColor since the vbo's format was
      // last reset); otherwise Mesa's fixed-function program reads the
      // material state, which enabling GL_COLOR_MATERIAL set from the
      // colour and a held glMaterial may have set back (copyToCurrent).
      const Vec4 c = v.color;
      for (int side = 0; side < 2; ++side) {
        if ((side == 0 && snap.colorMaterialFaces == MaterialFaces::Back) ||
            (side == 1 && snap.colorMaterialFaces == MaterialFaces::Front))
          continue;
        Material& m = s.material[side];
        switch (snap.colorMaterialParam) {
          case ColorMaterialParam::Emission: m.emission = c; break;
          case ColorMaterialParam::Ambient: m.ambient = c; break;
          case ColorMaterialParam::Diffuse: m.diffuse = c; break;
          case ColorMaterialParam::Specular: m.specular = c; break;
          case ColorMaterialParam::AmbientAndDiffuse: m.ambient = m.diffuse = c; break;
        }
      }
    }
    // emit_matrix_transform_vec3: component i is DP3(normal, row i of the
    // normal matrix).
    // In object space (LightingState::objectSpace) the program takes the
    // normal as given (times the normal scale, 1 for a length-preserving
    // modelview).
    const glm::mat3 rows = glm::transpose(snap.normalMatrix);
    Vec3 n = s.objectSpace ? v.normal
                           : Vec3(llvmpipeDot3(v.normal, rows[0]), llvmpipeDot3(v.normal, rows[1]),
                                  llvmpipeDot3(v.normal, rows[2]));
    if (snap.normalize) {
      // emit_normalize_vec3: DP3, RSQ (a square root and a division), MUL.
      const float lengthSquared = llvmpipeDot3(n, n);
      if (lengthSquared > 0.0f) n = n * (1.0f / std::sqrt(lengthSquared));
    }
    const Vec4 lit = snap.lightingUndividedEye ? Vec4(Vec3(eye), 1.0f) : eye;
    front = lightVertex(s, lit, n, false);
    back = snap.twoSide ? lightVertex(s, lit, n, true) : front;
  } else {
    front = back = clampColor(v.color);
  }
  for (int i = 0; i < 4; ++i) {
    out.attr[i] = front[i];
    out.attr[4 + i] = back[i];
  }
  // Fog coordinate: the eye-space distance |z_eye| (build_fog,
  // FDM_EYE_PLANE_ABS): the z of the eye position where the lighting code
  // computed it (a positional light, or a local viewer with a shininess
  // active), else its own DP4 of the modelview's third row, summed from the
  // last channel (nir_lower_alu_to_scalar).
  bool eyeComputed = false;
  if (snap.lighting) {
    for (const LightSource& l : s.lights) eyeComputed = eyeComputed || (l.enabled && l.position.w != 0.0f);
    eyeComputed = eyeComputed || (s.model.localViewer && !s.shininessKeyZero);
  }
  const float eyeZ = eyeComputed ? eye.z : ((mv[3][2] * o.w + mv[2][2] * o.z) + mv[1][2] * o.y) + mv[0][2] * o.x;
  const float fogCoord = std::fabs(eyeZ);
  out.attr[8] = snap.fog.enabled && !snap.fog.perFragment ? fogFactor(snap.fog, fogCoord) : fogCoord;
  return out;
}

}  // namespace mpr
