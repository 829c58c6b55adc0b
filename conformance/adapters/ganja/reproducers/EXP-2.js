#!/usr/bin/env node
// rotorcert reproducer: ganja.js, clause EXP-2 (spec/SPEC.md 8.2, tolerance eps16, loose bar 256 eps; METRIC-1).
// EXP-2: exp(log R) = R for a unit rotor R (as a rotation: +-R). ganja's Cl(3,0) Log returns B itself when
// |B|^2 < 1e-5 (|B| < 3.2e-3) and ignores the sign of the scalar part, so for a rotor near -1 (a rotation
// by nearly 2 pi) Exp(Log R) = (+|s|, B) instead of R = (-|s|, B) or -R = (+|s|, -B): the rotation axis is
// reversed, an error of ~4 |B| rad.
// Source (ganja.js 1.0.204): ganja.js:533 'if (Math.abs(square) < 1E-5) return sum.Add(si)'.
// Upstream tracker (github.com/enkimute/ganja.js/issues): no report found.
// Run: NODE_PATH=build/adapters/ganja/node_modules node EXP-2.js   (exit 0 shown, 1 not shown, 77 skip)
'use strict';
let Algebra, VERSION;
try { Algebra = require('ganja.js'); VERSION = require('ganja.js/package.json').version; } catch (e) {
  console.log('rotorcert reproducer: ganja.js EXP-2: SKIP, cannot load ganja.js: ' + e.message.split('\n')[0]);
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

// Conventions. Cl(3,0) in binary64; basis 1, e1, e2, e3, e12, e13, e23, e123 (e31 = -e13).
// Quaternion (w, x, y, z) <-> rotor w - x e23 - y e31 - z e12 (spec Q2R-1) = [w, 0,0,0, -z, +y, -x, 0];
// the exp/log vector v is the bivector -(vx e23 + vy e31 + vz e12) = C3.Bivector(e12, e13, e23) = (-vz, +vy, -vx).
const C3 = Algebra({p: 3, baseType: Float64Array});
const quat = (R) => [R.s, -R.e23, R.e13, -R.e12];        // (w, x, y, z)

// Input: the suite's worst case, q [x, y, z, w] = [-0x1.ea1989b2ac2e5p-15, 0x1.0966c46c0a9b4p-9,
// -0x1.39d33abbc4489p-9, -0x1.ffff5afa345c5p-1]: a unit rotor, a rotation by 2 pi - 6.3e-3 rad.
const q = [-0.9999950819421249, -5.842444388315884e-05, 0.0020248522541994277, -0.0023942956157801437]; // (w,x,y,z)
const R = C3.Element(q[0], 0, 0, 0, -q[3], q[2], -q[1], 0);
const L = R.Log(), got = quat(L.Exp());
// Correct (closed form): exp(log R) = R, i.e. q itself (or -q, the same rotation).
const err = metric1(got, q);

console.log(`rotorcert reproducer: ganja.js ${VERSION} EXP-2: Exp(Log R) of a rotor near -1 is neither R nor -R (Log drops the sign of the scalar part for |B| < 3.2e-3)`);
console.log('call:    C3 = Algebra({p:3, baseType:Float64Array}); R = C3.Element(w,0,0,0,-z,y,-x,0); R.Log().Exp()');
console.log(`input:   q (w,x,y,z) = ${show(q)}   (|q| - 1 = ${(norm(q) - 1).toExponential(2)})`);
console.log(`ganja:   Log(R) = ${show([-L.e23, L.e13, -L.e12])} (the vector part of q, unchanged)`);
console.log(`         Exp(Log(R)) (w,x,y,z) = ${show(got)}`);
console.log(`correct: (w,x,y,z) = ${show(q)}   (q itself, or -q)`);
console.log(`error:   METRIC-1 ${err.toExponential(3)} rad of rotation = ${(err / EPS).toExponential(3)} eps (loose bar ${LOOSE} eps)`);
if (!(err <= LOOSE * EPS)) { console.log('DEFECT SHOWN'); process.exit(0); }
console.log('DEFECT NOT SHOWN'); process.exit(1);
