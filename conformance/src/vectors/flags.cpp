#include <rotorcert/vectors/flags.hpp>

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace rotorcert::vectors {
namespace {

// The vocabulary, in the order flags are listed on a vector.
const std::vector<std::pair<std::string, std::string>>& vocabulary() {
  static const std::vector<std::pair<std::string, std::string>> v = {
      {"WorkedExample", "The inputs of a worked example of the spec (spec/examples.json), rounded to the format."},
      {"Random", "Ordinary random inputs: uniform rotations, vectors of length 1e-3..1e3, t in [0, 1], positive weights."},
      {"RoundTrip", "exp(log q) = q through the implementation (EXP-2): call log, feed its output to exp."},
      {"Identity", "Identity rotations (and the zero log vector, the identity matrix): results are defined exactly (EDGE-1)."},
      {"SmallAngle", "Rotation angles or angles between the inputs of 1e-9..1e-3 rad: cancellation in acos / sin(x)/x (EDGE-2)."},
      {"AngleNear2Pi", "Rotation angles in (2 pi - 1, 2 pi), i.e. w < -cos(1/2): the branch of the angle (AXANG-1)."},
      {"AngleSweep", "Rotation angles (or pair distances) from a logarithmic sweep over 1e-9..pi, every decade sampled (LEVEL-1)."},
      {"NearFullTurn", "Rotation angles 1e-9..1e-1 short of 2 pi: w near -1, where log, axis-angle and matrix extraction lose accuracy."},
      {"NearAntipodal", "b = -a rotated by 1e-9..1e-1 rad: the hemisphere rule flips and the interpolation is short."},
      {"NearIdentical", "b = a rotated by 2^-1 .. 2^-(p+2) rad: every scale of the format between the pair."},
      {"UnequalScales", "Influences scaled by different powers of two: each means its normalised rotation or motion (EDGE-5)."},
      {"NearHalfTurn", "Rotation matrices of angles within 1e-3 of pi: trace-based extraction loses accuracy (MAT-2)."},
      {"HemisphereTie", "Two quaternions whose dot product is exactly 0: the tie of the hemisphere rule (EDGE-3)."},
      {"Antipodal", "b = -a exactly: the same rotation, the interpolation must be constant (EDGE-3)."},
      {"Negated", "Every quaternion input negated: the double cover, results must describe the same rotation (EDGE-4)."},
      {"Endpoint", "t = 0 or t = 1: interpolation must return the end rotations (SLERP-3)."},
      {"TOutsideUnitInterval", "t in [-1, 0) or (1, 2]: extrapolation along the same great arc (SLERP-4)."},
      {"TSweep", "t = j/8 for j = 0..8 on one pair of rotations: constant angular velocity (SLERP-5)."},
      {"ObtusePair", "a.b < 0: the hemisphere rule must interpolate from a to -b, the shorter arc (SLERP-2, SLERP-5)."},
      {"NonUnit", "Quaternion inputs scaled by a power of two away from unit length (NORM-1, EDGE-5)."},
      {"HugeScale", "Non-unit inputs so large that |q|^2 overflows the format: needs scaled normalisation (EDGE-5)."},
      {"TinyScale", "Non-unit inputs so small that |q|^2 underflows the format: needs scaled normalisation (EDGE-5)."},
      {"UnbalancedScale", "Factors at opposite ends of the format: |a| overflows it, b is scaled down as far, the product is of order 1 (COMPOSE-1, EDGE-5)."},
      {"Subnormal", "Components that are subnormal in the format: a naive |q|^2 underflows to 0 (EDGE-8)."},
      {"SubnormalAxis", "A subnormal vector part beside w = +-1: the axis v/|v| must come from a rescaled v (EDGE-8, LOG-1)."},
      {"NegativeZero", "Components equal to -0."},
      {"NegativeReal", "Quaternions with w < 0 and a zero vector part, e.g. -1: the branch of the log (LOG-2); dual quaternions whose real part is -1 (DQ-8's branch cut)."},
      {"PureTranslation", "A dual vector without rotation part (xi_r = 0): its exponential is the translation by 2 xi_d, exactly (DQ-9)."},
      {"LargeAngle", "A rotation part beyond a half turn of the rotor, |xi_r| in (pi, 3 pi): exp has no range restriction (DQ-9, as EXP-1)."},
      {"ZeroQuaternion", "A quaternion input equal to 0: outside the domain, DOMAIN_ERROR with NaN outputs (EDGE-6)."},
      {"ZeroRealPart", "A dual quaternion whose real part is 0: outside the domain (EDGE-6)."},
      {"ZeroAxis", "A rotation axis equal to 0 (AXANG-2, AXIS-1): no direction, outside the domain even for angle 0 (EDGE-6)."},
      {"NaN", "A NaN among the inputs: DOMAIN_ERROR with NaN outputs (EDGE-7, EDGE-9)."},
      {"Infinity", "An infinity among the inputs: DOMAIN_ERROR with NaN outputs (EDGE-7, EDGE-9)."},
      {"Reflection", "A matrix with det < 0: no rotation is near it, DOMAIN_ERROR (MAT-3)."},
      {"NonOrthogonalMatrix", "A rotation matrix perturbed by 1e-6..1e-2: the nearest rotation is returned (MAT-3)."},
      {"SpreadSingularValues", "A matrix U diag(2^a, 2^b, +-2^c) V^T with exponents anywhere in the format: a polar iteration that forms the inverse overflows, a determinant of the matrix scaled as a whole underflows; the status (det sign decidable) and a unit result are judged (MAT-3)."},
      {"DegenerateWeights", "A weight set outside the domain of blending (EDGE-9): see the specific flag."},
      {"NegativeWeight", "A negative weight (EDGE-9)."},
      {"ZeroWeights", "Every weight 0 (EDGE-9)."},
      {"NoInfluences", "k = 0 influences (EDGE-9)."},
      {"ZeroFirstWeight", "The first weight is 0: the pivot of the hemisphere rule is the first influence of positive weight."},
      {"SingleInfluence", "One influence of weight 1: skinning must reproduce the rigid motion (SKIN-3)."},
      {"EqualInfluences", "Several influences with the same rotation and translation: skinning must reproduce it (SKIN-3)."},
  };
  return v;
}

}  // namespace

std::vector<std::string> sorted_flags(std::vector<std::string> f) {
  if (f.empty()) throw std::logic_error("a test case without flags: its family in conformance/src/engine/cases.cpp must set them");
  const auto& v = vocabulary();
  auto rank = [&](const std::string& name) {
    const auto it = std::find_if(v.begin(), v.end(), [&](const auto& p) { return p.first == name; });
    if (it == v.end())
      throw std::logic_error("the test-vector flag \"" + name + "\" is not in the vocabulary (conformance/src/vectors/flags.cpp)");
    return it - v.begin();
  };
  for (const std::string& name : f) (void)rank(name);
  std::sort(f.begin(), f.end(), [&](const std::string& a, const std::string& b) { return rank(a) < rank(b); });
  f.erase(std::unique(f.begin(), f.end()), f.end());
  return f;
}

const std::map<std::string, std::string>& flag_docs() {
  static const std::map<std::string, std::string> m(vocabulary().begin(), vocabulary().end());
  return m;
}

}  // namespace rotorcert::vectors
