#!/usr/bin/env node
// rotorcert reproducer: gl-matrix, clause EDGE-7 (spec/SPEC.md 9, tolerance class outcome).
// EDGE-7: NaN or +-Inf in any input component is DOMAIN_ERROR with every output a quiet NaN; since spec 2.7.0
// ACC-1 nonfinite_propagation also accepts status OK with at least one output component NaN or +-Inf (the
// input's NaN carried into the result by IEEE arithmetic), or all zero where zero is no answer. What stays a
// defect is an all-finite answer to a non-finite input: nothing in it shows the input was not a number.
// gl-matrix checks nothing, and quat2.normalize(out, a) gives such an answer: it writes out only if
// 'magnitude > 0'; for a NaN in the real part the test is false, out is left as it was, and the caller's
// quat2.create() comes back as the identity dual quaternion (below, [defect]).
// The suite also counts quat.getAxisAngle's returned angle alone (the adapter's to_angle): rad = 2 acos(w),
// finite for a NaN or Inf in x, y or z, while the axis the same call writes is NaN/Inf. The call as a whole
// carries the NaN, so that is shown as context, not as a gl-matrix defect ([context]); the certificate's
// worst input is one of those. (getAxisAngle's axis [1, 0, 0] for w = +-Inf is the identity's axis, the
// rotation q/|q| tends to: ACC-1 nonfinite_limit.)
// (quat.normalize, exp, multiply, invert, slerp, setAxisAngle, mat3.fromQuat and quat2.multiply carry the
// NaN/Inf into their results: ACC-1 nonfinite_propagation since 2.7.0, no longer a defect.)
// Source (gl-matrix 3.4.4): cjs/quat.js:111-125 getAxisAngle, cjs/quat2.js:801-824 normalize.
// Upstream tracker (github.com/toji/gl-matrix): no report found (#135, closed: vec3.normalize leaving out
// unwritten for a zero input, is a neighbour).
// Run: NODE_PATH=build/adapters/gl_matrix/node_modules node EDGE-7.js   (exit 0 shown, 1 not shown, 77 skip)
const CLAUSE = 'EDGE-7';
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

console.log(`rotorcert reproducer: gl-matrix ${VERSION} EDGE-7: quat2.normalize answers a NaN real part with an ` +
            'all-finite result (status OK): the identity');
let shown = false;
/** One result of a call on `input` (flat list of numbers): all finite for a non-finite input is a defect
 *  where `counts` (a call of its own), context where the same call's other output carries the NaN. */
function check(tag, call, input, out, note, counts) {
  const flat = Array.from(out), nonFiniteIn = input.some((c) => !Number.isFinite(c));
  const bad = nonFiniteIn && flat.every(Number.isFinite);
  if (counts) shown = shown || bad;
  const verdict = bad ? (counts ? 'all finite, status OK  <-- DEFECT' : 'finite, but the same call wrote a NaN/Inf beside it (context)')
                      : nonFiniteIn ? 'a NaN or Inf reaches the result' : 'a finite input: no EDGE-7 case';
  console.log(`\n[${tag}] call:    ${call}\n    input:   ${show(input)}`);
  console.log(`    gl-matrix: ${show(flat)}${note}   -> ${verdict}`);
  console.log('    correct:   DOMAIN_ERROR (every component NaN); acceptable (ACC-1 nonfinite_propagation): some ' +
              'component NaN or Inf');
}
const nan = (s) => (s === '-nan' ? -NaN : s === 'nan' ? NaN : hx(s));
// 1. The suite's worst input: to_angle q = [-0x1.23e64ep-1, -nan, -0x1.04e99ap-2, -0x1.580322p-2] ('NaN in q').
{
  const q = ['-0x1.23e64ep-1', '-nan', '-0x1.04e99ap-2', '-0x1.580322p-2'].map(nan);
  const axis = vec3.create(), angle = Math.fround(quat.getAxisAngle(axis, quat.fromValues(...q)));   // binary32, as stored
  check('context', 'angle = quat.getAxisAngle(axis = vec3.create(), q): the angle it returns', q, [angle],
        `   (the axis the same call wrote: ${show(axis)})`, false);
}
// 2. dq_normalize d with a NaN w in the real part ('NaN in d').
{
  const d = ['-0x1.c839b6p-8', '-0x1.034bb4p-2', '0x1.b850fcp-2', 'nan', '-0x1.3755c8p-7', '-0x1.61a4ep-2', '-0x1.4563f6p-3',
             '0x1.0cc92ep-2'].map(nan);
  check('defect', 'quat2.normalize(quat2.create(), d)', d, quat2.normalize(quat2.create(), quat2.fromValues(...d)),
        '   (the untouched quat2.create(): magnitude > 0 is false)', true);
}
if (shown) { console.log('\nDEFECT SHOWN'); process.exit(0); }
console.log('\nDEFECT NOT SHOWN'); process.exit(1);
