#!/usr/bin/env node
// rotorcert reproducer: three.js, clause EDGE-2 (spec/SPEC.md 9, tolerance eps16, loose bar 256 eps).
// EDGE-2: for rotation angles from 1e-9 to 1e-3 rad (and their differences in slerp) every op stays within
// its class. Quaternion.slerp interpolates every pair with a.b >= 0.9995 by lerp then normalize (nlerp):
// for two rotations W apart on S3 the result is off slerp by about W^3 t(1-t)|1-2t|/3, which is above the
// loose bar (5.7e-14 rad) for every pair more than about 2.5e-4 rad of rotation apart, so the small-angle
// range of EDGE-2 fails from 2.5e-4 to 1e-3 rad. normalize, multiplyQuaternions, applyQuaternion,
// makeRotationFromQuaternion, setFromRotationMatrix and setFromAxisAngle pass EDGE-2.
// Source (three 0.187.0): src/math/Quaternion.js:728 'if ( dot < 0.9995 )', branch :747-754 (SLERP-1.js).
// Upstream: mrdoob/three.js PR #31875 introduced the threshold on purpose; no report of the accuracy loss found.
// Run: NODE_PATH=build/adapters/three/node_modules node EDGE-2.js   (exit 0 shown, 1 not shown, 77 skip)
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

/** The spec's slerp (SLERP-1) in binary64: a, b normalised, b' = -b iff a.b < 0, W = 2 atan2(|a - b'|,
 *  |a + b'|) (no acos), (sin((1-t) W) a + sin(t W) b') / sin W: a few ulps, also for small W. */
function slerpRef(a, b, t) {
  const na = norm(a), nb = norm(b), u = a.map((c) => c / na);
  let w = b.map((c) => c / nb);
  if (u.reduce((s, c, i) => s + c * w[i], 0) < 0) w = w.map((c) => -c);
  const om = 2 * Math.atan2(Math.hypot(...u.map((c, i) => c - w[i])), Math.hypot(...u.map((c, i) => c + w[i])));
  const s0 = Math.sin((1 - t) * om) / Math.sin(om), s1 = Math.sin(t * om) / Math.sin(om);
  return u.map((c, i) => s0 * c + s1 * w[i]);
}

(async () => {
  let THREE, VERSION;
  try { ({THREE, VERSION} = await loadThree()); } catch (e) {
    console.log('rotorcert reproducer: three.js EDGE-2: SKIP, cannot load three: ' + String(e.message).split('\n')[0]);
    process.exit(77);
  }
  // The suite's worst case (EDGE-2, angle 1e-9 .. 1e-3): unit quaternions [x, y, z, w] 9.9e-4 rad apart.
  const a = ['0x1.582a9855cb724p-1', '0x1.5020ff12ebafcp-1', '-0x1.5315d96d007eap-2', '0x1.62bae793664d8p-4'].map(hx);
  const b = ['0x1.582f1357549cap-1', '0x1.503a9f3bdbeecp-1', '-0x1.529e72e9851a2p-2', '0x1.62b34f3ac6222p-4'].map(hx);
  const t = hx('0x1.7bcb378a2874cp-3');
  const got = new THREE.Quaternion().slerpQuaternions(new THREE.Quaternion(...a), new THREE.Quaternion(...b), t).toArray();
  const want = slerpRef(a, b, t);
  const err = Math.max(metric1(got, want), normDefect(got));

  console.log(`rotorcert reproducer: three.js ${VERSION} EDGE-2: Quaternion.slerp of two rotations ` +
              `${metric1(a, b).toExponential(2)} rad apart is nlerp (a.b >= 0.9995), ${(err / EPS).toExponential(2)} eps off slerp`);
  console.log('call:    new THREE.Quaternion().slerpQuaternions(new THREE.Quaternion(...a), new THREE.Quaternion(...b), t)');
  console.log(`input:   a = ${show(a)}  ([x, y, z, w], unit)\n         b = ${show(b)}\n         t = ${hex(t)}`);
  console.log(`three:   ${show(got)}`);
  console.log(`correct: ${show(want)}   (sin((1-t) W) a + sin(t W) b) / sin W, W = 2 atan2(|a-b|, |a+b|), binary64, a few ulps`);
  console.log(`check:   rotation from a: three ${metric1(a, got).toExponential(15)} rad, slerp t * d(a, b) = ` +
              `${(t * metric1(a, b)).toExponential(15)} rad`);
  console.log(`error:   METRIC-1 ${metric1(got, want).toExponential(3)} rad, METRIC-6 ${normDefect(got).toExponential(3)}: ` +
              `${(err / EPS).toExponential(3)} eps (loose bar ${LOOSE} eps)`);
  if (!(err <= LOOSE * EPS)) { console.log('DEFECT SHOWN'); process.exit(0); }
  console.log('DEFECT NOT SHOWN'); process.exit(1);
})();
