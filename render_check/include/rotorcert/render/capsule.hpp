// A generated skin for skeleton-only files (GLTF-4 of spec/SPEC.md): one capsule around each bone
// (parent joint -> child joint, both skinned), built in the bind pose given by the inverse bind
// matrices and weighted to the bone's two joints with a smooth falloff along the bone.
#pragma once

#include <rotorcert/render/scene.hpp>

namespace rotorcert::render {

struct CapsuleOptions {
  double radius_fraction = 0.15;  // capsule radius as a fraction of the bone length
  unsigned segments = 12;         // vertices around the bone (>= 3)
  unsigned cap_rings = 3;         // rings per hemispherical cap, pole and equator excluded
  unsigned body_rings = 5;        // rings along the cylinder, both ends included (>= 2)
};

/// Capsules for every bone whose length exceeds 1e-6 of the longest bone (shorter ones, such as
/// a joint placed on its parent, get none). Vertex weights: child joint smoothstep(s), parent
/// 1 - smoothstep(s), s = position along the bone in [0, 1] (caps clamp to 0 or 1).
/// Throws GltfError when a skinned joint's inverse bind matrix is singular.
SkinnedMesh make_capsule_skin(const Skeleton& skeleton, const CapsuleOptions& options = {});

}  // namespace rotorcert::render
