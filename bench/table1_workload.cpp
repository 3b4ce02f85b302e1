// Writes a GL script (.gls) in the shape of the 1997 paper's Table 1
// workload (Diefenbach & Badler 1997, "Multi-Pass Pipeline Rendering",
// section 5): at 640x480, a dozen scene images accumulated, each of about
// 2 000 lit, depth-tested triangles, two shadow-volume passes (front faces
// GL_INCR, back faces GL_DECR, colour and depth writes off) and two
// full-screen stencil passes (apply_stencil: a window-sized rectangle drawn
// where the stencil equals a value). Seeded: the same seed writes the same
// bytes. Usage: table1_workload [--seed N] [--images N] > workload.gls
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>

namespace {

constexpr int kWidth = 640, kHeight = 480;

struct Rng {
  std::mt19937 engine;
  // Dyadic values (multiples of 1/256) print exactly and parse the same everywhere.
  double uniform(double lo, double hi) {
    const double u = static_cast<double>(engine() % 65537u) / 65536.0;
    return lo + (hi - lo) * std::round(u * 256.0) / 256.0;
  }
};

void lit(std::FILE* out, Rng& rng, int triangles) {
  // A bumpy sheet seen in perspective: strips of lit triangles, normals varied.
  const int columns = 50, rows = triangles / (2 * columns);
  std::fprintf(out, "glEnable GL_LIGHTING\nglEnable GL_LIGHT0\nglEnable GL_DEPTH_TEST\nglDepthFunc GL_LEQUAL\n");
  std::fprintf(out, "glDepthMask GL_TRUE\nglColorMask GL_TRUE GL_TRUE GL_TRUE GL_TRUE\nglDisable GL_STENCIL_TEST\n");
  std::fprintf(out, "glLightfv GL_LIGHT0 GL_POSITION %g %g %g 1\n", rng.uniform(-4, 4), rng.uniform(2, 6),
               rng.uniform(-2, 4));
  std::fprintf(out, "glMaterialfv GL_FRONT_AND_BACK GL_DIFFUSE %g %g %g 1\n", rng.uniform(0.3, 0.9),
               rng.uniform(0.3, 0.9), rng.uniform(0.3, 0.9));
  for (int r = 0; r < rows; ++r) {
    std::fprintf(out, "glBegin GL_TRIANGLE_STRIP\n");
    for (int c = 0; c <= columns; ++c)
      for (int k = 0; k < 2; ++k) {
        const double x = -5.0 + 10.0 * c / columns, z = -8.0 + 10.0 * (r + k) / rows;
        std::fprintf(out, "glNormal3f %g %g 1\nglVertex3f %g %g %g\n", rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3),
                     x, rng.uniform(-0.1, 0.1), z);
      }
    std::fprintf(out, "glEnd\n");
  }
  std::fprintf(out, "glDisable GL_LIGHTING\n");
}

void shadowVolume(std::FILE* out, Rng& rng) {
  // Shadow-volume pass: a prism's sides, counted in the stencil (depth-pass rule).
  std::fprintf(out, "@pass shadow volume\nglEnable GL_STENCIL_TEST\nglStencilFunc GL_ALWAYS 0 255\n");
  std::fprintf(out, "glColorMask GL_FALSE GL_FALSE GL_FALSE GL_FALSE\nglDepthMask GL_FALSE\nglEnable GL_CULL_FACE\n");
  const double cx = rng.uniform(-3, 3), cz = rng.uniform(-6, 0), r = rng.uniform(0.5, 2.0);
  for (int face = 0; face < 2; ++face) {
    std::fprintf(out, "glCullFace %s\nglStencilOp GL_KEEP GL_KEEP %s\nglBegin GL_QUAD_STRIP\n",
                 face == 0 ? "GL_BACK" : "GL_FRONT", face == 0 ? "GL_INCR" : "GL_DECR");
    for (int k = 0; k <= 24; ++k) {
      const double a = 6.283185307179586 * k / 24;
      const double x = cx + r * std::cos(a), z = cz + r * std::sin(a);
      std::fprintf(out, "glVertex3f %.6f 3 %.6f\nglVertex3f %.6f -1 %.6f\n", x, z, x, z);
    }
    std::fprintf(out, "glEnd\n");
  }
  std::fprintf(out, "glDisable GL_CULL_FACE\n");
}

void applyStencil(std::FILE* out, Rng& rng, int value) {
  // Figure 4's apply_stencil: a full-screen rectangle where the stencil holds `value`.
  std::fprintf(out, "@pass apply_stencil\nglEnable GL_STENCIL_TEST\nglStencilFunc GL_EQUAL %d 255\n", value);
  std::fprintf(out, "glStencilOp GL_KEEP GL_KEEP GL_ZERO\nglDisable GL_DEPTH_TEST\n");
  std::fprintf(out, "glColorMask GL_TRUE GL_TRUE GL_TRUE GL_TRUE\nglEnable GL_BLEND\nglBlendFunc GL_ONE GL_ONE\n");
  std::fprintf(out, "glMatrixMode GL_PROJECTION\nglPushMatrix\nglLoadIdentity\nglOrtho 0 %d 0 %d -1 1\n", kWidth, kHeight);
  std::fprintf(out, "glMatrixMode GL_MODELVIEW\nglPushMatrix\nglLoadIdentity\n");
  std::fprintf(out, "glColor3f %g %g %g\nglRectf 0 0 %d %d\n", rng.uniform(0, 0.25), rng.uniform(0, 0.25),
               rng.uniform(0, 0.25), kWidth, kHeight);
  std::fprintf(out, "glPopMatrix\nglMatrixMode GL_PROJECTION\nglPopMatrix\nglMatrixMode GL_MODELVIEW\n");
  std::fprintf(out, "glDisable GL_BLEND\nglEnable GL_DEPTH_TEST\n");
}

}  // namespace

int main(int argc, char** argv) {
  unsigned seed = 1;
  int images = 12;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--seed") == 0 && i + 1 < argc) {
      seed = static_cast<unsigned>(std::strtoul(argv[++i], nullptr, 10));
    } else if (std::strcmp(argv[i], "--images") == 0 && i + 1 < argc) {
      images = std::atoi(argv[++i]);
    } else {
      std::fprintf(stderr, "usage: table1_workload [--seed N] [--images N] > workload.gls\n");
      return 2;
    }
  }
  Rng rng{std::mt19937(seed)};
  std::FILE* out = stdout;
  std::fprintf(out, "# Table-1-shaped workload (bench/table1_workload --seed %u --images %d)\n", seed, images);
  std::fprintf(out, "@framebuffer %d %d\n@profile mesa\nglDisable GL_DITHER\n", kWidth, kHeight);
  std::fprintf(out, "glClearAccum 0 0 0 0\nglClear GL_ACCUM_BUFFER_BIT\n");
  for (int image = 0; image < images; ++image) {
    std::fprintf(out, "@pass image %d\nglClearColor 0 0 0 1\nglClearStencil 0\n", image);
    std::fprintf(out, "glClear GL_COLOR_BUFFER_BIT|GL_DEPTH_BUFFER_BIT|GL_STENCIL_BUFFER_BIT\n");
    std::fprintf(out, "glMatrixMode GL_PROJECTION\nglLoadIdentity\ngluPerspective 45 1.3333333333333333 0.5 40\n");
    std::fprintf(out, "glMatrixMode GL_MODELVIEW\nglLoadIdentity\n");
    std::fprintf(out, "gluLookAt %g 3 6 0 0 -3 0 1 0\n", rng.uniform(-0.5, 0.5));  // a jittered view per image
    lit(out, rng, 2000);
    for (int s = 0; s < 2; ++s) shadowVolume(out, rng);
    for (int s = 0; s < 2; ++s) applyStencil(out, rng, s);
    std::fprintf(out, "glAccum GL_ACCUM %g\n", 1.0 / 16.0);
  }
  std::fprintf(out, "glAccum GL_RETURN 1\n");
  return 0;
}
