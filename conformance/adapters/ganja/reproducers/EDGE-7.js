#!/usr/bin/env node
// rotorcert reproducer: ganja.js, clause EDGE-7 (spec/SPEC.md 9, tolerance class outcome).
// EDGE-7: NaN or +-Inf in any input component (t included) is DOMAIN_ERROR with all output components
// quiet NaN (or, for a library without a status channel, an exception), even where the result would be
// mathematically defined. ganja checks nothing: NaN and Inf reach only some output components and the
// others come back as ordinary numbers, so a caller cannot tell the result is invalid.
// Upstream tracker (github.com/enkimute/ganja.js/issues): no report found.
// Run: NODE_PATH=build/adapters/ganja/node_modules node EDGE-7.js   (exit 0 shown, 1 not shown, 77 skip)
'use strict';
let Algebra, VERSION;
try { Algebra = require('ganja.js'); VERSION = require('ganja.js/package.json').version; } catch (e) {
  console.log('rotorcert reproducer: ganja.js EDGE-7: SKIP, cannot load ganja.js: ' + e.message.split('\n')[0]);
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
// <-> rotor w - x e23 - y e31 - z e12 (spec Q2R-1) = [w, 0,0,0, -z, +y, -x, 0].
// PGA Cl(3,0,1): basis 1, e0..e3, e01, e02, e03, e12, e13, e23, e012, e013, e023, e123, e0123; the
// dual quaternion [r; d] is the motor w_r - x_r e23 - y_r e31 - z_r e12 - x_d e01 - y_d e02 - z_d e03 -
// w_d e0123 (MOTOR-1), and the translator T(t) = exp(-(tx e01 + ty e02 + tz e03)/2) = 1 - t e0/2 (ALG-7).
const C3 = Algebra({p: 3, baseType: Float64Array});
const PGA = Algebra({p: 3, r: 1, baseType: Float64Array});
const rotor = (w, x, y, z) => C3.Element(w, 0, 0, 0, -z, y, -x, 0);
const quat = (R) => [R.s, -R.e23, R.e13, -R.e12];        // (w, x, y, z)
const dq = (M) => [M.s, -M.e23, M.e13, -M.e12, -M.e0123, -M.e01, -M.e02, -M.e03];  // (w,x,y,z)_r, (w,x,y,z)_d

console.log(`rotorcert reproducer: ganja.js ${VERSION} EDGE-7: NaN/Inf inputs give partly finite results (Normalized, Mul, T(t) R) instead of DOMAIN_ERROR`);
let shown = false;
function check(tag, call, input, fn) {
  let out, threw = null;
  try { out = fn(); } catch (e) { if (e instanceof TypeError || e instanceof ReferenceError) throw e; threw = e; }
  const domainError = threw !== null || out.every(Number.isNaN);
  shown = shown || !domainError;
  console.log(`\n[${tag}] call:    ${call}\n    input:   ${input}`);
  console.log(`    ganja:   ${threw ? 'throws ' + threw.constructor.name : show(out)}   -> ${domainError ? 'DOMAIN_ERROR' : 'not all NaN, no exception (status OK)'}`);
  console.log('    correct: DOMAIN_ERROR (every component NaN, or an exception)');
}

check(1, 'C3.Element(w,0,0,0,-z,y,-x,0).Normalized', 'q (w,x,y,z) = ' + show([1, NaN, 0, 0]),
      () => quat(rotor(1, NaN, 0, 0).Normalized));
check(2, 'C3.Element(w,0,0,0,-z,y,-x,0).Normalized', 'q (w,x,y,z) = ' + show([1, Infinity, 0, 0]),
      () => quat(rotor(1, Infinity, 0, 0).Normalized));
check(3, 'A.Mul(B)   (compose, the geometric product)', 'a (w,x,y,z) = ' + show([1, Infinity, 0, 0]) + '  b = ' + show([0, 0, 0, 1]),
      () => quat(rotor(1, Infinity, 0, 0).Mul(rotor(0, 0, 0, 1))));
check(4, 'PGA.Bivector(-tx/2,-ty/2,-tz/2,0,0,0).Exp().Mul(R.Normalized)   (T(t) R, DQ-1)',
      'q (w,x,y,z) = ' + show([1, 0, 0, 0]) + '  t = ' + show([NaN, 0, 0]),
      () => { const R = new PGA(); R.s = 1; return dq(PGA.Bivector(NaN / 2, 0, 0, 0, 0, 0).Exp().Mul(R.Normalized)); });
if (shown) { console.log('\nDEFECT SHOWN'); process.exit(0); }
console.log('\nDEFECT NOT SHOWN'); process.exit(1);
