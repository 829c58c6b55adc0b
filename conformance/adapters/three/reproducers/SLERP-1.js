#!/usr/bin/env node
// rotorcert reproducer: three.js, clause SLERP-1 (spec/SPEC.md 8.2, tolerance eps16, loose bar 256 eps).
// SLERP-1: slerp(a, b, t) = (sin((1-t) W) a + sin(t W) b') / sin W on the shorter arc, unit, judged by
// METRIC-1 and METRIC-6. Quaternion.slerp (and slerpQuaternions, which calls it, and the static
// slerpFlat) takes the hemisphere-aligned dot product and, when it is >= 0.9995, interpolates linearly
// and normalises: that is nlerp, not slerp. nlerp is not constant-velocity: its rotation differs from
// slerp's by about W^3 t(1-t)|1-2t|/3 (W the angle on S3), up to 0.032 W^3 = 8.7e-7 rad just below the
// threshold (a.b = 0.9995, 0.063 rad of rotation), and above the loose bar of 256 eps (5.7e-14 rad) for
// every pair more than about 2.5e-4 rad of rotation apart. The acos branch (a.b < 0.9995) is accurate.
// Source (three 0.187.0): src/math/Quaternion.js:728 'if ( dot < 0.9995 )' (slerp) and :89 (slerpFlat),
// the 'lerp then normalize' branch at :747-754. Upstream: introduced on purpose by mrdoob/three.js PR
// #31875 ('Quaternion - Rewrite .slerp() and .slerpFlat()': 'True spherical linear interpolation is
// unnecessary for small angles', the algorithm of Unity and Filament); PR #32541 restored t outside
// [0, 1] for it. No report of the accuracy loss found; the same threshold in glam-rs is bitshifter/glam-rs#356.
// Run: NODE_PATH=build/adapters/three/node_modules node SLERP-1.js   (exit 0 shown, 1 not shown, 77 skip)
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

/** The spec's slerp (SLERP-1) in binary64 with well-conditioned formulas: a and b normalised, b' = -b
 *  iff a.b < 0, Omega = 2 atan2(|a - b'|, |a + b'|) (no acos), (sin((1-t) Omega) a + sin(t Omega) b') /
 *  sin Omega. Its own error is a few ulps (about 1e-16 rad), nine orders below the defect shown. */
function slerpRef(a, b, t) {
  const na = norm(a), nb = norm(b), u = a.map((c) => c / na);
  let w = b.map((c) => c / nb);
  if (u.reduce((s, c, i) => s + c * w[i], 0) < 0) w = w.map((c) => -c);
  const om = 2 * Math.atan2(Math.hypot(...u.map((c, i) => c - w[i])), Math.hypot(...u.map((c, i) => c + w[i])));
  const s0 = Math.sin((1 - t) * om) / Math.sin(om), s1 = Math.sin(t * om) / Math.sin(om);
  return {q: u.map((c, i) => s0 * c + s1 * w[i]), omega: om};
}

(async () => {
  let THREE, VERSION;
  try { ({THREE, VERSION} = await loadThree()); } catch (e) {
    console.log('rotorcert reproducer: three.js SLERP-1: SKIP, cannot load three: ' + String(e.message).split('\n')[0]);
    process.exit(77);
  }
  // The suite's worst case (SLERP-1, near-identical pair, distance 2^-5): unit quaternions [x, y, z, w].
  const a = ['0x1.b2b4ed0c8b8ffp-3', '-0x1.cfdcd603e3ebbp-7', '0x1.44c04e1f5a53ap-2', '0x1.d93253b2ff66p-1'].map(hx);
  const b = ['0x1.83b6d09d9e97bp-3', '-0x1.2d857e1c762e1p-7', '0x1.34b747cb9dd6ap-2', '0x1.de6f6c0b895c8p-1'].map(hx);
  const t = hx('0x1.585c370a5be32p-3');
  const qa = new THREE.Quaternion(...a), qb = new THREE.Quaternion(...b);
  const got = new THREE.Quaternion().slerpQuaternions(qa, qb, t).toArray();
  const inst = qa.clone().slerp(qb, t).toArray(), flat = [];
  THREE.Quaternion.slerpFlat(flat, 0, a, 0, b, 0, t);
  const {q: want, omega} = slerpRef(a, b, t);
  const err = Math.max(metric1(got, want), normDefect(got));
  const dot = a.reduce((s, c, i) => s + c * b[i], 0);

  console.log(`rotorcert reproducer: three.js ${VERSION} SLERP-1: Quaternion.slerp returns nlerp (lerp, then normalize) ` +
              'instead of slerp whenever a.b >= 0.9995, i.e. for rotations up to 0.063 rad apart');
  console.log('call:    new THREE.Quaternion().slerpQuaternions(new THREE.Quaternion(...a), new THREE.Quaternion(...b), t)');
  console.log(`input:   a = ${show(a)}  ([x, y, z, w], unit)\n         b = ${show(b)}\n         t = ${hex(t)}`);
  console.log(`         a.b = ${dot} >= 0.9995: the lerp branch; the pair is ${(4 * omega / 2).toFixed(6)} rad of rotation apart`);
  console.log(`three:   ${show(got)}   (slerp instance method: ${show(inst)}; slerpFlat: ${show(flat)})`);
  console.log(`correct: ${show(want)}   (sin((1-t) W) a + sin(t W) b) / sin W, W = 2 atan2(|a-b|, |a+b|), binary64, a few ulps`);
  console.log(`check:   rotation from a: three ${metric1(a, got).toExponential(12)} rad, slerp t * d(a, b) = ` +
              `${(t * metric1(a, b)).toExponential(12)} rad (constant angular velocity, SLERP-5)`);
  console.log(`error:   METRIC-1 ${metric1(got, want).toExponential(3)} rad, METRIC-6 ${normDefect(got).toExponential(3)}: ` +
              `${(err / EPS).toExponential(3)} eps (loose bar ${LOOSE} eps)`);
  if (!(err <= LOOSE * EPS)) { console.log('DEFECT SHOWN'); process.exit(0); }
  console.log('DEFECT NOT SHOWN'); process.exit(1);
})();
