#!/usr/bin/env node
// rotorcert reproducer: ganja.js, clause AXANG-2 (spec/SPEC.md 6, tolerance eps16, loose bar 256 eps).
// AXANG-2: the quaternion of angle theta about axis u is (cos(theta/2), sin(theta/2) u/|u|), a unit
// quaternion (METRIC-1 and METRIC-6). ganja has no axis-angle constructor; its idiom is the exponential
// of the bivector -theta/2 I u (its examples write Math.E**(P*a*0.5), e.g. examples/
// example_chapter11_tricycle.html, which calls Exp). Its Cl(3,0) Exp returns 1 + B for
// |B| <= 1e-5, so every rotation by less than 2e-5 rad comes out non-unit: norm defect (theta/2)^2/2.
// Source (ganja.js 1.0.204): ganja.js:510 'if (len <= 1E-5) return total.Mul(Element.Scalar(1).Add(simple))'
// (the same cut-off as EXP-1.js). Upstream tracker (github.com/enkimute/ganja.js/issues): no report found.
// Run: NODE_PATH=build/adapters/ganja/node_modules node AXANG-2.js   (exit 0 shown, 1 not shown, 77 skip)
'use strict';
let Algebra, VERSION;
try { Algebra = require('ganja.js'); VERSION = require('ganja.js/package.json').version; } catch (e) {
  console.log('rotorcert reproducer: ganja.js AXANG-2: SKIP, cannot load ganja.js: ' + e.message.split('\n')[0]);
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
const norm = (v) => Math.hypot(...v);
/** spec METRIC-1: 4 atan2(min(|a-b|, |a+b|), max(...)) of the normalised quaternions (rotation angle). */
function metric1(a, b) {
  const na = norm(a), nb = norm(b), u = a.map((c) => c / na), w = b.map((c) => c / nb);
  const dm = Math.hypot(...u.map((c, i) => c - w[i])), dp = Math.hypot(...u.map((c, i) => c + w[i]));
  return 4 * Math.atan2(Math.min(dm, dp), Math.max(dm, dp));
}
/** spec METRIC-6: | |q| - 1 | of q = (w, x, y, z), as ((w-1)(w+1) + x^2 + y^2 + z^2)/(|q| + 1) (no cancellation). */
const normDefect = (q) => Math.abs((q[0] - 1) * (q[0] + 1) + q[1] ** 2 + q[2] ** 2 + q[3] ** 2) / (norm(q) + 1);

// Conventions. Cl(3,0) in binary64; the rotor w - x e23 - y e31 - z e12 (spec Q2R-1) is the quaternion
// (w, x, y, z) = (R.s, -R.e23, R.e13, -R.e12) (ganja names e13; e31 = -e13). u.Dual = u e123 = I u.
const C3 = Algebra({p: 3, baseType: Float64Array});
const quat = (R) => [R.s, -R.e23, R.e13, -R.e12];

// Input: the suite's worst case, angle = 0x1.454c90b8b3a32p-16 (1.94e-5 rad),
// axis = [0x1.e73c7ce1dfecp-1, 0x1.ad4e4b450479ep-4, 0x1.27bc9f5d7c294p-2] (unit to a few ulps).
const angle = 1.9389336304348986e-05, axis = [0.9516333604551264, 0.10481099512278866, 0.28880547531211076];
const got = quat(C3.Vector(...axis).Normalized.Dual.Scale(-angle / 2).Exp());
// Correct (closed form, Taylor in h = angle/2 = 9.7e-6; the dropped terms are below 1e-33):
// cos h = 1 - h^2/2 + h^4/24, sin h = h - h^3/6 + h^5/120, u = axis/|axis|.
const h = angle / 2, na = norm(axis);
const want = [1 - h * h / 2 + h ** 4 / 24, ...axis.map((c) => (h - h ** 3 / 6 + h ** 5 / 120) * c / na)];
const e1 = metric1(got, want), e6 = normDefect(got), err = Math.max(e1, e6);

console.log(`rotorcert reproducer: ganja.js ${VERSION} AXANG-2: the rotor of a rotation by < 2e-5 rad, Exp(-angle/2 I u), is 1 + B, not unit (norm defect (angle/2)^2/2)`);
console.log('call:    C3 = Algebra({p:3, baseType:Float64Array}); C3.Vector(ux,uy,uz).Normalized.Dual.Scale(-angle/2).Exp()');
console.log(`input:   angle = ${hex(angle)}  axis = ${show(axis)}`);
console.log(`ganja:   (w,x,y,z) = ${show(got)}`);
console.log(`correct: (w,x,y,z) = ${show(want)}   (cos(angle/2), sin(angle/2) u/|u|), unit`);
console.log(`error:   METRIC-1 ${e1.toExponential(3)} rad, METRIC-6 | |q| - 1 | = ${e6.toExponential(3)}: ` +
            `${(err / EPS).toExponential(3)} eps (loose bar ${LOOSE} eps)`);
if (!(err <= LOOSE * EPS)) { console.log('DEFECT SHOWN'); process.exit(0); }
console.log('DEFECT NOT SHOWN'); process.exit(1);
