#!/usr/bin/env node
// rotorcert reproducer: gl-matrix, clause EDGE-2 (spec/SPEC.md 9, tolerance eps16, loose bar 256 eps).
// EDGE-2: for rotation angles from 1e-9 to 1e-3 rad every op stays within its class; acos-based angles fail
// here. quat.getAxisAngle computes 2 acos(w) (see AXANG-1.js): with binary32 storage (gl-matrix's default
// Float32Array) w is exactly 1 for every rotation below about 4.9e-4 rad, so the small-angle family comes
// back as angle 0 about the axis [1, 0, 0]. Every other op of the adapter (multiply, normalize, ln, exp,
// slerp, mat3.fromQuat, fromMat3, setAxisAngle, transformQuat) passes EDGE-2.
// Source (gl-matrix 3.4.4): cjs/quat.js:112 'var rad = Math.acos(q[3]) * 2.0;', :114-122.
// Upstream: toji/gl-matrix PR #502 (acos clamped against NaN, merged after 3.4.4) keeps 2 acos(w); no report
// of the small-angle loss found.
// Run: NODE_PATH=build/adapters/gl_matrix/node_modules node EDGE-2.js   (exit 0 shown, 1 not shown, 77 skip)
const CLAUSE = 'EDGE-2';
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

// The suite's worst case (EDGE-2, angle 1e-9 .. 1e-3): a unit quaternion of a 9.97e-5 rad rotation.
const q = quat.fromValues(...['-0x1.a08bc6p-15', '-0x1.d19e82p-19', '-0x1.493176p-19', '0x1p+0'].map(hx));
const axis = vec3.create();
const angle = quat.getAxisAngle(axis, q);
const want = axisAngle(q);
const eAngle = Math.abs(Math.fround(angle) - want.angle);
const eAxis = Math.hypot(...Array.from(axis, (c, i) => c - want.axis[i]));
const err = Math.max(eAngle, eAxis);
console.log(`rotorcert reproducer: gl-matrix ${VERSION} EDGE-2: quat.getAxisAngle of a ${want.angle.toExponential(2)} rad ` +
            'rotation returns angle 0 about [1, 0, 0] (2 acos(w) with w = 1 in binary32)');
console.log('call:    quat.getAxisAngle(axis = vec3.create(), q)');
console.log(`input:   q = ${show(q)}  (Float32Array [x, y, z, w], unit within binary32 rounding)`);
console.log(`gl-matrix: angle = ${hex(angle)}, axis = ${show(axis)}`);
console.log(`correct:   angle = ${hex(want.angle)} (${want.angle.toExponential(8)}), axis = ${show(want.axis)}` +
            '   2 atan2(|v|, w), v/|v| (binary64 on the exact inputs)');
console.log(`error:   angle ${eAngle.toExponential(3)} rad, axis ${eAxis.toExponential(3)}: ${(err / EPS).toExponential(3)} eps ` +
            `(binary32, loose bar ${LOOSE} eps)`);
if (!(err <= LOOSE * EPS)) { console.log('DEFECT SHOWN'); process.exit(0); }
console.log('DEFECT NOT SHOWN'); process.exit(1);
