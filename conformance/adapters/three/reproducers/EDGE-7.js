#!/usr/bin/env node
// rotorcert reproducer: three.js, clause EDGE-7 (spec/SPEC.md 9, tolerance class outcome).
// EDGE-7: NaN or +-Inf in any input component is DOMAIN_ERROR with every output a quiet NaN, even where
// the result would be mathematically defined (normalize((Inf, 0, 0, 1)) is DOMAIN_ERROR, not (1, 0, 0, 0)).
// three.js checks nothing: Quaternion.normalize of (0, Inf, 0, 1) has length Inf, multiplies by 1/Inf = 0
// and returns (0, NaN, 0, 0), a partly-NaN result with no error; multiplyQuaternions with an infinite
// component returns +-Inf components. (Non-finite inputs of invert, applyQuaternion,
// makeRotationFromQuaternion, slerp, setFromAxisAngle and setFromRotationMatrix are outside their
// documented unit / rotation-matrix preconditions and not judged.)
// Source (three 0.187.0): src/math/Quaternion.js:627-653 normalize(), :686 multiplyQuaternions.
// Upstream tracker (github.com/mrdoob/three.js): no report found.
// Run: NODE_PATH=build/adapters/three/node_modules node EDGE-7.js   (exit 0 shown, 1 not shown, 77 skip)
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
    console.log('rotorcert reproducer: three.js EDGE-7: SKIP, cannot load three: ' + String(e.message).split('\n')[0]);
    process.exit(77);
  }
  console.log(`rotorcert reproducer: three.js ${VERSION} EDGE-7: no finiteness check: an infinite component gives ` +
              'partly-NaN or infinite results instead of a domain error');
  let shown = false;
  function check(tag, call, input, fn) {
    let out, threw = null;
    try { out = fn(); } catch (e) { if (e instanceof TypeError || e instanceof ReferenceError) throw e; threw = e; }
    const domainError = threw !== null || out.every(Number.isNaN);
    shown = shown || !domainError;
    console.log(`\n[${tag}] call:    ${call}\n    input:   ${input}`);
    console.log(`    three:   ${threw ? 'throws ' + threw.constructor.name : show(out)}   -> ${domainError ? 'DOMAIN_ERROR' : 'an ordinary result (status OK)'}`);
    console.log('    correct: DOMAIN_ERROR (every component NaN, or an exception)');
  }
  // EX-EDGE-7-b of the spec (the suite's worst case).
  const q = ['0x0p+0', 'inf', '0x0p+0', '0x1p+0'].map(hx);
  check(1, 'new THREE.Quaternion(x, y, z, w).normalize()', `q = ${show(q)}  ([x, y, z, w])`,
        () => new THREE.Quaternion(...q).normalize().toArray());
  // The suite's case '+Inf in a'.
  const a = ['inf', '0x1.bd3871e4b78cap-2', '-0x1.07cf0d274156bp-1', '-0x1.50583b526fee1p-4'].map(hx);
  const b = ['0x1.5f20eb8a4502ap-1', '-0x1.e472a45a35deep-2', '-0x1.d8f98f7aa6c7cp-2', '0x1.37794ce7528cbp-2'].map(hx);
  check(2, 'new THREE.Quaternion().multiplyQuaternions(a, b)', `a = ${show(a)}  b = ${show(b)}`,
        () => new THREE.Quaternion().multiplyQuaternions(new THREE.Quaternion(...a), new THREE.Quaternion(...b)).toArray());
  if (shown) { console.log('\nDEFECT SHOWN'); process.exit(0); }
  console.log('\nDEFECT NOT SHOWN'); process.exit(1);
})();
