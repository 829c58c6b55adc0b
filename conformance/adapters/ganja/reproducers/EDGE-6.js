#!/usr/bin/env node
// rotorcert reproducer: ganja.js, clause EDGE-6 (spec/SPEC.md 9, tolerance class outcome).
// EDGE-6: a zero quaternion, a dual quaternion whose real part is zero and a zero axis (AXANG-2) are
// DOMAIN_ERROR: every output component a quiet NaN (or, for a library without a status channel, an
// exception). ganja's Normalized returns a zero element unchanged ('if (!l) return this' in Cl(3,0),
// 'if (s==0) return this' in PGA), so a zero rotor, a zero axis and the motor T(t) R of a zero rotor all
// come back as ordinary finite values. Zero axis (AXANG-2) and zero rotation in T(t) R (DQ-1) are the
// rotorcert expected failures of those clauses; zero inputs are judged here (EDGE-6).
// Source (ganja.js 1.0.204): ganja.js:234 (Cl(3,0)) and ganja.js:230 (PGA). Upstream tracker: no report found.
// Run: NODE_PATH=build/adapters/ganja/node_modules node EDGE-6.js   (exit 0 shown, 1 not shown, 77 skip)
'use strict';
let Algebra, VERSION;
try { Algebra = require('ganja.js'); VERSION = require('ganja.js/package.json').version; } catch (e) {
  console.log('rotorcert reproducer: ganja.js EDGE-6: SKIP, cannot load ganja.js: ' + e.message.split('\n')[0]);
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

// Conventions. Cl(3,0): basis 1, e1, e2, e3, e12, e13, e23, e123 (e31 = -e13); quaternion (w, x, y, z)
// <-> rotor w - x e23 - y e31 - z e12 (spec Q2R-1) = [w, 0,0,0, -z, +y, -x, 0]. Axis-angle (Q2R-4):
// exp(-I u theta/2) with u the normalised axis; in Cl(3,0) ganja's Dual is the product with e123.
// PGA Cl(3,0,1): basis 1, e0..e3, e01, e02, e03, e12, e13, e23, e012, e013, e023, e123, e0123; the
// dual quaternion [r; d] is the motor w_r - x_r e23 - y_r e31 - z_r e12 - x_d e01 - y_d e02 - z_d e03 -
// w_d e0123 (MOTOR-1), and the translator T(t) = exp(-(tx e01 + ty e02 + tz e03)/2) = 1 - t e0/2 (ALG-7).
const C3 = Algebra({p: 3, baseType: Float64Array});
const PGA = Algebra({p: 3, r: 1, baseType: Float64Array});
const rotor = (w, x, y, z) => C3.Element(w, 0, 0, 0, -z, y, -x, 0);
const quat = (R) => [R.s, -R.e23, R.e13, -R.e12];        // (w, x, y, z)
const dq = (M) => [M.s, -M.e23, M.e13, -M.e12, -M.e0123, -M.e01, -M.e02, -M.e03];  // (w,x,y,z)_r, (w,x,y,z)_d

console.log(`rotorcert reproducer: ganja.js ${VERSION} EDGE-6: Normalized returns a zero rotor unchanged, so zero quaternions, zero axes and zero motors give finite results instead of DOMAIN_ERROR`);
let shown = false;
function check(tag, call, input, fn) {
  let out, threw = null;
  try { out = fn(); } catch (e) { if (e instanceof TypeError || e instanceof ReferenceError) throw e; threw = e; }
  const domainError = threw !== null || out.every(Number.isNaN);
  shown = shown || !domainError;
  console.log(`\n[${tag}] call:    ${call}\n    input:   ${input}`);
  console.log(`    ganja:   ${threw ? 'throws ' + threw.constructor.name : show(out)}   -> ${domainError ? 'DOMAIN_ERROR' : 'an ordinary result (status OK)'}`);
  console.log('    correct: DOMAIN_ERROR (every component NaN, or an exception)');
}

check(1, 'C3.Element(w,0,0,0,-z,y,-x,0).Normalized', 'q (w,x,y,z) = ' + show([0, 0, 0, 0]),
      () => quat(rotor(0, 0, 0, 0).Normalized));
const theta = 1.5707963267948966;                         // pi/2 rounded
check(2, 'C3.Vector(ux,uy,uz).Normalized.Dual.Scale(-theta/2).Exp()   (exp(-I u theta/2), AXANG-2)',
      `theta = ${hex(theta)}  axis u = ${show([0, 0, 0])}`,
      () => quat(C3.Vector(0, 0, 0).Normalized.Dual.Scale(-theta / 2).Exp()));
check(3, 'PGA.Bivector(-tx/2,-ty/2,-tz/2,0,0,0).Exp().Mul(R.Normalized)   (T(t) R, DQ-1)',
      'q (w,x,y,z) = ' + show([0, 0, 0, 0]) + '  t = ' + show([1, 0, 0]),
      () => dq(PGA.Bivector(-1 / 2, 0, 0, 0, 0, 0).Exp().Mul(new PGA().Normalized)));
check(4, 'C3.Element(w,0,0,0,-z,y,-x,0).Log()', 'q (w,x,y,z) = ' + show([0, 0, 0, 0]),
      () => { const B = rotor(0, 0, 0, 0).Log(); return [-B.e23, B.e13, -B.e12]; });
if (shown) { console.log('\nDEFECT SHOWN'); process.exit(0); }
console.log('\nDEFECT NOT SHOWN'); process.exit(1);
