#!/usr/bin/env node
// rotorcert reproducer: gl-matrix, clause EDGE-6 (spec/SPEC.md 9, tolerance class outcome).
// EDGE-6: a zero quaternion, a dual quaternion whose real part is zero and a zero axis are DOMAIN_ERROR:
// every output component a quiet NaN (or, for a library without a status channel, an exception).
// gl-matrix checks nothing and returns ordinary finite values: quat.normalize multiplies by len = 0
// (vec4.normalize: 'if (len > 0)' skips the 1/sqrt); quat.invert uses invDot = 0 for a zero dot; mat3.fromQuat
// of zero is the identity; getAxisAngle of zero is the angle pi about [0, 0, 0]; quat2.normalize of a zero
// real part writes nothing, so its receiving quat2.create() stays the identity.
// Source (gl-matrix 3.4.4): cjs/vec4.js:405-417 normalize, cjs/quat.js:391 invert ('var invDot = dot ? 1.0 / dot
// : 0;' with its '// TODO: Would be faster to return [0,0,0,0] immediately if dot == 0'), cjs/mat3.js:550,
// cjs/quat.js:111, cjs/quat2.js:801-803 ('if (magnitude > 0)'). Upstream tracker (github.com/toji/gl-matrix):
// no report found.
// Run: NODE_PATH=build/adapters/gl_matrix/node_modules node EDGE-6.js   (exit 0 shown, 1 not shown, 77 skip)
const CLAUSE = 'EDGE-6';
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

console.log(`rotorcert reproducer: gl-matrix ${VERSION} EDGE-6: zero quaternions and zero real parts give ordinary ` +
            'finite results (status OK) instead of a domain error');
let shown = false;
function check(tag, call, input, fn) {
  let out, threw = null;
  try { out = fn(); } catch (e) { if (e instanceof TypeError || e instanceof ReferenceError) throw e; threw = e; }
  const flat = threw ? [] : [].concat(...out.map((o) => (typeof o === 'number' ? [o] : Array.from(o))));
  const domainError = threw !== null || flat.every(Number.isNaN);
  shown = shown || !domainError;
  console.log(`\n[${tag}] call:    ${call}\n    input:   ${input}`);
  console.log(`    gl-matrix: ${threw ? 'throws ' + threw.constructor.name : out.map((o) => (typeof o === 'number' ? hex(o) : show(o))).join(' ')}` +
              `   -> ${domainError ? 'DOMAIN_ERROR' : 'an ordinary result (status OK)'}`);
  console.log('    correct:   DOMAIN_ERROR (every component NaN, or an exception)');
}
const zero = () => quat.fromValues(0, 0, 0, 0);
// EX-EDGE-6-a of the spec (the suite's worst case), then the other functions the suite found.
check(1, 'quat.normalize(quat.create(), q)', 'q = [0x0p+0, 0x0p+0, 0x0p+0, 0x0p+0]', () => [quat.normalize(quat.create(), zero())]);
check(2, 'quat.invert(quat.create(), q)', 'q = [0x0p+0, 0x0p+0, 0x0p+0, 0x0p+0]', () => [quat.invert(quat.create(), zero())]);
check(3, 'mat3.fromQuat(mat3.create(), q)', 'q = [0x0p+0, 0x0p+0, 0x0p+0, 0x0p+0]', () => [mat3.fromQuat(mat3.create(), zero())]);
check(4, 'angle = quat.getAxisAngle(axis = vec3.create(), q)', 'q = [0x0p+0, 0x0p+0, 0x0p+0, 0x0p+0]', () => {
  const axis = vec3.create(); const angle = quat.getAxisAngle(axis, zero()); return [angle, axis];
});
check(5, 'quat2.normalize(quat2.create(), d)', 'd = [0x0p+0, 0x0p+0, 0x0p+0, 0x0p+0, 0x1p+0, 0x0p+0, 0x0p+0, 0x0p+0] (EX-EDGE-6-j: zero real part)',
      () => [quat2.normalize(quat2.create(), quat2.fromValues(0, 0, 0, 0, 1, 0, 0, 0))]);
if (shown) { console.log('\nDEFECT SHOWN'); process.exit(0); }
console.log('\nDEFECT NOT SHOWN'); process.exit(1);
