// Figure 4 of Diefenbach & Badler 1994, routine by routine. The paper's
// pseudo-code is quoted in each pass label (after " | ") so the stepper and
// the trace show which line a pass runs.
//
// Decisions the paper leaves open (docs/explanation/draw-window.md):
// - Mirror depth: after draw_face marks a face's pixels with ZERO, those
//   pixels get depth = far and the clear colour (a quad at the far plane,
//   depth ALWAYS, under the stencil mask), so the virtual scene behind the
//   mirror can be drawn there; after the recursion the face is drawn again
//   with depth ALWAYS, which puts its own depth back for the faces drawn
//   after it, and blends its lit colour over the reflection through
//   destination alpha (the paper's "two additional renderings").
// - Virtual views clip at the face's plane (user clip plane 0) and flip the
//   winding (glFrontFace(GL_CW) under an odd number of reflections).
// - Lights are added one pass each, depth EQUAL, blend ONE ONE (1997 §7.2).
#include "algorithms/draw_window.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "algorithms/apply_stencil.hpp"
#include "algorithms/image_samples.hpp"
#include "algorithms/ref_face.hpp"
#include "algorithms/ref_light.hpp"
#include "algorithms/refraction.hpp"
#include "algorithms/scene_gl.hpp"
#include "algorithms/shadow_pass.hpp"
#include "algorithms/view_camera.hpp"

namespace mpr {
namespace {

class WindowRenderer {
 public:
  WindowRenderer(const Scene& s, const RenderPlan& p, GLCommandStream& gl,
                 const std::function<void(const DrawWindowProgress&)>& progress, const ViewSample& sample,
                 const ShadowPass* pivotBase)
      : s_(s), plan_(p), gl_(gl), lv_(p.levels), progress_(progress), faces_(findRefFaces(s)),
        faceTriangles_(faces_.size()),
        shadows_(pivotBase ? ShadowPass(s, *pivotBase) : ShadowPass(s, p)), gl_scene_(s, gl, p.usesStencil()) {
    gl_scene_.setViewSample(sample);
    image_ = sample.image;
    if (p.reflectedLights > 0) refLights_ = reflectedLights(s, faces_, image_);
    counts_.viewsAtLevel.assign(static_cast<std::size_t>(p.recursionDepth) + 1, 0);
  }

  DrawWindowCounts run() {
    path_ = {};
    pass("clear", "clear | clear every buffer");
    gl_.disable(GL_DITHER);
    gl_.clearColor(0.0f, 0.0f, 0.0f, 1.0f);
    gl_.clearDepth(1.0);
    gl_.clearStencil(0);
    gl_.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    gl_.viewport(0, 0, s_.render.width, s_.render.height);
    if (usesStencil()) gl_.enable(GL_STENCIL_TEST);
    draw_window(ViewCamera{});
    gl_.disable(GL_BLEND);
    if (usesStencil()) gl_.disable(GL_STENCIL_TEST);
    if (plan_.reflections) {
      gl_.disable(GL_CLIP_PLANE0);
      gl_.frontFace(GL_CCW);
    }
    gl_.depthMask(GL_TRUE);
    gl_.depthFunc(GL_LESS);
    gl_.endPasses();
    counts_.warnings.insert(counts_.warnings.begin(), shadows_.warnings().begin(), shadows_.warnings().end());
    return counts_;
  }

 private:
  bool usesStencil() const { return plan_.usesStencil(); }

  // Starts a pass labelled with the routine path and the pseudo-code line.
  void pass(const std::string& kind, const std::string& what) {
    std::string label;
    for (const std::string& p : path_) label += p + " > ";
    label += what;
    gl_.pass(kind, label);
  }

  // Every view, lit pass and shadow pass is reported as it starts, so that
  // --max-passes can stop a render at any of them (cli/scene_limits).
  void reportProgress() {
    if (progress_)
      progress_({counts_.views, counts_.views + counts_.lightPasses + counts_.shadowPasses,
                 "view " + std::to_string(counts_.views)});
  }

  // ---- drawwindow(Camera) -------------------------------------------------
  void draw_window(const ViewCamera& cam) {
    ++counts_.views;
    ++counts_.viewsAtLevel[static_cast<std::size_t>(cam.level)];
    reportProgress();
    path_.push_back("draw_window level " + std::to_string(cam.level));
    const std::uint32_t zero = lv_.zero;
    const bool shadowsHere = plan_.shadows && cam.level <= plan_.shadowDepth;

    pass("ambient", "ambient | draw_normal_objects(Camera, ZERO)  // ambient only");
    draw_normal_objects(cam, zero, nullptr);
    for (int light = 0; light < static_cast<int>(s_.lights.size()); ++light) {
      path_.push_back("light " + std::to_string(light));
      if (shadowsHere) {
        pass("apply_stencil", "render area to SHAD_ZERO | apply_stencil(EQUAL, ZERO, REPLACE, SHAD_ZERO)");
        apply_stencil(gl_, {PaperCompare::Equal, zero, PaperPass::Replace, lv_.shadZero}, lv_);
        if (draw_ref_shadows(cam, light)) {
          pass("apply_stencil", "after the ref shadows | apply_stencil(GREATER, SHAD_MIN, REPLACE, SHAD_ZERO)");
          apply_stencil(gl_, {PaperCompare::Greater, lv_.shadMin, PaperPass::Replace, lv_.shadZero}, lv_);
        }
        draw_all_shadows(cam, light);
        pass("apply_stencil", "back to ZERO | apply_stencil(GREATER, SHAD_MIN, REPLACE, ZERO)");
        apply_stencil(gl_, {PaperCompare::Greater, lv_.shadMin, PaperPass::Replace, zero}, lv_);
      } else {
        // No shadows in this view (past shadow_recursion_depth, or shadows
        // off): the light and its virtual lights added unshadowed, each
        // virtual light still only inside its light volume.
        if (hasVirtualLights(light)) {
          pass("apply_stencil", "render area to SHAD_ZERO | apply_stencil(EQUAL, ZERO, REPLACE, SHAD_ZERO)");
          apply_stencil(gl_, {PaperCompare::Equal, zero, PaperPass::Replace, lv_.shadZero}, lv_);
          draw_ref_shadows(cam, light, false);
          pass("apply_stencil", "back to ZERO | apply_stencil(GREATER, SHAD_MIN, REPLACE, ZERO)");
          apply_stencil(gl_, {PaperCompare::Greater, lv_.shadMin, PaperPass::Replace, zero}, lv_);
        }
        pass("light", "lit | draw_normal_objects(Camera, ZERO)  // light " + std::to_string(light) + " added");
        draw_normal_objects(cam, zero, &s_.lights[static_cast<std::size_t>(light)]);
      }
      path_.pop_back();
    }
    if (plan_.reflections && cam.level < plan_.recursionDepth) draw_ref_objects(cam, cam.level + 1);
    path_.pop_back();
  }

  // ---- draw_ref_shadows() ------------------------------------------------
  // For each ref face the light reaches beyond (a mirror lit from the front,
  // a refracting face below its critical angle; ref_light.hpp): its light
  // volume marks where the virtual light reaches (face_light_stencil: every shadow value
  // is raised by one, then the volume counted inverted, so inside the
  // volume holds SHAD_ZERO again), the virtual light's shadows are counted
  // (make_all_shadows(CAN'T_INTERSECT)), and the virtual light is added on
  // what remains at SHAD_ZERO. Returns whether anything was drawn.
  bool draw_ref_shadows(const ViewCamera& cam, int light, bool withShadows = true) {
    bool any = false;
    for (const ReflectedLight& rl : refLights_) {
      if (rl.light != light) continue;
      any = true;
      path_.push_back("draw_ref_shadows > " + pathText(rl));
      // A path of k faces: every shadow value raised by k, each constituent
      // light volume counted inverted; only inside all k is SHAD_ZERO again
      // (1997 §4.2, "stenciling each of the constituent light volumes").
      pass("light volume", rl.path.size() == 1 ? "light volume | face_light_stencil(ref_face)"
                                               : "light volume | face_light_stencil(every face of the light path)");
      for (std::size_t i = 0; i < rl.lightVolumes.size(); ++i)
        apply_to_screen(gl_, {GL_LEQUAL, lv_.shadMin, lv_.shadMin, lv_.max, GL_INCR});
      gl_scene_.setupView(cam);
      std::vector<const VolumeGeometry*> lightVolumes;
      for (const VolumeGeometry& v : rl.lightVolumes) lightVolumes.push_back(&v);
      countVolumes(gl_, lightVolumes, cam, s_.camera, gl_scene_.aspect(), lv_, true, true);
      if (withShadows) countRefShadows(cam, rl);
      pass("light", withShadows ? "lit by the virtual light | draw_normal_objects(Camera, SHAD_ZERO)"
                                : "lit by the virtual light, unshadowed | draw_normal_objects(Camera, SHAD_ZERO)");
      draw_normal_objects(cam, lv_.shadZero, &rl.virtualLight);
      pass("apply_stencil", "reset the counts | apply_stencil(GREATER, SHAD_MIN, REPLACE, SHAD_ZERO)");
      apply_stencil(gl_, {PaperCompare::Greater, lv_.shadMin, PaperPass::Replace, lv_.shadZero}, lv_);
      path_.pop_back();
    }
    return any;
  }

  bool hasVirtualLights(int light) const {
    for (const ReflectedLight& rl : refLights_)
      if (rl.light == light) return true;
    return false;
  }

  // The virtual light's shadows inside its light volume.
  void countRefShadows(const ViewCamera& cam, const ReflectedLight& rl) {
    pass("shadow volume",
         "virtual light's shadows | ref_light(light, ref_face); make_all_shadows(CAN'T_INTERSECT and MUST_INTERSECT, ref_face)");
    ++counts_.shadowPasses, reportProgress();
    std::vector<const VolumeGeometry*> vols;
    for (const VolumeGeometry& v : rl.shadows) vols.push_back(&v);
    counts_.zfailVolumes += countVolumes(gl_, vols, cam, s_.camera, gl_scene_.aspect(), lv_, false);
  }

  // The faces a virtual light's path passed: face N "name" > face M "name".
  std::string pathText(const ReflectedLight& rl) const {
    std::string t;
    for (const int f : rl.path)
      t += (t.empty() ? "face " : " > face ") + std::to_string(f) + " \"" +
           s_.objects[static_cast<std::size_t>(faces_[static_cast<std::size_t>(f)].object)].name + "\"";
    return t;
  }

  // ---- draw_all_shadows() -------------------------------------------------
  void draw_all_shadows(const ViewCamera& cam, int light) {
    path_.push_back("draw_all_shadows");
    pass("shadow volume", "shadow volumes | make_all_shadows(ALWAYS)");
    ++counts_.shadowPasses, reportProgress();
    gl_scene_.setupView(cam);
    counts_.zfailVolumes += shadows_.drawVolumes(gl_, light, cam, s_.camera, lv_);
    // More nested volumes than SHAD_ZERO..max can count saturate at max (INCR
    // clamps); find such pixels with a stencil-only pass the fragment counter
    // measures (an occlusion query's part) and report them.
    pass("shadow check", "count check | apply_stencil(EQUAL, max, KEEP, max)  // saturated counts?");
    gl_.beginFragmentCount();
    apply_stencil(gl_, {PaperCompare::Equal, lv_.max, PaperPass::Keep, lv_.max}, lv_);
    const std::uint64_t saturated = gl_.endFragmentCount();
    if (saturated > 0)
      counts_.warnings.push_back(std::to_string(saturated) + " pixels of view " + std::to_string(counts_.views) +
                                 ", light " + std::to_string(light) + " are inside " +
                                 std::to_string(lv_.maxShadowDepthAbove()) +
                                 " or more shadow volumes, as many as the stencil bits above SHAD_ZERO count: "
                                 "their shadow may be wrong");
    const PointLight& l = s_.lights[static_cast<std::size_t>(light)];
    const int levels = darknessLevelSamples(s_, l);
    if (levels > 1) {
      darkness_levels(cam, l, levels);
    } else {
      pass("light", "lit outside the shadows | draw_normal_objects(Camera, SHAD_ZERO)");
      draw_normal_objects(cam, lv_.shadZero, &l);
    }
    pass("apply_stencil", "reset the counts | apply_stencil(GREATER, SHAD_MIN, REPLACE, SHAD_ZERO)");
    apply_stencil(gl_, {PaperCompare::Greater, lv_.shadMin, PaperPass::Replace, lv_.shadZero}, lv_);
    path_.pop_back();
  }

  // ---- darkness levels (1994, "Soft shadows and caustics", second method) --
  // The S samples' volumes are counted (a pixel inside k of them holds
  // SHAD_ZERO + k); "the scene is redrawn with diffuse lighting for areas
  // whose stencil value is [at] the shadow zero value. All stencil values are
  // then decremented, and the image is redrawn ... for each darkness level,
  // accumulating each intermediate image": level j lights the pixels with
  // k <= j, so a pixel is lit in S - k of the S levels, (S - k) / S of the
  // light. The image so far is loaded into the accumulation buffer, each
  // level drawn alone on a cleared colour buffer and added with 1/S, the sum
  // returned; alpha (destination alpha of the faces) is masked throughout.
  // The light is drawn from its centre in every level: the images method
  // lights each sample from its own position (docs/explanation/accumulation-effects.md).
  void darkness_levels(const ViewCamera& cam, const PointLight& light, int levels) {
    const std::string n = std::to_string(levels);
    pass("accumulate", "darkness levels | glAccum(GL_LOAD, 1)  // the image so far");
    gl_.colorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
    gl_.accum(GL_LOAD, 1.0f);
    for (int j = 0; j < levels; ++j) {
      const std::string level = "level " + std::to_string(j) + " of " + n;
      pass("light", level + ": lit where inside at most " + std::to_string(j) +
                        " volumes | clear the colour; draw_normal_objects(Camera, SHAD_ZERO)");
      gl_.colorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);  // apply_to_screen turned all four on
      gl_.clear(GL_COLOR_BUFFER_BIT);
      draw_normal_objects(cam, lv_.shadZero, &light);
      pass("accumulate", level + " | glAccum(GL_ACCUM, 1/" + n + ")");
      gl_.accum(GL_ACCUM, 1.0f / static_cast<float>(levels));
      if (j + 1 < levels) {
        pass("apply_stencil", level + ": step the levels down | apply_stencil(GREATER, SHAD_ZERO, DECR)");
        apply_to_screen(gl_, {GL_LESS, lv_.shadZero, lv_.max, lv_.max, GL_DECR});
      }
    }
    pass("accumulate", "darkness levels summed | glAccum(GL_RETURN, 1)");
    gl_.colorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
    gl_.accum(GL_RETURN, 1.0f);
    gl_.colorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  }

  // ---- draw_ref_objects(Camera) -------------------------------------------
  void draw_ref_objects(const ViewCamera& cam, int refLevel) {
    const std::uint32_t level = static_cast<std::uint32_t>(refLevel);
    path_.push_back("draw_ref_objects level " + std::to_string(refLevel));
    if (refLevel == 1) {
      pass("apply_stencil", "clear | clear_stencil(ZERO)");
      gl_.clear(GL_STENCIL_BUFFER_BIT);
    }
    pass("apply_stencil", "render area to REF_LEVEL | apply_stencil(EQUAL, ZERO, REPLACE, REF_LEVEL)");
    apply_stencil(gl_, {PaperCompare::Equal, lv_.zero, PaperPass::Replace, level}, lv_);
    const DVec3 eye = cam.eye(s_.camera);
    for (int f = 0; f < static_cast<int>(faces_.size()); ++f) {
      const RefFace& face = faces_[static_cast<std::size_t>(f)];
      if (f == cam.throughFace) continue;  // a planar face cannot see itself (eq. 5: n - 1)
      // Mirrors seen from behind show nothing (culling on); glass has two
      // sides and is looked through from either (issue 12, bug 2).
      const bool behind = !(face.side(eye) > 0.0);
      if (plan_.cull && behind && !face.refracts()) {
        ++counts_.facesSkipped;
        continue;
      }
      const SceneObject& obj = s_.objects[static_cast<std::size_t>(face.object)];
      path_.push_back("face " + std::to_string(f) + " \"" + obj.name + "\"");
      pass("ref face", "mask the face | stencil(EQUAL, REF_LEVEL, REPLACE, ZERO); draw_face(ref_face)");
      stencil(gl_, {PaperCompare::Equal, level, PaperPass::Replace, lv_.zero}, lv_);
      // No pixel of the face survives the depth and stencil tests: nothing
      // to reflect (culling on; the counter plays an occlusion query's part).
      if (plan_.cull) gl_.beginFragmentCount();
      drawFaceMask(cam, face, behind && face.refracts());
      if (plan_.cull && gl_.endFragmentCount() == 0) {
        ++counts_.facesSkipped;
        path_.pop_back();
        continue;
      }
      ViewCamera next = refCamera(cam, face, f, refLevel);
      const SceneMaterial& fm = s_.materials[static_cast<std::size_t>(s_.objects[static_cast<std::size_t>(face.object)].material)];
      if (face.kind == MaterialKind::Mirror && fm.roughness > 0.0f && s_.render.frosted) {
        // A glossy mirror (1997 Fig. 4, the marble): the reflected view
        // sheared about the face normal like frosted glass, by twice the
        // Ward roughness (microfacets tilted by alpha tilt the reflection by
        // 2 alpha), one shear per accumulated image.
        next.world = next.world * shearAboutFace(face.centre, face.normal,
                                                 frostedShear(2.0 * fm.roughness, fm.samples, image_));
      }
      if (face.refracts()) {
        const auto r = refractedView(cam, s_.camera, face, f, face.ior, gl_scene_.aspect());
        if (!r) {
          // The face's image cannot be mapped (a corner behind a camera):
          // nothing sensible to show through it; its mask is released below.
          ++counts_.facesSkipped;
          pass("apply_stencil", "face back to REF_LEVEL | apply_stencil(EQUAL, ZERO, REPLACE, REF_LEVEL)");
          apply_stencil(gl_, {PaperCompare::Equal, lv_.zero, PaperPass::Replace, level}, lv_);
          path_.pop_back();
          continue;
        }
        if (!r->totalReflection) next = r->view;  // past the critical angle the face is a mirror
        const MaterialKind kind = face.kind;
        if (kind == MaterialKind::Frosted && !r->totalReflection) {
          // Frosted glass (1997 §3): the view through the face sheared about
          // its normal by this image's stochastic (X, Y) shear; the images of
          // the accumulation average the shears into the scattered view.
          next.world = next.world * shearAboutFace(face.centre, face.normal, frostedShear(face.shear, fm.samples, image_));
        }
        if ((kind == MaterialKind::Translucent || kind == MaterialKind::Frosted) && !r->totalReflection) {
          // Fog from the face (its centre's eye distance in the view through
          // it) to fog_distance behind it (frosted glass scatters as
          // translucency does, 1997 §3).
          const DMat4 view = glm::lookAt(DVec3(s_.camera.position), DVec3(s_.camera.lookAt), DVec3(s_.camera.up));
          const DVec4 c = view * next.world * DVec4(face.centre, 1.0);
          next.fog = true;
          next.fogColor = face.color;
          next.fogStart = static_cast<float>(std::max(0.0, -c.z));
          next.fogEnd = next.fogStart + face.fogDistance;
        }
      }
      pass("ref face", "depth to far inside the mask | (the paper is silent: clear the face's pixels)");
      // Nothing behind a translucent face is as far as full fog.
      clearMaskToFar(next.fog ? next.fogColor : Vec3(0.0f));
      draw_window(next);
      pass("ref face", "blend the face's own colour | two renderings through destination alpha");
      finishFace(cam, face, behind && face.refracts());
      pass("apply_stencil", "face back to REF_LEVEL | apply_stencil(EQUAL, ZERO, REPLACE, REF_LEVEL)");
      apply_stencil(gl_, {PaperCompare::Equal, lv_.zero, PaperPass::Replace, level}, lv_);
      path_.pop_back();
    }
    pass("apply_stencil", "level done | apply_stencil(EQUAL, REF_LEVEL, REPLACE, ZERO)");
    apply_stencil(gl_, {PaperCompare::Equal, level, PaperPass::Replace, lv_.zero}, lv_);
    path_.pop_back();
  }

  // The mirror's virtual camera: the view reflected through the face's plane,
  // clipped at that plane so that nothing behind the mirror shows.
  ViewCamera refCamera(const ViewCamera& cam, const RefFace& face, int f, int level) const {
    ViewCamera v;
    v.world = cam.world * reflectionMatrix(face.normal, face.offset);
    v.mirrored = !cam.mirrored;
    v.clip = true;
    v.clipPlane = DVec4(face.normal, -face.offset);
    v.throughFace = f;
    v.level = level;
    v.near = mirrorNear(cam, face);
    return v;
  }

  // Everything a mirror's view shows lies beyond the mirror's plane (its
  // clip plane) and inside the face's image, so nothing in it is nearer the
  // eye, along the view axis, than the face's nearest corner: the view's
  // near plane moves out to that corner (0: the camera's own, when that is
  // as far, a corner is behind the eye, or the view is mapped). The depth
  // buffer's resolution then serves what the mirror shows: with a camera
  // 1e-6 before a mirror and near 1e-7, every reflected object lay within
  // 3 of 2^24 depth steps and their order turned on a rounding (issue 43).
  // The margin keeps the face's own plane inside the frustum.
  double mirrorNear(const ViewCamera& cam, const RefFace& face) const {
    if (cam.mapped) return 0.0;
    const Camera& c = s_.camera;
    const DVec3 eye(c.position), forward = glm::normalize(DVec3(c.lookAt) - eye);
    double nearest = std::numeric_limits<double>::infinity();
    for (const Vec3& corner : face.polygon) {
      const DVec4 q = cam.world * DVec4(DVec3(corner), 1.0);
      nearest = std::min(nearest, glm::dot(DVec3(q) / q.w - eye, forward));
    }
    const double near = nearest * (1.0 - 1e-3);
    return near > static_cast<double>(c.near) ? near : 0.0;
  }

  // ---- draw_normal_objects(Camera, STEN_VALUE) ----------------------------
  // No light: the ambient pass (depth LEQUAL, writes depth); otherwise that
  // light alone, added where depth is EQUAL (1997 §7.2).
  void draw_normal_objects(const ViewCamera& cam, std::uint32_t stenValue, const PointLight* light) {
    if (usesStencil()) stencil(gl_, {PaperCompare::Equal, stenValue, PaperPass::Keep, stenValue}, lv_);
    gl_scene_.setupView(cam);
    gl_.enable(GL_DEPTH_TEST);
    gl_.enable(GL_CULL_FACE);
    gl_.enable(GL_LIGHTING);
    if (!light) {
      gl_.depthFunc(GL_LEQUAL);
      gl_.depthMask(GL_TRUE);
      gl_.disable(GL_BLEND);
      gl_.disable(GL_LIGHT0);
      gl_.lightModelfv(GL_LIGHT_MODEL_AMBIENT, glFloats(s_.ambient.x, s_.ambient.y, s_.ambient.z, 1.0f).data());
    } else {
      gl_.depthFunc(GL_EQUAL);
      gl_.depthMask(GL_FALSE);
      gl_.enable(GL_BLEND);
      gl_.blendFunc(GL_ONE, GL_ONE);
      gl_.lightModelfv(GL_LIGHT_MODEL_AMBIENT, glFloats(0.0f, 0.0f, 0.0f, 1.0f).data());
      gl_.enable(GL_LIGHT0);
      gl_scene_.setLight(0, *light);
    }
    if (cam.fog) {
      // The ambient pass fades to the material's colour, the light passes to
      // black: their sum is f * lit + (1 - f) * colour, fog of the whole.
      const Vec3 c = !light ? cam.fogColor : Vec3(0.0f);
      gl_.enable(GL_FOG);
      gl_.fogi(GL_FOG_MODE, GL_LINEAR);
      gl_.fogf(GL_FOG_START, cam.fogStart);
      gl_.fogf(GL_FOG_END, cam.fogEnd);
      gl_.fogfv(GL_FOG_COLOR, glFloats(c.x, c.y, c.z, 1.0f).data());
    }
    // "for (each non_ref object)": ref objects are drawn by draw_ref_objects
    // where this view recurses into them; where it does not (recursion_depth
    // reached, or 0), they are drawn as their own colour (drawNotRecursedInto).
    const bool recurses = plan_.reflections && cam.level < plan_.recursionDepth;
    for (std::size_t i = 0; i < s_.objects.size(); ++i) {
      const SceneObject& o = s_.objects[i];
      const SceneMaterial& m = s_.materials[static_cast<std::size_t>(o.material)];
      const bool ref = isRefMaterial(m, s_.render);
      if (recurses && ref) continue;
      gl_scene_.setMaterial(m, !light);
      if (ref) drawNotRecursedInto(cam, static_cast<int>(i), m);
      else gl_scene_.drawTriangles(o.mesh);
    }
    if (cam.fog) gl_.disable(GL_FOG);
    if (light) ++counts_.lightPasses, reportProgress();
  }

  // Where the recursion stops (the deepest level, or recursion_depth 0).
  // The 1994 paper's bottom level draws "each non_ref object" only
  // (Figure 4, draw_normal_objects; §Recursion: "once the desired recursion
  // level has been reached ... puts us back one level of recursion"): its
  // ref faces are left out, their pixels keep whatever lies behind them, or
  // the clear colour (black) where nothing does. MPR draws them as their
  // own material, lit as opaque faces, the least wrong colour it has for
  // them without another level (issue 43, defect 7), per face:
  // - not the face this view looks through: it lies on the view's clip
  //   plane, and drawn into its own view it covered everything seen
  //   through it with its own colour (a lamp behind a pane at the deepest
  //   level vanished);
  // - glass has two sides, as in draw_ref_objects: a refracting face seen
  //   from behind (every face of a glass box seen from inside it) is drawn
  //   turned round, lit from the side the eye sees, where culling showed
  //   what lay behind it or black. Mirrors stay one-sided.
  void drawNotRecursedInto(const ViewCamera& cam, int object, const SceneMaterial& m) {
    const Mesh& mesh = s_.objects[static_cast<std::size_t>(object)].mesh;
    const std::vector<std::uint8_t>* skip = nullptr;
    if (cam.throughFace >= 0 && faces_[static_cast<std::size_t>(cam.throughFace)].object == object)
      skip = &trianglesOfFace(cam.throughFace);
    gl_scene_.drawTriangles(mesh, skip);
    if (refracts(m.kind)) gl_scene_.drawTriangles(mesh, skip, true);
  }

  // The triangles of ref face f's object that lie in its plane (within the
  // loader's planarity tolerance, 1e-4 of the face's extent, at least 1e-4):
  // the face itself, and anything else of the object on the plane a view
  // through it clips at. Computed once per face.
  const std::vector<std::uint8_t>& trianglesOfFace(int f) {
    std::vector<std::uint8_t>& marks = faceTriangles_[static_cast<std::size_t>(f)];
    if (!marks.empty()) return marks;
    const RefFace& face = faces_[static_cast<std::size_t>(f)];
    const Mesh& mesh = s_.objects[static_cast<std::size_t>(face.object)].mesh;
    double extent = 0.0;
    for (const Vec3& p : face.polygon) extent = std::max(extent, glm::length(DVec3(p) - DVec3(face.polygon.front())));
    const double tolerance = 1e-4 * std::max(1.0, extent);
    marks.assign(mesh.triangles.size(), 0);
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      bool inPlane = true;
      for (const std::uint32_t v : mesh.triangles[t])
        inPlane = inPlane && std::fabs(face.side(DVec3(mesh.positions[v]))) <= tolerance;
      marks[t] = inPlane ? 1 : 0;
    }
    return marks;
  }

  // draw_face(ref_face): the face's visible pixels (depth test, no colour or
  // depth writes) take the stencil op set by the caller.
  void drawFaceMask(const ViewCamera& cam, const RefFace& face, bool fromBehind) {
    gl_scene_.setupView(cam);
    gl_.colorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    gl_.depthMask(GL_FALSE);
    gl_.enable(GL_DEPTH_TEST);
    gl_.depthFunc(GL_LEQUAL);
    gl_.enable(GL_CULL_FACE);
    gl_.disable(GL_LIGHTING);
    gl_.disable(GL_BLEND);
    gl_scene_.drawPolygon(face, false, fromBehind);
    gl_.colorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    gl_.depthMask(GL_TRUE);
  }

  // Inside the face's mask (stencil ZERO): clear colour (black, or a
  // translucent face's fog colour) and depth = far, so
  // the virtual scene can be drawn there with the depth test.
  void clearMaskToFar(Vec3 colour) {
    stencil(gl_, {PaperCompare::Equal, lv_.zero, PaperPass::Keep, lv_.zero}, lv_);
    gl_.windowMap(std::nullopt);
    gl_.disable(GL_LIGHTING);
    gl_.disable(GL_BLEND);
    gl_.disable(GL_CULL_FACE);
    gl_.disable(GL_CLIP_PLANE0);
    gl_.enable(GL_DEPTH_TEST);
    gl_.depthFunc(GL_ALWAYS);
    gl_.depthMask(GL_TRUE);
    gl_.matrixMode(GL_PROJECTION);
    gl_.loadIdentity();
    gl_.matrixMode(GL_MODELVIEW);
    gl_.loadIdentity();
    gl_.color4f(colour.x, colour.y, colour.z, 1.0f);
    gl_.begin(GL_QUADS);
    gl_.vertex3f(-1.0f, -1.0f, 1.0f);
    gl_.vertex3f(1.0f, -1.0f, 1.0f);
    gl_.vertex3f(1.0f, 1.0f, 1.0f);
    gl_.vertex3f(-1.0f, 1.0f, 1.0f);
    gl_.end();
  }

  // After the reflection is drawn in the face's mask (still ZERO): first
  // rendering writes destination alpha = 1 - reflectance, no colour; second
  // draws the face lit (ambient and up to eight lights at once) blended as
  // lit * dst_alpha + reflection * (1 - dst_alpha). Depth ALWAYS puts the
  // face's own depth back. (1994 paper, "Object attributes and translucency".)
  void finishFace(const ViewCamera& cam, const RefFace& face, bool fromBehind) {
    const SceneMaterial& m = s_.materials[static_cast<std::size_t>(s_.objects[static_cast<std::size_t>(face.object)].material)];
    stencil(gl_, {PaperCompare::Equal, lv_.zero, PaperPass::Keep, lv_.zero}, lv_);
    gl_scene_.setupView(cam);
    gl_.enable(GL_DEPTH_TEST);
    gl_.depthFunc(GL_ALWAYS);
    gl_.enable(GL_CULL_FACE);
    gl_.disable(GL_LIGHTING);
    gl_.disable(GL_BLEND);
    gl_.colorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_TRUE);
    gl_.depthMask(GL_FALSE);
    const float through = m.kind == MaterialKind::Mirror ? m.reflectance : m.transmittance;
    gl_.color4f(0.0f, 0.0f, 0.0f, 1.0f - through);
    gl_scene_.drawPolygon(face, false, fromBehind);
    gl_.colorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    gl_.depthMask(GL_TRUE);
    gl_.enable(GL_BLEND);
    gl_.blendFunc(GL_DST_ALPHA, GL_ONE_MINUS_DST_ALPHA);
    if (!(plan_.shadows && cam.level <= plan_.shadowDepth)) {
      gl_scene_.enableAllLights();
      gl_scene_.setFullMaterial(m);
      gl_scene_.drawPolygon(face, true, fromBehind);
      gl_scene_.disableExtraLights();
      gl_.disable(GL_BLEND);
      return;
    }
    shadowedFaceColour(cam, face, fromBehind, m);
  }

  // Mirrors and glass receive shadows (issue 12, bug 4; the 1997 paper
  // casts shadows on partially specular surfaces, §7.3): in a view with
  // shadows the face's own colour is drawn as the scene is, the ambient
  // term first (blended over the view through it with destination alpha
  // 1 - r, depth ALWAYS, which puts the face's depth back), then per light
  // the face's pixels (ZERO) raised to SHAD_ZERO, the light's shadow
  // volumes counted (all but the face's own), the light added where
  // SHAD_ZERO remains (depth EQUAL, blend DST_ALPHA, ONE: (1 - r) of it),
  // and the counts back to ZERO. Destination alpha is masked after its
  // first rendering, so every pass scales by the same 1 - r.
  void shadowedFaceColour(const ViewCamera& cam, const RefFace& face, bool fromBehind, const SceneMaterial& m) {
    const std::uint32_t zero = lv_.zero;
    gl_.colorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
    gl_.lightModelfv(GL_LIGHT_MODEL_AMBIENT, glFloats(s_.ambient.x, s_.ambient.y, s_.ambient.z, 1.0f).data());
    gl_.disable(GL_LIGHT0);
    gl_.enable(GL_LIGHTING);
    gl_scene_.setMaterial(m, true);
    gl_scene_.drawPolygon(face, true, fromBehind);
    for (int light = 0; light < static_cast<int>(s_.lights.size()); ++light) {
      const std::string l = std::to_string(light);
      pass("apply_stencil", "face lit by light " + l + ": its pixels to SHAD_ZERO | apply_stencil(EQUAL, ZERO, REPLACE, SHAD_ZERO)");
      apply_stencil(gl_, {PaperCompare::Equal, zero, PaperPass::Replace, lv_.shadZero}, lv_);
      pass("shadow volume", "shadows on the face, light " + l + " | the light's volumes but the face's own, on its pixels");
      ++counts_.shadowPasses, reportProgress();
      gl_scene_.setupView(cam);
      counts_.zfailVolumes += shadows_.drawVolumes(gl_, light, cam, s_.camera, lv_, face.object);
      pass("light", "the face lit by light " + l + " outside the shadows | blend (DST_ALPHA, ONE)");
      stencil(gl_, {PaperCompare::Equal, lv_.shadZero, PaperPass::Keep, lv_.shadZero}, lv_);
      gl_scene_.setupView(cam);
      gl_.colorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
      gl_.enable(GL_DEPTH_TEST);
      gl_.depthFunc(GL_EQUAL);
      gl_.depthMask(GL_FALSE);
      gl_.enable(GL_CULL_FACE);
      gl_.enable(GL_BLEND);
      gl_.blendFunc(GL_DST_ALPHA, GL_ONE);
      gl_.enable(GL_LIGHTING);
      gl_.lightModelfv(GL_LIGHT_MODEL_AMBIENT, glFloats(0.0f, 0.0f, 0.0f, 1.0f).data());
      gl_.enable(GL_LIGHT0);
      gl_scene_.setLight(0, s_.lights[static_cast<std::size_t>(light)]);
      gl_scene_.setMaterial(m, false);
      gl_scene_.drawPolygon(face, true, fromBehind);
      ++counts_.lightPasses, reportProgress();
      pass("apply_stencil", "face back to ZERO | apply_stencil(GREATER, SHAD_MIN, REPLACE, ZERO)");
      apply_stencil(gl_, {PaperCompare::Greater, lv_.shadMin, PaperPass::Replace, zero}, lv_);
    }
    gl_.colorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    gl_.depthMask(GL_TRUE);
    gl_.disable(GL_BLEND);
  }

  const Scene& s_;
  const RenderPlan& plan_;
  GLCommandStream& gl_;
  StencilLevels lv_;
  std::function<void(const DrawWindowProgress&)> progress_;
  std::vector<RefFace> faces_;
  std::vector<std::vector<std::uint8_t>> faceTriangles_;  // trianglesOfFace, per ref face
  ShadowPass shadows_;
  std::vector<ReflectedLight> refLights_;
  std::vector<std::string> path_;
  DrawWindowCounts counts_;
  SceneGL gl_scene_;
  int image_ = 0;  // which image of an accumulation (frosted faces' shear)
};

}  // namespace

DrawWindowCounts drawScene(const Scene& scene, const RenderPlan& plan, GLCommandStream& gl,
                           const std::function<void(const DrawWindowProgress&)>& progress,
                           const ViewSample& sample, const ShadowPass* pivotBase) {
  return WindowRenderer(scene, plan, gl, progress, sample, pivotBase).run();
}

}  // namespace mpr
