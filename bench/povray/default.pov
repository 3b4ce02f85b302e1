// scenes/default.yaml (MPR's default scene: a room with a mirror, a glass
// pane, a cube, a sphere and one light) transcribed by hand into POV-Ray 3.7
// SDL, for scripts/reference-vs-povray (the speed comparison of
// `mpr reference` with POV-Ray in docs/explanation/accuracy.md).
//
// Render (what the script runs; File_Gamma=1.0 writes linear values, as MPR does):
//   povray +W640 +H480 +WT2 -D +A0.0 +AM1 +R4 File_Gamma=1.0 \
//          +Ibench/povray/default.pov +O/tmp/pov.png
//
// Coordinates are MPR's (right-handed, y up, metres as in the YAML): the
// camera's `right -x*...` makes POV-Ray right-handed, so every position,
// scale and rotation is copied unchanged (POV-Ray's `rotate y*a` is the same
// matrix as glRotate(a, 0, 1, 0)). MPR builds primitives at unit size,
// centred, quads facing +z, and applies scale, then rotate, then translate;
// so does every object below.
//
// Where this scene differs from MPR's (and from `mpr reference`'s):
//  * light attenuation: POV-Ray's fade is 2 / (1 + (d/fade_distance)^fade_power),
//    it cannot be 1/(1 + 0.02 d + 0.01 d^2). fade_distance 2.12, fade_power 0.7
//    is the least-worst fit over the distances that occur (2.5 .. 8.5): within
//    5% (0.942 vs 0.899 at 2.5, 0.836 vs 0.845 at 3.4, 0.708 vs 0.741 at 5,
//    0.549 vs 0.528 at 8.5). fade_power 2 fits no better than 46%.
//  * the area light: a disc of the light's radius 0.15 turned to face each
//    shaded point (`circular orient`), 4x4 = 16 jittered shadow rays at
//    every shaded point (not adaptive), whatever the pixel's sample count
//    (AreaSamples, below, changes the 4).
//  * the glass pane: a box 3 cm thick (ior 1.5), as the default scene's pane
//    is a 3 cm slab (`thickness: 0.03`, in-out refraction, 1997 §2): the ray
//    is bent going in and bent back going out, leaving shifted and parallel
//    to itself. MPR and its reference apply that shift at the face as
//    modelled (thin in position); POV-Ray's box has its two faces 3 cm apart,
//    so its view through the pane sits up to 1.5 cm off MPR's.
//    The inner faces are fully transparent and unlit (interior_texture), so
//    the pane's colour is 0.15 x lit + 0.85 x what lies behind, once, as in
//    MPR's blend.
//  * the sphere is a true sphere, not MPR's 48 x 24 faceted one with smooth
//    normals.
//  * the mirror: reflection 0.9 adds the reflection; MPR blends
//    0.1 x lit + 0.9 x reflection, so the mirror's ambient and diffuse are
//    scaled by 0.1 here.
//  * the front wall (behind the camera, facing the room) is `no_image`: MPR
//    culls it in the direct view, seen from behind; POV-Ray's surfaces are
//    two-sided, so it would otherwise hide the room.
//  * shadows are the reference's: every object casts one (the pipeline's
//    quads and planes cast none). The reference's mirror and pane are opaque
//    to shadow rays and their light arrives along its own reflected or bent
//    path; POV-Ray lets shadow rays through the pane, unbent, weakened by its
//    transmit (a pale shadow, straight-through light: the 1 cm slab would
//    hardly bend it anyway), and traces no light off the mirror unless
//    photons are on (`Declare=Photons=1`: the mirror becomes a photon
//    target, so its light reaches the floor, as the reference's and the
//    pipeline's does; not in the timed renders).
//  * highlights: the red material's GL Blinn-Phong (specular 0.4,
//    shininess 32) is POV-Ray's `specular 0.4 roughness 1/32` (the same
//    formula); the blue Ward material (rho_s 0.04, alpha 0.2) is MPR's
//    eq. (6) fit, exponent 1.999/0.2^2 = 49.975 with the specular scaled by
//    0.0398 x 49.975: specular 0.0796, roughness 1/49.975.
//  * the floor is one polygon, not MPR's 8 x 8 subdivided plane (the same
//    surface); the sphere and cube are POV-Ray primitives, the rest polygons.
//  * tracing depth: max_trace_level 64 with adc_bailout 1/512, as the
//    reference stops where a contribution falls below 1/512.
#version 3.7;

// Shadow rays a shaded point sends: AreaSamples x AreaSamples (default 4x4);
// the command line may change it, e.g. `Declare=AreaSamples=2`.
#ifndef (AreaSamples) #declare AreaSamples = 4; #end
// Photons = 1: the light the mirror reflects and the pane bends (see above).
#ifndef (Photons) #declare Photons = 0; #end

global_settings {
  assumed_gamma 1.0        // linear, as GL
  ambient_light rgb 1      // the finish's ambient is the scene ambient
  max_trace_level 64
  adc_bailout 1/512
  #if (Photons) photons { spacing 0.01 } #end
}

background { rgb 0 }

// gluPerspective(45, 640/480): POV-Ray's angle is horizontal.
camera {
  perspective
  location <0.0, 1.7, 6.5>
  look_at <0.0, 1.0, 0.0>
  right -x * image_width / image_height   // minus: right-handed, as GL
  up y
  sky y
  angle 2 * degrees(atan(tan(radians(45 / 2)) * image_width / image_height))  // 57.82
}

light_source {
  <1.5, 3.4, 2.5>
  color rgb <1.0, 0.95, 0.85>
  area_light <0.3, 0, 0>, <0, 0.3, 0>, AreaSamples, AreaSamples   // diameter 2 x radius 0.15
  circular
  orient
  jitter
  fade_distance 2.12
  fade_power 0.7
  #if (Photons) photons { reflection on refraction on area_light } #end
}

#declare Ambient = rgb <0.12, 0.12, 0.14>;

#macro Lambert(Diffuse)
  texture {
    pigment { rgb Diffuse }
    finish { ambient Ambient diffuse 1 specular 0 phong 0 }
  }
#end

#declare T_floor = Lambert(<0.75, 0.72, 0.66>)
#declare T_wall  = Lambert(<0.62, 0.68, 0.78>)
#declare T_front = Lambert(<0.78, 0.66, 0.52>)
#declare T_red = texture {
  pigment { rgb <0.85, 0.22, 0.15> }
  finish { ambient Ambient diffuse 1 specular 0.4 roughness 1/32 }
}
#declare T_blue = texture {
  pigment { rgb <0.2, 0.35, 0.85> }
  finish { ambient Ambient diffuse 1 specular 0.04 * 0.0398 * 1.999 / (0.2 * 0.2) roughness (0.2 * 0.2) / 1.999 }
}
#declare T_mirror = texture {
  pigment { rgb 0.05 }
  finish { ambient 0.1 * Ambient diffuse 0.1 reflection 0.9 }
}
#declare T_glass = texture {
  pigment { rgbt <0.7, 0.8, 0.85, 0.85> }
  finish { ambient Ambient diffuse 1 }
}

// MPR's quad: unit size, centred, facing +z.
#declare UnitQuad = polygon { 5, <-0.5, -0.5, 0>, <0.5, -0.5, 0>, <0.5, 0.5, 0>, <-0.5, 0.5, 0>, <-0.5, -0.5, 0> }

// floor: plane, scale [8, 1, 8] (unit square in xz at y = 0, facing +y)
polygon {
  5, <-4, 0, 4>, <4, 0, 4>, <4, 0, -4>, <-4, 0, -4>, <-4, 0, 4>
  texture { T_floor }
}
// back wall
object { UnitQuad scale <8, 4, 1> translate <0, 2, -3> texture { T_wall } }
// left wall
object { UnitQuad scale <8, 4, 1> rotate y * 90 translate <-4, 2, 1> texture { T_wall } }
// right wall
object { UnitQuad scale <8, 4, 1> rotate y * -90 translate <4, 2, 1> texture { T_wall } }
// front wall: behind the camera, facing the room; seen only in the mirror
object { UnitQuad scale <8, 4, 1> rotate y * 180 translate <0, 2, 5> texture { T_front } no_image }
// mirror
object {
  UnitQuad scale <2.4, 1.8, 1> translate <0, 1.6, -2.98> texture { T_mirror }
  #if (Photons) photons { target reflection on refraction off collect off } #end
}
// glass pane: a box 3 cm thick, MPR's slab of thickness 0.03
box {
  <-0.5, -0.5, -0.015>, <0.5, 0.5, 0.015>
  texture { T_glass }
  interior_texture { pigment { rgbt <1, 1, 1, 1> } finish { ambient 0 diffuse 0 } }
  interior { ior 1.5 }
  scale <1.2, 1.6, 1>
  rotate y * 15
  translate <1.6, 0.9, 0.8>
}
// cube
box { <-0.5, -0.5, -0.5>, <0.5, 0.5, 0.5> texture { T_red } rotate y * 25 translate <-1.0, 0.5, 0.2> }
// sphere
sphere { <0, 0, 0>, 1 texture { T_blue } scale 0.55 translate <0.6, 0.55, -0.8> }
