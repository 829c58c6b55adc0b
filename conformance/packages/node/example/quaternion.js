'use strict';
/* A small quaternion library in JavaScript numbers (binary64): the library a maintainer certifies in
 * this example. Quaternions are [x, y, z, w] arrays, vectors [x, y, z] (the ABI's layouts, LAYOUT-1),
 * Hamilton product, compose(a, b) = a b applies b first, active rotation v' = q v q*.
 *
 * Every function refuses what is not a rotation (a zero, NaN or infinite quaternion, a non-finite
 * vector or t) with a RangeError: rotorcert grades that as DOMAIN_ERROR (RESULT-2, EDGE-6, EDGE-7).
 *
 * ROTORCERT_EXAMPLE_DEFECT plants a defect, for the test that the certificate catches it:
 *   compose_reversed   compose returns b a (the JPL order): COMPOSE-1 must FAIL
 *   typo               compose calls a function that does not exist: the subtest of COMPOSE-1 must
 *                      fail naming the vector and its input */

const VERSION = '1.0';
const DEFECT = process.env.ROTORCERT_EXAMPLE_DEFECT || '';

function finite(xs) { return xs.every((x) => Number.isFinite(x)); }

function checkRotation(q) {
  if (!finite(q) || q.every((c) => c === 0)) throw new RangeError(`not a rotation: [${q.join(', ')}]`);
}

/** x 2^n with one rounding (C's scalbn; musl's steps keep every intermediate exact). */
function ldexp(x, n) {
  if (n > 1023) {
    x *= 2 ** 1023; n -= 1023;
    if (n > 1023) { x *= 2 ** 1023; n -= 1023; if (n > 1023) n = 1023; }
  } else if (n < -1022) {  // stop 53 short of the subnormal range: the last step rounds once
    x *= 2 ** -1022 * 2 ** 53; n += 1022 - 53;
    if (n < -1022) { x *= 2 ** -1022 * 2 ** 53; n += 1022 - 53; if (n < -1022) n = -1022; }
  }
  return x * 2 ** n;
}

/** q 2^-e with 2^e near max |q_i|, and e: |q|^2 then neither overflows nor underflows (NORM-1). */
function scaled(q) {
  const e = Math.floor(Math.log2(Math.max(...q.map(Math.abs)))) + 1;
  return [q.map((c) => ldexp(c, -e)), e];
}

/** q / |q| (NORM-1). */
function normalize(q) {
  checkRotation(q);
  const [s] = scaled(q);
  const n = Math.sqrt(s.reduce((acc, c) => acc + c * c, 0));
  return s.map((c) => c / n);
}

function hamilton(a, b) {
  const [ax, ay, az, aw] = a, [bx, by, bz, bw] = b;
  return [aw * bx + ax * bw + ay * bz - az * by,
          aw * by - ax * bz + ay * bw + az * bx,
          aw * bz + ax * by - ay * bx + az * bw,
          aw * bw - ax * bx - ay * by - az * bz];
}

/** a b: b is applied first (COMPOSE-1); not normalised. */
function compose(a, b) {
  checkRotation(a);
  checkRotation(b);
  if (DEFECT === 'compose_reversed') return hamilton(b, a);
  if (DEFECT === 'typo') return hamiltonian(a, b);  // eslint-disable-line no-undef -- the planted defect
  return hamilton(a, b);
}

/** q* / |q|^2 (INV-1), scaled so that |q|^2 stays in range. */
function inverse(q) {
  checkRotation(q);
  const [s, e] = scaled(q);
  const n2 = s.reduce((acc, c) => acc + c * c, 0);
  return [-s[0], -s[1], -s[2], s[3]].map((c) => ldexp(c / n2, -e));
}

function cross(u, v) {
  return [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
}

/** q v q* of the normalised q (APPLY-1): v + 2w (u x v) + 2 u x (u x v). */
function applyVector(q, v) {
  checkRotation(q);
  if (!finite(v)) throw new RangeError(`not a vector: [${v.join(', ')}]`);
  const [x, y, z, w] = normalize(q);
  const u = [x, y, z];
  const t = cross(u, v).map((c) => 2 * c);
  const ut = cross(u, t);
  return [0, 1, 2].map((i) => v[i] + w * t[i] + ut[i]);
}

/** a (a^-1 b')^t with b' = -b when a.b < 0 (SLERP-1), for unit a and b: sin((1-t) theta)/sin(theta) a
 *  + sin(t theta)/sin(theta) b', theta the angle between a and b' as 4-vectors, taken as
 *  2 atan2(|a - b'|, |a + b'|), which stays accurate for nearly equal and nearly opposite pairs. */
function slerp(a, b, t) {
  checkRotation(a);
  checkRotation(b);
  if (!Number.isFinite(t)) throw new RangeError(`t is not finite: ${t}`);
  if (a.reduce((acc, c, i) => acc + c * b[i], 0) < 0) b = b.map((c) => -c);  // flip iff a.b < 0 strictly
  const diff = Math.sqrt(a.reduce((acc, c, i) => acc + (c - b[i]) ** 2, 0));
  const total = Math.sqrt(a.reduce((acc, c, i) => acc + (c + b[i]) ** 2, 0));
  const theta = 2 * Math.atan2(diff, total);
  let wa = 1 - t, wb = t;
  if (theta !== 0) {
    const s = Math.sin(theta);
    wa = Math.sin((1 - t) * theta) / s;
    wb = Math.sin(t * theta) / s;
  }
  return a.map((c, i) => wa * c + wb * b[i]);
}

module.exports = {VERSION, normalize, compose, inverse, applyVector, slerp};
