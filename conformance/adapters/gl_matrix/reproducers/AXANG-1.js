#!/usr/bin/env node
// rotorcert reproducer: gl-matrix, clause AXANG-1 (spec/SPEC.md 6, tolerance eps16, loose bar 256 eps).
// AXANG-1: theta = 2 atan2(|v|, w), u = v/|v|; implementations MUST NOT compute theta as 2 acos(w). gl-matrix
// (default glMatrix.ARRAY_TYPE Float32Array: binary32 storage, binary64 arithmetic) computes
// rad = 2 acos(q[3]): w = cos(theta/2) stored in binary32 is exactly 1 for every rotation below about
// 4.9e-4 rad, so the angle is 0 and, sin(0) being <= glMatrix.EPSILON, the axis is [1, 0, 0], although
// x, y, z still hold the rotation exactly. The result (0, [1, 0, 0]) is the identity: not an acceptable
// convention (ACC-1) for a quaternion that rotates by 1e-4 rad. The documentation promises the round trip
// with setAxisAngle ('this method will return the same values as providied in the original parameter
// list OR functionally equivalent values'); item 2 shows it lost.
// Source (gl-matrix 3.4.4): cjs/quat.js:112 'var rad = Math.acos(q[3]) * 2.0;', :114-122 the EPSILON axis.
// Upstream: toji/gl-matrix PR #502 (merged after 3.4.4) clamps the acos argument against NaN but keeps
// 2 acos(w); no report of the small-angle loss found (the same defect in GLM: g-truc/glm PR #946).
// Run: NODE_PATH=build/adapters/gl_matrix/node_modules node AXANG-1.js   (exit 0 shown, 1 not shown, 77 skip)
const CLAUSE = 'AXANG-1';
'use strict';
let glm, VERSION;
try { glm = require('gl-matrix'); VERSION = require('gl-matrix/package.json').version; } catch (e) {
  console.log(`rotorcert reproducer: gl-matrix ${CLAUSE}: SKIP, cannot load gl-matrix: ` + String(e.message).split('\n')[0]);
  process.exit(77);
}
const {glMatrix, quat, quat2, vec3, mat3, mat4} = glm;
if (glMatrix.ARRAY_TYPE !== Float32Array) throw new Error('gl-matrix ARRAY_TYPE is not its default Float32Array');
/** Exact C99 %a-style hexfloat of a double (sign, 52-bit mantissa and exponent from its bits); a binary32
 *  value prints as its exact binary64 value, as C's printf("%a", (double)f) does. */
function hex(x) {
  if (Number.isNaN(x)) return 'nan';
  if (!Number.isFinite(x)) return x > 0 ? 'inf' : '-inf';
  const dv = new DataView(new ArrayBuffer(8)); dv.setFloat64(0, x);
  const hi = dv.getUint32(0), lo = dv.getUint32(4), sign = hi >>> 31 ? '-' : '', field = (hi >>> 20) & 0x7ff;
  const mant = ((hi & 0xfffff).toString(16).padStart(5, '0') + lo.toString(16).padStart(8, '0')).replace(/0+$/, '');
  if (field === 0 && !mant) return sign + '0x0p+0';
  const e = field === 0 ? -1022 : field - 1023;           // subnormals: 0x0.<mantissa>p-1022
  return sign + (field === 0 ? '0x0.' : mant ? '0x1.' : '0x1') + mant + 'p' + (e < 0 ? '' : '+') + e;
}
/** The double of an exact hexfloat literal ('-0x1.b2b4ed0c8b8ffp-3', 'inf'); checked to print back. */
function hx(s) {
  if (s === 'inf' || s === '-inf') return s[0] === '-' ? -Infinity : Infinity;
  const m = /^(-?)0x([01])\.?([0-9a-f]*)p([+-]\d+)$/.exec(s);
  let x = (m[1] ? -1 : 1) * Number(BigInt('0x' + m[2] + m[3])), k = Number(m[4]) - 4 * m[3].length;
  for (; k !== 0; k -= Math.sign(k) * Math.min(Math.abs(k), 1000)) x *= 2 ** (Math.sign(k) * Math.min(Math.abs(k), 1000));
  if (hex(x) !== s) throw new Error('hexfloat ' + s + ' read as ' + hex(x));
  return x;
}
const show = (v) => '[' + Array.from(v, hex).join(', ') + ']';   // also for a Float32Array
const EPS = 2 ** -23, LOOSE = 256;   // binary32 eps: gl-matrix stores binary32
const norm = (v) => Math.hypot(...v);
/** spec METRIC-1: 4 atan2(min(|a-b|, |a+b|), max(...)) of the normalised quaternions (rotation angle). */
function metric1(a, b) {
  a = Array.from(a); b = Array.from(b);                   // binary64 from here on
  const na = norm(a), nb = norm(b), u = a.map((c) => c / na), w = b.map((c) => c / nb);
  const dm = Math.hypot(...u.map((c, i) => c - w[i])), dp = Math.hypot(...u.map((c, i) => c + w[i]));
  return 4 * Math.atan2(Math.min(dm, dp), Math.max(dm, dp));
}
/** spec METRIC-6: | |q| - 1 | of q = [x, y, z, w], as ((w-1)(w+1) + x^2 + y^2 + z^2)/(|q| + 1) (no cancellation). */
const normDefect = (q) => Math.abs((q[3] - 1) * (q[3] + 1) + q[0] ** 2 + q[1] ** 2 + q[2] ** 2) / (norm(q) + 1);

/** AXANG-1 in binary64 on the exact binary32 inputs: theta = 2 atan2(|v|, w), u = v/|v|. */
function axisAngle(q) {
  const n = Math.hypot(q[0], q[1], q[2]);
  return {angle: 2 * Math.atan2(n, q[3]), axis: [q[0] / n, q[1] / n, q[2] / n]};
}
/** The rotation (cos(theta/2), sin(theta/2) u) of an angle and axis, [x, y, z, w]. */
const rotationOf = (angle, axis) => [...Array.from(axis, (c) => Math.sin(angle / 2) * c), Math.cos(angle / 2)];

console.log(`rotorcert reproducer: gl-matrix ${VERSION} AXANG-1: quat.getAxisAngle takes 2 acos(w): in binary32 a rotation ` +
            'below 4.9e-4 rad has w = 1, and comes back as angle 0 about [1, 0, 0]');
let worst = 0;
function check(tag, call, q) {
  const axis = vec3.create();
  const angle = quat.getAxisAngle(axis, q);
  const want = axisAngle(q);
  const eAngle = Math.abs(Math.fround(angle) - want.angle);
  const eAxis = Math.hypot(...Array.from(axis, (c, i) => c - want.axis[i]));
  const err = Math.max(eAngle, eAxis);
  worst = Math.max(worst, err);
  console.log(`\n[${tag}] call:    ${call}`);
  console.log(`    input:   q = ${show(q)}  (Float32Array [x, y, z, w]; |q| - 1 = ${(norm(Array.from(q)) - 1).toExponential(2)})`);
  console.log(`    gl-matrix: angle = ${hex(angle)} (${angle}), axis = ${show(axis)}`);
  console.log(`    correct:   angle = ${hex(want.angle)} (${want.angle.toExponential(8)}), axis = ${show(want.axis)}` +
              '   2 atan2(|v|, w), v/|v| (binary64 on the exact inputs, a few ulps)');
  console.log(`    error:   angle ${eAngle.toExponential(3)} rad, axis ${eAxis.toExponential(3)}: ${(err / EPS).toExponential(3)} eps ` +
              `(binary32, loose bar ${LOOSE} eps); as a rotation, the answer is ${metric1(rotationOf(angle, axis), q).toExponential(3)} rad ` +
              `(${(metric1(rotationOf(angle, axis), q) / EPS).toFixed(0)} eps) from q`);
}
// 1. The suite's worst case (AXANG-1, angle sweep 1e-9 .. pi): a unit quaternion of a 9.73e-5 rad rotation.
check(1, 'quat.getAxisAngle(axis = vec3.create(), q)',
      quat.fromValues(...['-0x1.9126ap-15', '0x1.c850c8p-18', '-0x1.8b44dp-18', '0x1p+0'].map(hx)));
// 2. The documented round trip: setAxisAngle([0, 0, 1], 1e-4), then getAxisAngle.
check(2, 'q = quat.setAxisAngle(quat.create(), [0, 0, 1], 1e-4); quat.getAxisAngle(axis, q)',
      quat.setAxisAngle(quat.create(), [0, 0, 1], 1e-4));
if (!(worst <= LOOSE * EPS)) { console.log('\nDEFECT SHOWN'); process.exit(0); }
console.log('\nDEFECT NOT SHOWN'); process.exit(1);
