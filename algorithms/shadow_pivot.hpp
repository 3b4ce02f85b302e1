#pragma once
// The pivot (1997 §4.4, "Soft shadows", Fig. 7): a light jittered by J
// moves only the two far nodes of each shadow-volume face, "a linearly
// scaled movement of the end of the shadow volume": the segment from the
// light through a silhouette node pivots about that node, so the far node
// moves by -J times a2/a1 (b2/b1 for the edge's other node), a1 the
// light-to-node distance, a2 the node-to-far-node distance. The far node
// then lies on the ray from the jittered light through the unmoved node:
// exactly the jittered volume's face while the silhouette stays the same
// (the approximation is that it is kept: no silhouette is recomputed).
#include "algorithms/shadow_volume.hpp"
#include "util/vecmath.hpp"

namespace mpr {

// far - J |far - near| / |near - light|, in double, rounded once to float
// (equal inputs, equal outputs: a pivoted volume stays watertight).
Vec3 pivotFarNode(Vec3 near, Vec3 far, Vec3 light, DVec3 jitter);

// Every far node of the volume (sides' b', a' and the dark cap's) pivoted
// about its near node; the light cap and the silhouette stay.
ShadowVolume pivotShadowVolume(const ShadowVolume& base, DVec3 jitter);

// The volume to pivot: its far nodes pushed out from R to
// (R + r) / (1 - r / a1min) (a1min the nearest near node's distance from
// the light), so that after a jitter of at most r every far node is still
// at least R + r from the jittered light and beyond the receivers (whose
// reach from the jittered light grows by at most r). A light disc that
// reaches half way to the caster (r >= a1min / 2) is pushed out by 2 (R + r)
// only: the guarantee is lost there.
ShadowVolume pivotBaseVolume(const ShadowVolume& volume, double lightRadius);

}  // namespace mpr
