#!/usr/bin/env node
// rotorcert reproducer: gl-matrix, clause EDGE-8 (spec/SPEC.md 9, tolerance eps4, loose bar 64 eps).
// EDGE-8: subnormal components are ordinary nonzero values and the quaternion means the rotation q/|q|.
// With binary32 storage and binary64 arithmetic, quat.normalize handles them (the binary64 squares of
// binary32 subnormals do not underflow), but the functions that never normalise keep the tiny scale:
// quat.slerp of two subnormal quaternions returns a subnormal quaternion, not a unit one, and mat3.fromQuat
// computes 1 - 2(y^2 + z^2) with squares near 2^-280, which round to the identity matrix in binary32
// although q denotes a half turn (w = -0). gl-matrix documents no unit input for either (see EDGE-5.js).
// Source (gl-matrix 3.4.4): cjs/quat.js:319-372 slerp, cjs/mat3.js:550 fromQuat. Upstream tracker
// (github.com/toji/gl-matrix): no report found.
// Run: NODE_PATH=build/adapters/gl_matrix/node_modules node EDGE-8.js   (exit 0 shown, 1 not shown, 77 skip)
const CLAUSE = 'EDGE-8';
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

/** q/|q| in binary64, scaled by a power of two first (exact). */
function normalized(q) {
  const e = Math.floor(Math.log2(Math.max(...q.map(Math.abs)))), s = q.map((c) => c * 2 ** -e), n = norm(s);
  return s.map((c) => c / n);
}
/** The spec's slerp in binary64 on normalised inputs (hemisphere rule, W = 2 atan2(|a-b'|, |a+b'|)). */
function slerpRef(a, b, t) {
  const u = normalized(a);
  let w = normalized(b);
  if (u.reduce((s, c, i) => s + c * w[i], 0) < 0) w = w.map((c) => -c);
  const om = 2 * Math.atan2(Math.hypot(...u.map((c, i) => c - w[i])), Math.hypot(...u.map((c, i) => c + w[i])));
  const s0 = Math.sin((1 - t) * om) / Math.sin(om), s1 = Math.sin(t * om) / Math.sin(om);
  return u.map((c, i) => s0 * c + s1 * w[i]);
}
/** The 3x3 rotation matrix (column-major) of q/|q|, binary64. */
function matrixOf(q) {
  const [x, y, z, w] = normalized(q);
  return [1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y),
          2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x),
          2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)];
}

console.log(`rotorcert reproducer: gl-matrix ${VERSION} EDGE-8: quat.slerp and mat3.fromQuat of subnormal quaternions ` +
            'keep the subnormal scale: a tiny slerp result, and the identity matrix for a half turn');
let worst = 0;
// 1. The suite's worst case (EDGE-8, subnormal and -0 components), slerp.
{
  const a = ['-0x0p+0', '0x1.8p-144', '0x1p-146', '0x1p-145'].map(hx), b = ['-0x0p+0', '0x1p-149', '0x1.8p-137', '0x1.4p-138'].map(hx);
  const t = hx('0x1.8a8064p-4');
  const got = quat.slerp(quat.create(), quat.fromValues(...a), quat.fromValues(...b), t), want = slerpRef(a, b, t);
  const err = Math.max(metric1(got, want), normDefect(got));
  worst = Math.max(worst, err);
  console.log(`\n[1] call:    quat.slerp(quat.create(), a, b, t)\n    input:   a = ${show(a)}  b = ${show(b)}  t = ${hex(t)}`);
  console.log(`    gl-matrix: ${show(got)}\n    correct:   ${show(want)}   slerp of a/|a| and b/|b|, unit (binary64)`);
  console.log(`    error:   METRIC-1 ${metric1(got, want).toExponential(3)} rad, METRIC-6 ${normDefect(got).toExponential(3)}: ` +
              `${(err / EPS).toExponential(3)} eps (binary32, loose bar 64 eps)`);
}
// 2. The suite's worst to_matrix case of EDGE-8.
{
  const q = ['0x1p-137', '0x1p-148', '0x1.8p-140', '-0x0p+0'].map(hx);
  const got = mat3.fromQuat(mat3.create(), quat.fromValues(...q)), want = matrixOf(q);
  const err = Math.max(...Array.from(got, (c, i) => Math.abs(c - want[i])));
  worst = Math.max(worst, err);
  console.log(`\n[2] call:    mat3.fromQuat(mat3.create(), q)\n    input:   q = ${show(q)}  (w = -0: a half turn)`);
  console.log(`    gl-matrix: ${show(got)}\n    correct:   ${show(want)}   the half turn of q/|q| (binary64)`);
  console.log(`    error:   METRIC-4 ${err.toExponential(3)}: ${(err / EPS).toExponential(3)} eps (binary32, loose bar 128 eps of MAT-1)`);
}
if (!(worst <= 64 * EPS)) { console.log('\nDEFECT SHOWN'); process.exit(0); }
console.log('\nDEFECT NOT SHOWN'); process.exit(1);
