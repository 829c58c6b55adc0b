// The operation families of the harnesses: harness name -> the ABI ops it decodes into (byte 0 of
// an input picks one, decode.hpp). Shared by the harnesses and the seed-corpus generator. Every op
// of the op list (abi_op_list.h) is in exactly one family (ctest fuzz_test_families);
// a family's order is part of its corpus's meaning, so an op joins a new family, never an old one.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace rotorcert::fuzz {

inline const std::map<std::string, std::vector<std::string>>& families() {
  static const std::map<std::string, std::vector<std::string>> f = {
      {"conversions", {"normalize", "inverse", "to_matrix", "from_matrix", "to_axis_angle", "from_axis_angle"}},
      {"compose_apply", {"compose", "apply_vector", "apply_bivector", "apply_trivector"}},
      {"log_exp", {"log", "exp"}},
      {"interpolation", {"slerp", "nlerp"}},
      {"blending", {"blend_qlb", "blend_log", "dq_blend"}},
      {"rigid", {"dq_from_rotation_translation", "dq_compose", "dq_apply_point", "dq_normalize", "dq_sclerp",
                 "rotate_about_axis"}},
      {"skinning", {"skin_linear", "skin_dual_quaternion"}},
      {"rotation_parts", {"to_angle", "to_axis", "sqrt"}},
      {"rigid_transforms",
       {"dq_to_rotation_translation", "dq_log", "dq_exp", "rigid_compose", "rigid_apply", "rigid_inverse"}},
  };
  return f;
}

}  // namespace rotorcert::fuzz
