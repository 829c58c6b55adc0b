#!/usr/bin/env node
// rotorcert reproducer: gl-matrix, clause EDGE-5 (spec/SPEC.md 9, tolerance eps16, loose bar 256 eps).
// EDGE-5: a finite nonzero q means the rotation q/|q| at every scale, and an axis of any length its
// direction (AXANG-2). gl-matrix normalises nothing, and documents no unit input for mat3.fromQuat,
// quat.slerp, quat.getAxisAngle and quat.setAxisAngle (it does for vec3.transformQuat, quat.ln and
// quat2.fromRotationTranslation, which are not judged here): mat3.fromQuat builds 1 - 2(y^2 + z^2), ...
// from q as given (a non-unit q gives a scaled, sheared matrix; at 2^100 the products overflow binary32
// to +-inf); slerp combines the unnormalised inputs (its output has their norm, and its dot product
// exceeds 1); getAxisAngle takes acos of an unnormalised w (NaN when w > 1); setAxisAngle multiplies the
// axis as given. (quat.normalize, multiply, invert, exp and the quat2 functions pass at every scale:
// binary64 arithmetic between binary32 loads and stores neither overflows nor underflows there.)
// Source (gl-matrix 3.4.4): cjs/mat3.js:550 fromQuat, cjs/quat.js:319 slerp, :111 getAxisAngle, :88
// setAxisAngle. Upstream: toji/gl-matrix PR #502 (merged after 3.4.4) clamps getAxisAngle's acos argument
// (no NaN, still no normalisation); no report of the others found.
// Run: NODE_PATH=build/adapters/gl_matrix/node_modules node EDGE-5.js   (exit 0 shown, 1 not shown, 77 skip)
const CLAUSE = 'EDGE-5';
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

/** The 3x3 rotation matrix (column-major) of q/|q|, in binary64 (MAT-1 of the normalised q). */
function matrixOf(q) {
  const e = Math.floor(Math.log2(Math.max(...q.map(Math.abs)))), s = q.map((c) => c * 2 ** -e), n = norm(s);
  const [x, y, z, w] = s.map((c) => c / n);
  return [1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y),
          2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x),
          2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)];
}
const maxAbsDiff = (a, b) => Math.max(...Array.from(a, (c, i) => Math.abs(c - b[i])));   // METRIC-4 (NaN stays NaN)

console.log(`rotorcert reproducer: gl-matrix ${VERSION} EDGE-5: mat3.fromQuat, quat.slerp, quat.getAxisAngle and ` +
            'quat.setAxisAngle use non-unit quaternions and axes as given');
let worst = 0;
function report(tag, call, input, got, want, why, err) {
  worst = Math.max(worst, Number.isNaN(err) ? Infinity : err);
  console.log(`\n[${tag}] call:    ${call}\n    input:   ${input}`);
  console.log(`    gl-matrix: ${got}\n    correct:   ${want}   ${why}`);
  console.log(`    error:   ${Number.isNaN(err) ? 'NaN (above every bar)' : (err / EPS).toExponential(3) + ' eps'} (binary32, loose bar ${LOOSE} eps)`);
}
// 1. The suite's worst case (EDGE-5, non-unit scale 2^100).
{
  const q = quat.fromValues(...['-0x1.7819d6p+99', '0x1.2184d2p+97', '-0x1.3a1edap+99', '-0x1.c9be74p+99'].map(hx));
  const m = mat3.fromQuat(mat3.create(), q), want = matrixOf(Array.from(q));
  report(1, 'mat3.fromQuat(mat3.create(), q)', `q = ${show(q)}  (Float32Array [x, y, z, w])`, show(m), show(want),
         'the matrix of q/|q| (binary64)', maxAbsDiff(m, want));
}
// 2. A quarter turn about z, q = (0, 0, 1, 1) = sqrt(2) (0, 0, sin 45deg, cos 45deg).
{
  const q = quat.fromValues(0, 0, 1, 1), m = mat3.fromQuat(mat3.create(), q), want = matrixOf([0, 0, 1, 1]);
  report(2, 'mat3.fromQuat(mat3.create(), q)', `q = ${show(q)}  (a quarter turn about z, |q| = sqrt 2)`, show(m),
         show(want.map((c) => Math.round(c * 1e15) / 1e15)), 'column 0 = [0, 1, 0]: x turns into y (closed form)', maxAbsDiff(m, want));
}
// 3. slerp halfway from the identity to the quarter turn about z, both given at norm 2 and 2 sqrt 2.
{
  const a = quat.fromValues(0, 0, 0, 2), b = quat.fromValues(0, 0, 2, 2);
  const got = quat.slerp(quat.create(), a, b, 0.5);
  const want = [0, 0, Math.sin(Math.PI / 8), Math.cos(Math.PI / 8)];
  report(3, 'quat.slerp(quat.create(), a, b, 0.5)', `a = ${show(a)}  b = ${show(b)}  t = 0.5  (identity and quarter turn about z, not unit)`,
         `${show(got)}  (|out| = ${norm(Array.from(got)).toFixed(4)}, a ${metric1(got, [0, 0, 0, 1]).toFixed(4)} rad turn)`,
         show(want), '(0, 0, sin(pi/8), cos(pi/8)): the eighth turn, unit (closed form)', Math.max(metric1(got, want), normDefect(got)));
}
// 4. getAxisAngle of the same quarter turn given at norm 2 sqrt 2.
{
  const q = quat.fromValues(0, 0, 2, 2), axis = vec3.create(), angle = quat.getAxisAngle(axis, q);
  report(4, 'quat.getAxisAngle(axis = vec3.create(), q)', `q = ${show(q)}  (a quarter turn about z, not unit)`,
         `angle = ${hex(angle)}, axis = ${show(axis)}`, `angle = ${hex(Math.PI / 2)}, axis = [0x0p+0, 0x0p+0, 0x1p+0]`,
         '2 atan2(|v|, w) = pi/2 about z (closed form)', Math.max(Math.abs(Math.fround(angle) - Math.PI / 2), maxAbsDiff(axis, [0, 0, 1])));
}
// 5. setAxisAngle with an axis of length 2.
{
  const got = quat.setAxisAngle(quat.create(), vec3.fromValues(0, 0, 2), Math.fround(Math.PI / 2));
  const h = Math.fround(Math.PI / 2) / 2, want = [0, 0, Math.sin(h), Math.cos(h)];
  report(5, 'quat.setAxisAngle(quat.create(), axis, angle)', `axis = ${show([0, 0, 2])}  angle = ${hex(Math.fround(Math.PI / 2))}`,
         show(got), show(want), '(0, 0, sin(angle/2), cos(angle/2)): the axis direction, unit', Math.max(metric1(got, want), normDefect(got)));
}
if (!(worst <= LOOSE * EPS)) { console.log('\nDEFECT SHOWN'); process.exit(0); }
console.log('\nDEFECT NOT SHOWN'); process.exit(1);
