#!/usr/bin/env node
// rotorcert reproducer: gl-matrix, clause EDGE-6 (spec/SPEC.md 9, tolerance class outcome).
// EDGE-6: a zero quaternion and a zero axis (also with angle 0) are DOMAIN_ERROR: every output component
// a quiet NaN (or, for a library without a status channel, an exception). Since spec 2.2.0, ACC-1
// zero_sentinel also accepts status OK with every output component +-0, or exactly the identity's output
// (the zero quaternion replaced by (0, 0, 0, 1), a zero axis by +z at angle 0; for getAxisAngle angle 0
// about any unit axis). gl-matrix checks nothing, and three of its functions return finite values that are
// neither: quat.getAxisAngle of zero is the angle 2 acos(0) = pi about the zero axis (s = sin(pi/2) = 1
// passes its 's > EPSILON' test, so the axis is q.xyz / 1 = 0); quat.setAxisAngle of a zero axis is the
// non-unit (0, 0, 0, cos(rad/2)); quat.slerp of a zero quaternion mixes it in (EX-EDGE-6-g: slerp(0, b, 1/2)
// = [0, 0, 0.5, 0.5], not unit). (quat.normalize(0) = 0, quat.invert(0) = -0, mat3.fromQuat(0) = I,
// quat.multiply with 0, quat2.normalize and quat2.multiply of a zero real part are ACC-1 zero_sentinel /
// algebraic_product answers since 2.2.0 and no longer a defect.)
// Source (gl-matrix 3.4.4): cjs/quat.js:111-124 getAxisAngle, cjs/quat.js:88-95 setAxisAngle, cjs/quat.js:319-360
// slerp. Upstream tracker (github.com/toji/gl-matrix): no report found.
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

console.log(`rotorcert reproducer: gl-matrix ${VERSION} EDGE-6: getAxisAngle of a zero quaternion is pi about the zero ` +
            'axis, setAxisAngle of a zero axis and slerp of a zero quaternion are not unit: finite answers (status OK) ' +
            'that are neither a domain error nor an ACC-1 zero_sentinel');
let shown = false;
/** One call: out is the flat list of outputs; sentinel(out) says whether it is the identity's answer. */
function check(tag, call, input, out, identityAnswer, sentinel) {
  const flat = [].concat(...out.map((o) => (typeof o === 'number' ? [o] : Array.from(o))));
  const nonFinite = flat.every((c) => !Number.isFinite(c)), allZero = flat.every((c) => c === 0);
  const ok = nonFinite || allZero || sentinel(out);
  shown = shown || !ok;
  console.log(`\n[${tag}] call:    ${call}\n    input:   ${input}`);
  console.log(`    gl-matrix: ${out.map((o) => (typeof o === 'number' ? hex(o) : show(o))).join(' ')}` +
              `   -> ${ok ? 'DOMAIN_ERROR or an ACC-1 zero_sentinel' : 'a finite answer, status OK  <-- DEFECT'}`);
  console.log('    correct:   DOMAIN_ERROR (every component NaN); acceptable (ACC-1 zero_sentinel): every component 0, or ' +
              identityAnswer);
}
const zero = () => quat.fromValues(0, 0, 0, 0);
// 1. The suite's worst input: to_axis_angle q = [0x0p+0, 0x0p+0, 0x0p+0, 0x0p+0] (zero quaternion in q).
{
  const axis = vec3.create(), angle = Math.fround(quat.getAxisAngle(axis, zero()));   // stored as binary32 (the adapter's ABI output)
  check(1, 'angle = quat.getAxisAngle(axis = vec3.create(), q)', 'q = [0x0p+0, 0x0p+0, 0x0p+0, 0x0p+0]', [angle, axis],
        'the identity\'s: angle 0 about any unit axis',
        ([a, u]) => a === 0 && Math.abs(norm(Array.from(u)) - 1) <= LOOSE * EPS);
}
// 2. from_axis_angle with a zero axis (EX-AXANG-2-g, judged by EDGE-6 since spec 2.2.0).
{
  const angle = hx('0x1.921fb6p+0');                     // pi/2 rounded to binary32
  const q = quat.setAxisAngle(quat.create(), vec3.fromValues(0, 0, 0), angle);
  check(2, 'quat.setAxisAngle(quat.create(), axis, rad)', `axis = [0x0p+0, 0x0p+0, 0x0p+0], rad = ${hex(angle)}`, [q],
        'the identity [0, 0, 0, 1] (+z at angle 0)', ([r]) => r[0] === 0 && r[1] === 0 && r[2] === 0 && r[3] === 1);
}
// 3. slerp with a zero first quaternion (EX-EDGE-6-g); the identity's answer is slerp(1, b, t), the
//    rotation by 45 degrees about z, computed here in binary64 from the closed form.
{
  const h = hx('0x1.6a09e6p-1'), b = quat.fromValues(0, 0, h, h), t = 0.5;
  const q = quat.slerp(quat.create(), zero(), b, t);
  const half = Math.atan2(h, h) * t;                      // half-angle of b is 45 degrees; slerp(1, b, t) turns by t of it
  const ref = [0, 0, Math.sin(half), Math.cos(half)];
  check(3, 'quat.slerp(quat.create(), a, b, t)', `a = [0x0p+0, 0x0p+0, 0x0p+0, 0x0p+0], b = ${show(b)}, t = ${hex(t)}`, [q],
        `slerp(identity, b, t) = ${show(ref.map(Math.fround))}`,
        ([r]) => metric1(r, ref) <= LOOSE * EPS && normDefect(Array.from(r)) <= LOOSE * EPS);
}
if (shown) { console.log('\nDEFECT SHOWN'); process.exit(0); }
console.log('\nDEFECT NOT SHOWN'); process.exit(1);
