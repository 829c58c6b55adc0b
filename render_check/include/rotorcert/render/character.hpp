// The built-in default characters of the render check (CHAR-1 of spec/SPEC.md): the three
// complexities of Papagiannakis (2013), Section 6 ("from 3 joints and 4 triangles up to 42 joints
// and 30000 triangles ... from a simple 6 vertex plane to a standard md2 and collada
// characters"), generated here at run time, never stored as files. write_gltf (gltf_write.hpp)
// turns one into a glTF document that load_gltf_memory reads back as the same Scene, so the
// built-in characters and user files take the same input path.
//
// Conventions of every character: metres, +Y up, facing +Z, the character's left at +X. Each joint
// has a bone from its origin to a tail point and a rest rotation that turns local +Y onto that
// bone (the Blender convention), so rest rotations are not the identity. Joints are in depth-first
// preorder (the loader's order); the last joint, "body", is the node that carries the one mesh and
// is not a skin joint, so skin_joints lists every other joint. Accessor data (positions, normals,
// weights, inverse bind matrices, keyframes) are binary32 values already, so a glTF round trip
// reproduces them exactly; node rest transforms are binary64.
//
// Layout of the scene:
//   simple  3 skin joints root -> mid -> tip along +X (1 m apart); one 2 x 1 m strip in the XZ
//           plane, 6 vertices, 4 triangles facing +Y. Clips "bend" (mid: 90 deg about +Z) and
//           "twist" (tip: 180 deg about its bone axis +X; the tip column is weighted half mid,
//           half tip, the smallest candy-wrapper case).
//   medium  21 skin joints: torso (hips, spine, chest, neck, head) and two arms (clavicle_S,
//           upper_arm_S, forearm_S, hand_S, thumb_1_S, thumb_2_S, fingers_1_S, fingers_2_S; S = L
//           or R); a few thousand triangles. Clips "bend" and "twist".
//   full    42 skin joints: hips, spine, chest, upper_chest, neck, head; per side clavicle,
//           upper_arm, forearm, hand, five fingers of two joints (thumb, index, middle, ring,
//           pinky: <finger>_1_S, <finger>_2_S), thigh, shin, foot, toe; about 30,000 triangles.
//           Clips "walk", "bend" and "twist".
// Clips: 2 s at 30 frames per second (61 keyframes per channel, times k/30), LINEAR, rotation
// keyframes unit quaternions with consecutive keys in the same hemisphere.
//   "bend"   the elbows (forearm_S) bend forwards from 0 to 135 deg (simple: mid, 90 deg);
//   "twist"  the wrists (hand_S) turn about the forearm axis from 0 to 180 deg (simple: tip);
//   "walk"   one gait cycle that loops: legs, knees, feet, arms lowered and swinging, spine, and a
//            vertical bob of the hips (the only translation channel).
// Both "bend" and "twist" ease in and out (smoothstep in time) and end at the stated angle.
// Skin: the mesh is made of closed tubes (torso with head, arms with hands, fingers, legs, feet)
// whose weights blend smoothly across each joint along the tube; every vertex has 1 to 4
// influences of distinct joints, each a multiple of 2^-16, summing to exactly 1.
#pragma once

#include <rotorcert/render/scene.hpp>

namespace rotorcert::render {

/// The paper's three figures: 3 joints / 4 triangles, an md2-like upper body, a collada-like
/// humanoid of 42 joints and about 30,000 triangles.
enum class Complexity { simple, medium, full };

/// "simple", "medium", "full".
const char* to_string(Complexity c);

/// The character of that complexity, built in memory (deterministic: no randomness). Its name is
/// "rotorcert_<complexity>".
Scene make_character(Complexity c);

}  // namespace rotorcert::render
