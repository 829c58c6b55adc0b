#!/usr/bin/env node
// rotorcert reproducer: three.js, clause SLERP-2 (spec/SPEC.md 8.2, tolerance eps16, loose bar 256 eps).
// SLERP-2: the rotor interpolation R(t) = exp(t log(R_B ~R_A)) R_A, after R_B -> -R_B when a.b < 0, equals
// slerp(a, b, t). Quaternion.slerp flips b for a.b < 0 as it should, and then, when the flipped dot is
// >= 0.9995 (a near-antipodal pair is a near-identical pair after the flip), takes its lerp-then-normalize
// branch: nlerp, which leaves the geodesic rate of exp(t log(.)) by up to 0.032 W^3 (W the angle on S3)
// (SLERP-1.js has the analysis).
// Source (three 0.187.0): src/math/Quaternion.js:728 'if ( dot < 0.9995 )', branch :747-754. Upstream:
// mrdoob/three.js PR #31875 introduced the threshold on purpose; no report of the accuracy loss found.
// Run: NODE_PATH=build/adapters/three/node_modules node SLERP-2.js   (exit 0 shown, 1 not shown, 77 skip)
'use strict';
const fs = require('fs');
const path = require('path');
const {pathToFileURL} = require('url');

/** three.js as its users import it (the ES module build), found where require() finds the package. */
async function loadThree() {
  const cjs = require.resolve('three');                       // .../three/build/three.cjs
  const THREE = await import(pathToFileURL(path.join(path.dirname(cjs), 'three.module.js')).href);
  const VERSION = JSON.parse(fs.readFileSync(path.join(path.dirname(cjs), '..', 'package.json'), 'utf8')).version;
  return {THREE, VERSION};
}

/** Exact C99 %a-style hexfloat of a double (sign, 52-bit mantissa and exponent from its bits). */
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
const show = (v) => '[' + v.map(hex).join(', ') + ']';
const EPS = 2 ** -52, LOOSE = 256;
const norm = (v) => Math.hypot(...v);
/** spec METRIC-1: 4 atan2(min(|a-b|, |a+b|), max(...)) of the normalised quaternions (rotation angle). */
function metric1(a, b) {
  const na = norm(a), nb = norm(b), u = a.map((c) => c / na), w = b.map((c) => c / nb);
  const dm = Math.hypot(...u.map((c, i) => c - w[i])), dp = Math.hypot(...u.map((c, i) => c + w[i]));
  return 4 * Math.atan2(Math.min(dm, dp), Math.max(dm, dp));
}
/** spec METRIC-6: | |q| - 1 | of q = [x, y, z, w], as ((w-1)(w+1) + x^2 + y^2 + z^2)/(|q| + 1) (no cancellation). */
const normDefect = (q) => Math.abs((q[3] - 1) * (q[3] + 1) + q[0] ** 2 + q[1] ** 2 + q[2] ** 2) / (norm(q) + 1);

/** Hamilton product of [x, y, z, w] quaternions. */
function mul(a, b) {
  return [a[3] * b[0] + a[0] * b[3] + a[1] * b[2] - a[2] * b[1],
          a[3] * b[1] - a[0] * b[2] + a[1] * b[3] + a[2] * b[0],
          a[3] * b[2] + a[0] * b[1] - a[1] * b[0] + a[2] * b[3],
          a[3] * b[3] - a[0] * b[0] - a[1] * b[1] - a[2] * b[2]];
}
/** SLERP-2's rotor form in the quaternion view, binary64: a, b normalised, b' = -b iff a.b < 0,
 *  r = b' a*, log r = atan2(|v|, w) v/|v|, exp(t log r) a. A few ulps (about 1e-16 rad). */
function rotorRef(a, b, t) {
  const na = norm(a), nb = norm(b), u = a.map((c) => c / na);
  let w = b.map((c) => c / nb);
  if (u.reduce((s, c, i) => s + c * w[i], 0) < 0) w = w.map((c) => -c);
  const r = mul(w, [-u[0], -u[1], -u[2], u[3]]), vn = Math.hypot(r[0], r[1], r[2]);
  const half = t * Math.atan2(vn, r[3]);                     // t times the S3 angle of r
  const e = [...r.slice(0, 3).map((c) => Math.sin(half) * c / vn), Math.cos(half)];
  return mul(e, u);
}

(async () => {
  let THREE, VERSION;
  try { ({THREE, VERSION} = await loadThree()); } catch (e) {
    console.log('rotorcert reproducer: three.js SLERP-2: SKIP, cannot load three: ' + String(e.message).split('\n')[0]);
    process.exit(77);
  }
  // The suite's worst case (SLERP-2, near-antipodal pair): unit quaternions [x, y, z, w], a.b close to -1.
  const a = ['0x1.966d5214e2b4fp-1', '-0x1.9159470f6aef3p-2', '0x1.7e530a01ed29ap-2', '-0x1.1be2efc6729dcp-2'].map(hx);
  const b = ['-0x1.9028235faf5c1p-1', '0x1.a99b2c3eedb3p-2', '-0x1.820ac977924eap-2', '0x1.171d6167a7f7ap-2'].map(hx);
  const t = hx('0x1.d7dd4e8f2225ep-3');
  const got = new THREE.Quaternion().slerpQuaternions(new THREE.Quaternion(...a), new THREE.Quaternion(...b), t).toArray();
  const want = rotorRef(a, b, t);
  const err = Math.max(metric1(got, want), normDefect(got));
  const dot = a.reduce((s, c, i) => s + c * b[i], 0);

  console.log(`rotorcert reproducer: three.js ${VERSION} SLERP-2: Quaternion.slerp of a near-antipodal pair (|a.b| >= 0.9995 ` +
              'after its hemisphere flip) is nlerp, off the rotor interpolation exp(t log(b a*)) a');
  console.log('call:    new THREE.Quaternion().slerpQuaternions(new THREE.Quaternion(...a), new THREE.Quaternion(...b), t)');
  console.log(`input:   a = ${show(a)}  ([x, y, z, w], unit)\n         b = ${show(b)}\n         t = ${hex(t)}`);
  console.log(`         a.b = ${dot}: b is flipped, -a.b >= 0.9995: the lerp branch`);
  console.log(`three:   ${show(got)}`);
  console.log(`correct: ${show(want)}   exp(t log(b' a*)) a, b' = -b; binary64, a few ulps`);
  console.log(`error:   METRIC-1 ${metric1(got, want).toExponential(3)} rad, METRIC-6 ${normDefect(got).toExponential(3)}: ` +
              `${(err / EPS).toExponential(3)} eps (loose bar ${LOOSE} eps)`);
  if (!(err <= LOOSE * EPS)) { console.log('DEFECT SHOWN'); process.exit(0); }
  console.log('DEFECT NOT SHOWN'); process.exit(1);
})();
