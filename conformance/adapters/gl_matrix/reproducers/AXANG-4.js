#!/usr/bin/env node
// rotorcert reproducer: gl-matrix, clause AXANG-4 (spec/SPEC.md 6, level Extended, tolerance eps16: METRIC-3
// with s = 1, loose bar 256 eps). AXANG-4: the axis alone, u = v/|v| of AXANG-1; only the identity (v = 0)
// may have any axis (ACC-1 identity_axis), and -u is acceptable where w < 0. gl-matrix has no axis-only
// call: its axis is the one quat.getAxisAngle writes, v / sin(acos(w)), or [1, 0, 0] when sin(acos(w))
// <= glMatrix.EPSILON = 1e-6 (cjs/quat.js:112-122). In binary32 w = cos(theta/2) is exactly 1 for every
// rotation below about 4.9e-4 rad (and -1 within as much of a full turn), so sin(acos(w)) = 0 and the axis
// is [1, 0, 0] although x, y, z still hold it exactly; above that the axis is not unit. The AXANG-1 defect
// (AXANG-1.js), met by the axis query alone.
// Upstream: no report found in toji/gl-matrix (PR #502 clamps getAxisAngle's acos argument against NaN).
// Run: NODE_PATH=build/adapters/gl_matrix/node_modules node AXANG-4.js   (exit 0 shown, 1 not shown, 77 skip)
const CLAUSE = 'AXANG-4';
'use strict';
let glm, VERSION;
try { glm = require('gl-matrix'); VERSION = require('gl-matrix/package.json').version; } catch (e) {
  console.log(`rotorcert reproducer: gl-matrix ${CLAUSE}: SKIP, cannot load gl-matrix: ` + String(e.message).split('\n')[0]);
  process.exit(77);
}
const {glMatrix, quat, vec3} = glm;
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

// The suite's worst input (AXANG-4, angle sweep 1e-9 .. pi): a unit quaternion of a 2.7e-7 rad rotation.
const q = quat.fromValues(...['-0x1.1e7c72p-23', '0x1.62a12cp-28', '0x1.0bf11p-27', '0x1p+0'].map(hx));
const axis = vec3.create();
quat.getAxisAngle(axis, q);
const n = Math.hypot(q[0], q[1], q[2]), u = [q[0] / n, q[1] / n, q[2] / n];
const err = Math.hypot(...Array.from(axis, (c, i) => c - u[i]));
console.log(`rotorcert reproducer: gl-matrix ${VERSION} AXANG-4: quat.getAxisAngle's axis is [1, 0, 0] for a rotation of ` +
            `${(2 * Math.atan2(n, q[3])).toExponential(2)} rad (w = 1 in binary32)`);
console.log('  call:    quat.getAxisAngle(axis = vec3.create(), q); axis');
console.log(`  input:   q = ${show(q)}  (Float32Array [x, y, z, w]; |q| - 1 = ${(norm(Array.from(q)) - 1).toExponential(2)})`);
console.log(`  library: axis = ${show(axis)}`);
console.log(`  correct: axis = ${show(u)}   v/|v| (binary64 on the exact inputs)`);
console.log(`  error:   ${err.toExponential(3)} = ${(err / EPS).toExponential(3)} eps (METRIC-3; binary32, loose bar ${LOOSE} eps; w > 0: -u is no answer)`);
if (!(err <= LOOSE * EPS)) { console.log('DEFECT SHOWN'); process.exit(0); }
console.log('DEFECT NOT SHOWN'); process.exit(1);
