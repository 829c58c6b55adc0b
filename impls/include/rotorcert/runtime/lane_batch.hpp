// The batch function of an element op whose ordinary elements run in SIMD lanes: lane blocks by
// runtime/lane_blocks.hpp, and every element a lane does not take (its cheap tests failed, or it
// is one of the last n mod 4) by the element function through impl.hpp's Elementwise loop, so
// that the batch keeps the element function's outcomes, NaN poisoning of DOMAIN_ERROR included.
// For the ops of one or two inputs (and a parameter t) and one output array (normalize, compose,
// apply_vector, nlerp; dq_normalize, dq_compose, dq_from_rotation_translation, dq_apply_point), of
// AXIS-1's four (rotate_about_axis) and of the skinning shape (skin_linear, skin_dual_quaternion).
#pragma once

#include <cstddef>
#include <cstdint>

#include <rotorcert/impl.hpp>
#include <rotorcert/runtime/lane_blocks.hpp>

namespace rotorcert::runtime {

/// Two inputs of A and B scalars per element, Out output scalars; Kernel<S, L>::run(a, b).
template <template <class, std::size_t> class Kernel, auto Element, std::size_t A, std::size_t B, std::size_t Out,
          class S>
int lanes_or_element(std::size_t n, const S* a, const S* b, S* out, std::uint8_t* status) {
  using Checked = impl::detail::Elementwise<Element, decltype(Element)>;
  const auto element = [&](std::size_t e) { Checked::run(1, a + A * e, b + B * e, out + Out * e, status + e); };
  in_lanes_or_checked<Kernel>(n, a, A, b, B, [](auto& k, const S* x, const S* y) { k.run(x, y); },
                              copy_lane_outputs<Out>(out, status), element, element);
  return 0;
}

/// Two inputs of A scalars and one scalar per element (t of the interpolations), Out output
/// scalars; Kernel<S, L>::run(a, b, t).
template <template <class, std::size_t> class Kernel, auto Element, std::size_t A, std::size_t Out, class S>
int lanes_or_element(std::size_t n, const S* a, const S* b, const S* t, S* out, std::uint8_t* status) {
  using Checked = impl::detail::Elementwise<Element, decltype(Element)>;
  const auto element = [&](std::size_t e) { Checked::run(1, a + A * e, b + A * e, t + e, out + Out * e, status + e); };
  in_lanes_or_checked<Kernel>(n, a, A, b, A,
                              [a, t](auto& k, const S* x, const S* y) { k.run(x, y, t + (x - a) / A); },
                              copy_lane_outputs<Out>(out, status), element, element);
  return 0;
}

/// One input of A scalars per element, Out output scalars; Kernel<S, L>::run(a, unused).
template <template <class, std::size_t> class Kernel, auto Element, std::size_t A, std::size_t Out, class S>
int lanes_or_element(std::size_t n, const S* a, S* out, std::uint8_t* status) {
  using Checked = impl::detail::Elementwise<Element, decltype(Element)>;
  const auto element = [&](std::size_t e) { Checked::run(1, a + A * e, out + Out * e, status + e); };
  in_lanes_or_checked<Kernel>(n, a, A, a, 0, [](auto& k, const S* x, const S* y) { k.run(x, y); },
                              copy_lane_outputs<Out>(out, status), element, element);
  return 0;
}

/// Three inputs of A, B and P scalars and one scalar between them per element (rotate_about_axis:
/// centre, axis, angle, point), Out output scalars; Kernel<S, L>::run(a, b, t, p).
template <template <class, std::size_t> class Kernel, auto Element, std::size_t A, std::size_t B, std::size_t P,
          std::size_t Out, class S>
int lanes_or_element(std::size_t n, const S* a, const S* b, const S* t, const S* p, S* out, std::uint8_t* status) {
  using Checked = impl::detail::Elementwise<Element, decltype(Element)>;
  const auto element = [&](std::size_t e) {
    Checked::run(1, a + A * e, b + B * e, t + e, p + P * e, out + Out * e, status + e);
  };
  in_lanes_or_checked<Kernel>(
      n, a, A, b, B,
      [a, t, p](auto& k, const S* x, const S* y) {
        const std::size_t first = std::size_t(x - a) / A;
        k.run(x, y, t + first, p + P * first);
      },
      copy_lane_outputs<Out>(out, status), element, element);
  return 0;
}

/// The skinning shape (impl.hpp detail::skin: element e's k rotations at q + 4 k e, translations
/// at t + 3 k e, weights at w + k e, vertex at v + 3 e; 3 output scalars), for 1 <= k <= MaxK;
/// Kernel<S, L>::run(k, q, t, w, v) on the block's arrays. Other k: the element function for
/// every element.
template <template <class, std::size_t> class Kernel, auto Element, std::size_t MaxK, class S>
int skin_lanes_or_element(std::size_t n, std::size_t k, const S* q, const S* t, const S* w, const S* v, S* out,
                          std::uint8_t* status) {
  if (k == 0 || k > MaxK) return impl::detail::skin<Element, S>(n, k, q, t, w, v, out, status);
  const auto element = [&](std::size_t e) {
    impl::detail::skin<Element, S>(1, k, q + 4 * k * e, t + 3 * k * e, w + k * e, v + 3 * e, out + 3 * e, status + e);
  };
  in_lanes_or_checked<Kernel>(
      n, q, 4 * k, w, k,
      [k, w, t, v](auto& lanes, const S* qq, const S* ww) {
        const std::size_t first = std::size_t(ww - w) / k;
        lanes.run(k, qq, t + 3 * k * first, ww, v + 3 * first);
      },
      copy_lane_outputs<3>(out, status), element, element);
  return 0;
}

}  // namespace rotorcert::runtime
