#!/usr/bin/env node
// rotorcert reproducer: ganja.js, clause EDGE-6 (spec/SPEC.md 9, tolerance class outcome).
// EDGE-6: a dual quaternion (motor) whose real part is zero is DOMAIN_ERROR: every output component a
// quiet NaN (or, for a library without a status channel, an exception). Since spec 2.2.0, ACC-1
// zero_sentinel also accepts status OK with every output component +-0, or exactly the output of the
// identity motion substituted for the zero real part. ganja's PGA Normalized returns a motor whose
// M ~M has a zero scalar unchanged ('if (s==0) return this', ganja.js:230): the zero-real-part motor
// -e01 (a pure translation part, no rotation) comes back as itself, a finite non-normalised motor that
// is neither an error, nor zero, nor the identity. (The zero rotor's other answers, Normalized of 0 =
// 0, products with 0 = 0, the identity from Exp(0) for a zero axis, are ACC-1 zero_sentinel /
// algebraic_product answers since 2.2.0 and no longer a defect.)
// Source (ganja.js 1.0.204): ganja.js:227-232 (get Normalized, PGA branch). Upstream tracker: no report found.
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

// Conventions (MOTOR-1): the dual quaternion [r; d], each (x, y, z, w), is the PGA Cl(3,0,1) motor
// w_r - x_r e23 - y_r e31 - z_r e12 - x_d e01 - y_d e02 - z_d e03 - w_d e0123 (ganja names e13 = -e31).
const PGA = Algebra({p: 3, r: 1, baseType: Float64Array});
function motor(d) {  // [x_r, y_r, z_r, w_r, x_d, y_d, z_d, w_d] -> PGA motor
  const M = new PGA();
  M.s = d[3]; M.e23 = -d[0]; M.e13 = d[1]; M.e12 = -d[2];
  M.e01 = -d[4]; M.e02 = -d[5]; M.e03 = -d[6]; M.e0123 = -d[7];
  return M;
}
const dualQuat = (M) => [-M.e23, M.e13, -M.e12, M.s, -M.e01, -M.e02, -M.e03, -M.e0123];

console.log(`rotorcert reproducer: ganja.js ${VERSION} EDGE-6: PGA Normalized returns a motor with a zero real part unchanged (finite, status OK) instead of DOMAIN_ERROR`);
const d = [0, 0, 0, 0, 1, 0, 0, 0];                       // EX-EDGE-6-j: real part 0, dual part x = 1
const out = dualQuat(motor(d).Normalized);
const nonFinite = out.every((c) => !Number.isFinite(c));
const allZero = out.every((c) => c === 0);
const identity = out.every((c, i) => c === (i === 3 ? 1 : 0));   // the identity motion [0, 0, 0, 1, 0, 0, 0, 0]
const shown = !(nonFinite || allZero || identity);
console.log('  call:    motor(d).Normalized   (d [x,y,z,w]_real [x,y,z,w]_dual as the PGA motor of MOTOR-1)');
console.log('  input:   d = ' + show(d));
console.log('  ganja:   ' + show(out) + (shown ? '   (the input itself, status OK)  <-- DEFECT' : ''));
console.log('  correct: DOMAIN_ERROR (every component NaN, or an exception); acceptable (ACC-1 zero_sentinel): ' +
            show([0, 0, 0, 0, 0, 0, 0, 0]) + ' or the identity motion ' + show([0, 0, 0, 1, 0, 0, 0, 0]));
if (shown) { console.log('DEFECT SHOWN'); process.exit(0); }
console.log('DEFECT NOT SHOWN'); process.exit(1);
