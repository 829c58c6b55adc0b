#include <rotorcert/engine/convention.hpp>

#include <utility>

namespace rotorcert::engine {
namespace {

bool is_quaternion_output(const Array& a) {
  return a.measure == Measure::rotation || a.measure == Measure::quaternion || a.measure == Measure::unit_rotation ||
         a.measure == Measure::canonical_rotation ||
         a.measure == Measure::rigid || a.measure == Measure::unit_rigid || a.measure == Measure::dual_parts;
}

/// Applies f to every 4-scalar quaternion block ([x, y, z, w]) of the arrays selected by `pick`;
/// a dual quaternion (stride 8) is two blocks.
template <class Pick, class F>
Values each_quaternion(const std::vector<Array>& arrays, Values values, Pick pick, F f) {
  for (std::size_t a = 0; a < arrays.size() && a < values.size(); ++a) {
    if (!pick(arrays[a]) || (arrays[a].stride != 4 && arrays[a].stride != 8)) continue;
    for (std::size_t j = 0; j + 4 <= values[a].size(); j += 4) f(&values[a][j]);
  }
  return values;
}

bool has_quaternion_input(const AbiOp& op) {
  for (const Array& a : op.inputs)
    if (a.stride == 4 || a.stride == 8) return true;
  return false;
}
bool has_quaternion_output(const AbiOp& op) {
  for (const Array& a : op.outputs)
    if (is_quaternion_output(a)) return true;
  return false;
}

void conjugate(Real* q) {
  for (int i = 0; i < 3; ++i) q[i] = -q[i];
}
/// The implementation reads the ABI's [x, y, z, w] as [w, x, y, z]: the rotation it sees, in ABI
/// order, is [a1, a2, a3, a0].
void read_as_wxyz(Real* q) {
  Real w = q[0];
  q[0] = q[1], q[1] = q[2], q[2] = q[3], q[3] = std::move(w);
}
/// ... and writes [w, x, y, z] where [x, y, z, w] belongs.
void write_as_wxyz(Real* q) {
  Real w = q[3];
  q[3] = q[2], q[2] = q[1], q[1] = q[0], q[0] = std::move(w);
}

bool is_apply(const AbiOp& op) {
  return op.name == "apply_vector" || op.name == "apply_bivector" || op.name == "to_matrix" ||
         op.name == "dq_apply_point" || op.name == "skin_linear" || op.name == "skin_dual_quaternion";
}

std::vector<Convention> build() {
  const auto any = [](const Array&) { return true; };
  const auto quaternion_out = [](const Array& a) { return is_quaternion_output(a); };
  std::vector<Convention> all;

  all.push_back({"reverse_map",
                 "reverse quaternion-to-rotor map (R = w + x e23 + y e31 + z e12, the printed Method 2): "
                 "every quaternion in and out is the conjugate of the spec's",
                 [](const AbiOp& op) { return has_quaternion_input(op) || has_quaternion_output(op); },
                 [=](const AbiOp& op, const Values& in) { return each_quaternion(op.inputs, in, any, conjugate); },
                 [=](const AbiOp& op, const Values& out) {
                   return each_quaternion(op.outputs, out, quaternion_out, conjugate);
                 }});

  all.push_back({"inverse_sandwich",
                 "~R x R sandwich (v' = q* v q): vectors, matrices and points are rotated by the inverse",
                 [](const AbiOp& op) { return is_apply(op); },
                 [=](const AbiOp& op, const Values& in) { return each_quaternion(op.inputs, in, any, conjugate); },
                 [](const AbiOp&, const Values& out) { return out; }});

  all.push_back({"wxyz_order", "w-first storage: [w, x, y, z] where the ABI has [x, y, z, w]",
                 [](const AbiOp& op) { return has_quaternion_input(op) || has_quaternion_output(op); },
                 [=](const AbiOp& op, const Values& in) { return each_quaternion(op.inputs, in, any, read_as_wxyz); },
                 [=](const AbiOp& op, const Values& out) {
                   return each_quaternion(op.outputs, out, quaternion_out, write_as_wxyz);
                 }});

  all.push_back({"compose_reversed",
                 "compose(a, b) = b a (the JPL/Shuster product with ijk = +1, or the passive order)",
                 [](const AbiOp& op) { return op.name == "compose" || op.name == "dq_compose"; },
                 [](const AbiOp&, Values in) {
                   std::swap(in[0], in[1]);
                   return in;
                 },
                 [](const AbiOp&, const Values& out) { return out; }});

  const Real pi = ref::ScalarTraits<Real>::pi();
  all.push_back({"degrees", "angles in degrees where the spec has radians",
                 [](const AbiOp& op) {
                   for (const Array& a : op.inputs)
                     if (a.name == "angle") return true;
                   for (const Array& a : op.outputs)
                     if (a.name == "out_angle") return true;
                   return false;
                 },
                 [pi](const AbiOp& op, Values in) {
                   for (std::size_t a = 0; a < op.inputs.size(); ++a)
                     if (op.inputs[a].name == "angle")
                       for (Real& x : in[a]) x = x * pi / Real(180);
                   return in;
                 },
                 [pi](const AbiOp& op, Values out) {
                   for (std::size_t a = 0; a < op.outputs.size(); ++a)
                     if (op.outputs[a].name == "out_angle")
                       for (Real& x : out[a]) x = x * Real(180) / pi;
                   return out;
                 }});
  return all;
}

}  // namespace

const std::vector<Convention>& conventions() {
  static const std::vector<Convention> all = build();
  return all;
}

const Convention* find_convention(const std::string& id) {
  for (const Convention& c : conventions())
    if (c.id == id) return &c;
  return nullptr;
}

}  // namespace rotorcert::engine
