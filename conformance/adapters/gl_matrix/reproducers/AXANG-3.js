#!/usr/bin/env node
// rotorcert reproducer: gl-matrix, clause AXANG-3 (spec/SPEC.md 6, level Extended, tolerance eps16, loose bar 256 eps).
// AXANG-3: the angle alone, theta = 2 atan2(|v|, w) of AXANG-1 (an angle of the same rotation, 2 pi - theta
// or signed, is acceptable: the error is |rho(angle) - rho(theta)| with rho the angle in [0, pi]).
// gl-matrix has no angle-only call: its angle is the one quat.getAxisAngle returns, rad = 2 acos(q[3])
// (cjs/quat.js:112), computed in binary64 from the binary32 w. acos is flat at w = +-1, so near the
// identity and near a full turn the angle keeps only about half of its digits: a rotation 4.7e-4 rad
// short of 2 pi has w = -1 exactly in binary32 and reads 2 pi, the angle of -1 (3.9e3 eps). The AXANG-1
// defect (AXANG-1.js), met by the angle query alone.
// Upstream: toji/gl-matrix PR #502 (merged after 3.4.4) clamps the acos argument against NaN but keeps
// 2 acos(w); no report of the precision loss found (the same defect in GLM: g-truc/glm PR #946).
// Run: NODE_PATH=build/adapters/gl_matrix/node_modules node AXANG-3.js   (exit 0 shown, 1 not shown, 77 skip)
const CLAUSE = 'AXANG-3';
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

/** The angle in [0, pi] of the rotation by x about some axis (ACC-1 angle_range). */
const rho = (x) => 2 * Math.atan2(Math.abs(Math.sin(x / 2)), Math.abs(Math.cos(x / 2)));

// The suite's worst input (AXANG-3, near a full turn: 2 pi - 1e-9 .. 1e-1), [x, y, z, w] binary32.
const q = quat.fromValues(...['-0x1.e0db64p-13', '-0x1.a3d8d8p-15', '0x1.0df91ap-16', '-0x1p+0'].map(hx));
const angle = Math.fround(quat.getAxisAngle(vec3.create(), q));   // stored in binary32, as the adapter does
const theta = 2 * Math.atan2(Math.hypot(q[0], q[1], q[2]), q[3]);
const err = Math.abs(rho(angle) - rho(theta));
console.log(`rotorcert reproducer: gl-matrix ${VERSION} AXANG-3: quat.getAxisAngle's angle, 2 acos(w), reads 2 pi for a ` +
            `rotation ${(2 * Math.PI - theta).toExponential(2)} rad short of a full turn`);
console.log('  call:    angle = quat.getAxisAngle(vec3.create(), q)');
console.log(`  input:   q = ${show(q)}  (Float32Array [x, y, z, w]; |q| - 1 = ${(norm(Array.from(q)) - 1).toExponential(2)})`);
console.log(`  library: angle = ${hex(angle)} (${angle})`);
console.log(`  correct: angle = ${hex(theta)} (${theta})   2 atan2(|v|, w) (binary64 on the exact inputs, a few ulps)`);
console.log(`  error:   ${err.toExponential(3)} rad = ${(err / EPS).toExponential(3)} eps under any angle range (binary32, loose bar ${LOOSE} eps)`);
if (!(err <= LOOSE * EPS)) { console.log('DEFECT SHOWN'); process.exit(0); }
console.log('DEFECT NOT SHOWN'); process.exit(1);
