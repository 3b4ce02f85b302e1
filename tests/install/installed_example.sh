# The installed package from outside the tree: cmake --install to a
# temporary prefix, then examples/stencil-unit-test (a separate CMake
# project, find_package(MPR CONFIG REQUIRED), one #include <mpr/mpr.hpp>)
# configured, built and run against it; and the pkg-config file.
# $1: the build tree, $2: the source tree.
set -euo pipefail
BUILD="$1"
SRC="$2"
WORK="$(mktemp -d)"
trap 'rm -rf "$WORK"' EXIT
cmake --install "$BUILD" --prefix "$WORK/prefix" >/dev/null
for f in include/mpr/mpr.hpp include/mpr/pipeline/gl/gl_context.hpp include/mpr/pipeline/draw/draw_stage.hpp \
         include/mpr/script/gl_script.hpp include/mpr/testing/gtest_helpers.hpp \
         lib/libmpr_pipeline.a lib/libmpr_script.a lib/cmake/MPR/MPRConfig.cmake lib/cmake/MPR/MPRTargets.cmake lib/pkgconfig/mpr.pc bin/mpr; do
  [[ -e "$WORK/prefix/$f" ]] || { echo "FAIL: $f was not installed" >&2; exit 1; }
done
cmake -S "$SRC/examples/stencil-unit-test" -B "$WORK/build" -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_PREFIX_PATH="$WORK/prefix" >/dev/null
nice -n 10 cmake --build "$WORK/build" -j2 >/dev/null
"$WORK/build/stencil_unit_test" --gtest_brief=1
# The pkg-config file names the prefix and the libraries.
flags="$(PKG_CONFIG_PATH="$WORK/prefix/lib/pkgconfig" pkg-config --cflags --libs mpr)"
[[ "$flags" == *"-I$WORK/prefix/include "* && "$flags" == *"-lmpr_pipeline"* ]] ||
  { echo "FAIL: pkg-config mpr: $flags" >&2; exit 1; }
echo ok
