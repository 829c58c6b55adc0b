#!/usr/bin/env node
// rotorcert reproducer: ganja.js, clause EDGE-2 (spec/SPEC.md 9, tolerance eps16, loose bar 256 eps).
// EDGE-2: for rotation angles from 1e-9 to 1e-3 rad, exp and log stay within their own class (EXP-1:
// exp(B) = cos|B| + B sin|B|/|B|, unit output, METRIC-1 and METRIC-6; LOG-1: log(s + B) =
// atan2(|B|, s) B/|B|, METRIC-5). ganja's Cl(3,0) Exp returns 1 + B when |B| <= 1e-5 (not unit), and
// Log returns B unchanged when |B|^2 < 1e-5 (|B| < 3.2e-3): it drops the atan2 factor, and for s < 0
// it also drops the sign of s, so exp(log q) is neither q nor -q.
// Source (ganja.js 1.0.204): ganja.js:510 'if (len <= 1E-5) return total.Mul(Element.Scalar(1).Add(simple))',
// ganja.js:533 'if (Math.abs(square) < 1E-5) return sum.Add(si)'. Upstream tracker: no report found.
// Run: NODE_PATH=build/adapters/ganja/node_modules node EDGE-2.js   (exit 0 shown, 1 not shown, 77 skip)
'use strict';
let Algebra, VERSION;
try { Algebra = require('ganja.js'); VERSION = require('ganja.js/package.json').version; } catch (e) {
  console.log('rotorcert reproducer: ganja.js EDGE-2: SKIP, cannot load ganja.js: ' + e.message.split('\n')[0]);
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
const EPS = 2 ** -52, LOOSE = 256;

// Conventions. Cl(3,0) in binary64; basis 1, e1, e2, e3, e12, e13, e23, e123 (e31 = -e13).
// Quaternion (w, x, y, z) <-> rotor w - x e23 - y e31 - z e12 (spec Q2R-1) = [w, 0,0,0, -z, +y, -x, 0].
// The quaternion-view log/exp vector v is the bivector -(vx e23 + vy e31 + vz e12), so
// C3.Bivector(e12, e13, e23) = C3.Bivector(-vz, +vy, -vx) and exp(v) = (w, x, y, z) = (cos|v|, sin|v| v/|v|).
const C3 = Algebra({p: 3, baseType: Float64Array});
const rotor = (w, x, y, z) => C3.Element(w, 0, 0, 0, -z, y, -x, 0);
const quat = (R) => [R.s, -R.e23, R.e13, -R.e12];        // (w, x, y, z)
const logv = (B) => [-B.e23, B.e13, -B.e12];             // (vx, vy, vz)

console.log(`rotorcert reproducer: ganja.js ${VERSION} EDGE-2: small-angle cut-offs: Exp returns 1 + B for |B| <= 1e-5, Log returns B for |B| < 3.2e-3 (sign of s ignored)`);
let shown = false;
const report = (err, what) => {
  const e = err / EPS; shown = shown || !(e <= LOOSE);
  console.log(`    error:   ${err.toExponential(3)} ${what} = ${e.toExponential(3)} eps (loose bar ${LOOSE} eps)`);
};

// Case 1 (EXP-1): v = (0, 0, 1e-5), a rotation by 2e-5 rad about z. Closed form (Taylor, the dropped
// terms are below 1e-33): cos x = 1 - x^2/2 + x^4/24, sin x = x - x^3/6 + x^5/120.
{
  const vz = 1e-5, R = C3.Bivector(-vz, 0, 0).Exp(), q = quat(R);
  const c = 1 - vz * vz / 2 + vz ** 4 / 24, s = vz - vz ** 3 / 6 + vz ** 5 / 120;
  console.log('\n[1] call:    C3.Bivector(-vz, vy, -vx).Exp()     (exp of the quaternion-view vector v)');
  console.log(`    input:   v = ${show([0, 0, vz])}`);
  console.log(`    ganja:   (w,x,y,z) = ${show(q)}`);
  console.log(`    correct: (w,x,y,z) = ${show([c, 0, 0, s])}   (cos|v|, sin|v| v/|v|), unit`);
  const norm = Math.hypot(...q);                         // |q| - 1 = (|q|^2 - 1)/(|q| + 1), no cancellation
  const defect = Math.abs((q[0] - 1) * (q[0] + 1) + q[1] ** 2 + q[2] ** 2 + q[3] ** 2) / (norm + 1);
  report(defect, '= | |exp(v)| - 1 | (METRIC-6, unit output)');
}

// Cases 2 and 3 (LOG-1): q = (w, 0, 0, +-2^-11) with w = sqrt(1 - 2^-22) rounded, a rotation by
// 2 asin(2^-11) = 9.77e-4 rad. log q = atan2(|v|, w) v/|v| (scale-free); atan2(z, w) = atan(t),
// t = z/w, by its series t - t^3/3 + t^5/5 (the dropped t^7/7 is below 1e-24).
const z = 0.00048828125, w = 0.9999998807907033;         // 2^-11 and 1 - 2^-23 - 2^-47
const t = z / w, theta = t - t ** 3 / 3 + t ** 5 / 5;
{
  const v = logv(rotor(w, 0, 0, z).Log());
  console.log('\n[2] call:    C3.Element(w,0,0,0,-z,y,-x,0).Log()');
  console.log(`    input:   q (w,x,y,z) = ${show([w, 0, 0, z])}`);
  console.log(`    ganja:   v = ${show(v)}`);
  console.log(`    correct: v = ${show([0, 0, theta])}   (0, 0, atan2(z, w))`);
  report(Math.hypot(v[0], v[1], v[2] - theta), 'rad (METRIC-5)');
}
{
  const v = logv(rotor(-w, 0, 0, z).Log());
  const principal = Math.PI - theta;                     // atan2(z, -w); log(-q) = (0, 0, -theta) is accepted too
  console.log('\n[3] call:    C3.Element(w,0,0,0,-z,y,-x,0).Log()   with w < 0 (the same small rotation, -q)');
  console.log(`    input:   q (w,x,y,z) = ${show([-w, 0, 0, z])}`);
  console.log(`    ganja:   v = ${show(v)}   exp(v) = ${show([Math.cos(v[2]), 0, 0, Math.sin(v[2])])} is neither q nor -q`);
  console.log(`    correct: v = ${show([0, 0, principal])} (principal, atan2(z, -|w|)), or ${show([0, 0, -theta])} (log of -q)`);
  report(Math.min(Math.abs(v[2] - principal), Math.abs(v[2] + theta)) + Math.hypot(v[0], v[1]), 'rad to the nearer accepted log (METRIC-5)');
}
if (shown) { console.log('\nDEFECT SHOWN'); process.exit(0); }
console.log('\nDEFECT NOT SHOWN'); process.exit(1);
