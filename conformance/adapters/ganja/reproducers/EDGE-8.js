#!/usr/bin/env node
// rotorcert reproducer: ganja.js, clause EDGE-8 (spec/SPEC.md 9, tolerance eps4, loose bar 64 eps).
// EDGE-8: subnormal components are ordinary nonzero values: normalize((2^-1074, -0, 0, 0)) (x,y,z,w)
// = (1, -0, 0, 0), with full accuracy (NORM-1: no intermediate underflow). ganja's Normalized computes
// sqrt(<R conj R>_0), which underflows to 0, and then returns the input unchanged; to_matrix written
// as ganja's sandwich of the normalised rotor gives the zero matrix. (The Log case of the expected
// failure, q = (tiny, -0, tiny', -1), returns the log of -q up to a subnormal: accepted, not shown here.)
// Source (ganja.js 1.0.204): ganja.js:225 Length, ganja.js:234 'if (!l) return this'. Upstream tracker: no report found.
// Run: NODE_PATH=build/adapters/ganja/node_modules node EDGE-8.js   (exit 0 shown, 1 not shown, 77 skip)
'use strict';
let Algebra, VERSION;
try { Algebra = require('ganja.js'); VERSION = require('ganja.js/package.json').version; } catch (e) {
  console.log('rotorcert reproducer: ganja.js EDGE-8: SKIP, cannot load ganja.js: ' + e.message.split('\n')[0]);
  process.exit(77);
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
const show = (v) => '[' + v.map(hex).join(', ') + ']';
const EPS = 2 ** -52, LOOSE = 64;

// Conventions. Cl(3,0) in binary64; basis 1, e1, e2, e3, e12, e13, e23, e123 (e31 = -e13).
// Quaternion (w, x, y, z) <-> rotor w - x e23 - y e31 - z e12 (spec Q2R-1) = [w, 0,0,0, -z, +y, -x, 0].
// Matrix (MAT-1): column c is the image R e_c ~R of the basis vector e_c.
const C3 = Algebra({p: 3, baseType: Float64Array});
const rotor = (w, x, y, z) => C3.Element(w, 0, 0, 0, -z, y, -x, 0);
const quat = (R) => [R.s, -R.e23, R.e13, -R.e12];        // (w, x, y, z)

console.log(`rotorcert reproducer: ganja.js ${VERSION} EDGE-8: Normalized of a subnormal rotor returns it unchanged (|q|^2 underflows), so to_matrix is the zero matrix`);
let shown = false;
const report = (err, what) => {
  const e = err / EPS; shown = shown || !(e <= LOOSE);
  console.log(`    error:   ${err.toExponential(3)} ${what} = ${e.toExponential(3)} eps (loose bar ${LOOSE} eps)`);
};
// Input: q = 2^-1074 i (x = the smallest subnormal, y = -0): the half turn about x. Closed forms:
// q/|q| = (w,x,y,z) = (0, 1, -0, 0); its matrix is diag(1, -1, -1).
const w = 0, x = 5e-324, y = -0, z = 0;                   // x = 2^-1074
{
  const q = quat(rotor(w, x, y, z).Normalized), want = [0, 1, -0, 0];
  console.log('\n[1] call:    C3.Element(w,0,0,0,-z,y,-x,0).Normalized');
  console.log(`    input:   q (w,x,y,z) = ${show([w, x, y, z])}`);
  console.log(`    ganja:   ${show(q)}\n    correct: ${show(want)}   q/|q|, unit`);
  report(Math.abs(Math.hypot(...q) - 1), '= | |q| - 1 | (METRIC-6: the output is not unit)');
}
{
  const cols = C3.sw(rotor(w, x, y, z).Normalized, [C3.Vector(1, 0, 0), C3.Vector(0, 1, 0), C3.Vector(0, 0, 1)]);
  const m = cols.flatMap((c) => [c.e1, c.e2, c.e3]), want = [1, 0, 0, 0, -1, 0, 0, 0, -1];   // column-major
  console.log('\n[2] call:    C3.sw(R.Normalized, [C3.Vector(1,0,0), C3.Vector(0,1,0), C3.Vector(0,0,1)])   (to_matrix, R >>> e_c)');
  console.log(`    input:   q (w,x,y,z) = ${show([w, x, y, z])}`);
  console.log(`    ganja:   ${show(m)}\n    correct: ${show(want)}   diag(1, -1, -1), column-major`);
  report(Math.max(...m.map((c, i) => Math.abs(c - want[i]))), 'max entry (METRIC-4)');
}
if (shown) { console.log('\nDEFECT SHOWN'); process.exit(0); }
console.log('\nDEFECT NOT SHOWN'); process.exit(1);
