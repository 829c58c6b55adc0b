#!/usr/bin/env node
// rotorcert reproducer: three.js, clause EDGE-8 (spec/SPEC.md 9, tolerance eps4, loose bar 64 eps).
// EDGE-8: subnormal components are ordinary nonzero values: normalize((2^-1074, -0, 0, 0)) = (1, -0, 0, 0).
// Quaternion.normalize computes length() = sqrt(x^2 + y^2 + z^2 + w^2) without scaling: every square of
// a component below 2^-537 underflows to 0, the length is 0, and normalize() then sets the identity
// (0, 0, 0, 1): a subnormal quaternion about x (a half turn) comes back as no rotation at all.
// (Subnormal inputs of invert, applyQuaternion, makeRotationFromQuaternion and slerp are outside their
// documented unit precondition and not judged; multiplyQuaternions passes.)
// Source (three 0.187.0): src/math/Quaternion.js:617 length(), :631-636 the zero-length rule of normalize().
// Upstream tracker (github.com/mrdoob/three.js): no report found.
// Run: NODE_PATH=build/adapters/three/node_modules node EDGE-8.js   (exit 0 shown, 1 not shown, 77 skip)
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

(async () => {
  let THREE, VERSION;
  try { ({THREE, VERSION} = await loadThree()); } catch (e) {
    console.log('rotorcert reproducer: three.js EDGE-8: SKIP, cannot load three: ' + String(e.message).split('\n')[0]);
    process.exit(77);
  }
  // EX-EDGE-8-a of the spec (the suite's worst case): the half turn about x, scaled to the smallest subnormal.
  const q = ['0x0.0000000000001p-1022', '-0x0p+0', '0x0p+0', '0x0p+0'].map(hx);
  const got = new THREE.Quaternion(...q).normalize().toArray();
  const want = [1, -0, 0, 0];
  const err = Math.max(metric1(got, want), normDefect(got));
  console.log(`rotorcert reproducer: three.js ${VERSION} EDGE-8: normalize() of a subnormal quaternion squares it to 0 ` +
              'and returns the identity');
  console.log('call:    new THREE.Quaternion(x, y, z, w).normalize()');
  console.log(`input:   q = ${show(q)}  ([x, y, z, w]: 2^-1074 i, a half turn about x)`);
  console.log(`three:   ${show(got)}`);
  console.log(`correct: ${show(want)}   q/|q| (closed form)`);
  console.log(`error:   METRIC-1 ${metric1(got, want).toExponential(3)} rad (pi: a half turn off), ` +
              `${(err / EPS).toExponential(3)} eps (loose bar 64 eps)`);
  if (!(err <= 64 * EPS)) { console.log('DEFECT SHOWN'); process.exit(0); }
  console.log('DEFECT NOT SHOWN'); process.exit(1);
})();
