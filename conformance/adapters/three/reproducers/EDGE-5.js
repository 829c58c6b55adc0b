#!/usr/bin/env node
// rotorcert reproducer: three.js, clause EDGE-5 (spec/SPEC.md 9, tolerance eps16, loose bar 256 eps).
// EDGE-5: a finite nonzero q means the rotation q/|q| at every scale the format holds, from subnormal
// components to components near the overflow threshold (NORM-1: 'scaling by a power of two near the
// largest |component| before squaring is the expected technique'). Quaternion.normalize divides by
// length() = sqrt(x^2 + y^2 + z^2 + w^2) computed without scaling: below about 2^-537 every square
// underflows, the length is 0 and normalize() replaces q by the identity (0, 0, 0, 1) (its zero-length
// rule); above about 2^511 the sum overflows, the length is inf and every component becomes 0.
// (invert, applyQuaternion, makeRotationFromQuaternion, slerp and setFromAxisAngle document unit inputs
// and are not judged on non-unit ones; multiplyQuaternions passes at every scale.)
// Source (three 0.187.0): src/math/Quaternion.js:617 length(), :627-653 normalize() (:631 the zero-length rule). Upstream tracker
// (github.com/mrdoob/three.js): no report found.
// Run: NODE_PATH=build/adapters/three/node_modules node EDGE-5.js   (exit 0 shown, 1 not shown, 77 skip)
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

/** q/|q| with the scaling NORM-1 asks for: multiply by the power of two that brings the largest
 *  component near 1 (exact), then divide by the norm (a few ulps). */
function normalized(q) {
  const e = Math.floor(Math.log2(Math.max(...q.map(Math.abs))));
  const s = q.map((c) => c * 2 ** -e);
  const n = norm(s);
  return s.map((c) => c / n);
}

(async () => {
  let THREE, VERSION;
  try { ({THREE, VERSION} = await loadThree()); } catch (e) {
    console.log('rotorcert reproducer: three.js EDGE-5: SKIP, cannot load three: ' + String(e.message).split('\n')[0]);
    process.exit(77);
  }
  console.log(`rotorcert reproducer: three.js ${VERSION} EDGE-5: Quaternion.normalize squares without scaling: ` +
              'at 2^-900 it returns the identity, at 2^+900 the zero quaternion');
  let worst = 0;
  function check(tag, q) {
    const got = new THREE.Quaternion(...q).normalize().toArray(), want = normalized(q);
    const err = Math.max(metric1(got, want), normDefect(got));
    worst = Math.max(worst, Number.isNaN(err) ? Infinity : err);
    console.log(`\n[${tag}] call:    new THREE.Quaternion(x, y, z, w).normalize()`);
    console.log(`    input:   q = ${show(q)}  ([x, y, z, w])`);
    console.log(`    three:   ${show(got)}`);
    console.log(`    correct: ${show(want)}   q/|q| (scaled by a power of two first: exact), unit`);
    console.log(got.every((c) => c === 0) ? '    error:   the zero quaternion is no rotation (METRIC-6 = 1): a NaN error, above every bar'
      : `    error:   METRIC-1 ${metric1(got, want).toExponential(3)} rad, METRIC-6 ${normDefect(got).toExponential(3)}: ` +
        `${(err / EPS).toExponential(3)} eps (loose bar ${LOOSE} eps)`);
  }
  // The suite's worst case (EDGE-5, non-unit scale 2^-900): the squares underflow, the length is 0.
  const q = ['-0x1.6b35f8bf1e5c2p-905', '-0x1.d83ae4b18863ap-901', '-0x1.0ec9134728671p-900', '-0x1.f58be72c5603fp-907'].map(hx);
  check(1, q);
  // The same rotation at 2^+900 (q times 2^1800, exact): the sum of squares overflows, the length is inf.
  check(2, q.map((c) => c * 2 ** 900 * 2 ** 900));
  if (!(worst <= LOOSE * EPS)) { console.log('\nDEFECT SHOWN'); process.exit(0); }
  console.log('\nDEFECT NOT SHOWN'); process.exit(1);
})();
