#!/usr/bin/env node
// rotorcert reproducer: ganja.js, clause EDGE-5 (APPLY-3 on a non-unit q) (spec/SPEC.md 9, EDGE-5: tolerance
// eps16, loose bar 256 eps). APPLY-3 (spec 8.1): a rotor leaves a volume unchanged, R (a I) ~R = a I; EDGE-5:
// a finite nonzero quaternion q means the rotation q/|q| (the input q = (1, 1, 1, 1) is not unit, so the
// suite judges this at the Robust level, EDGE-5). ganja's sandwich R X ~R of a non-unit rotor
// returns |q|^2 a I instead. ganja documents x>>>y as x.Mul(y).Mul(x.Conjugate) (README, "Ganja
// ingredients and syntax") and states no unit-rotor precondition for it.
// Source (ganja.js 1.0.204): ganja.js:675 'return a.Mul(b).Mul(a.Reverse)'. Upstream tracker
// (github.com/enkimute/ganja.js/issues): no report found; GitHub master has the same ganja.js.
// Run: NODE_PATH=build/adapters/ganja/node_modules node EDGE-5-trivector.js   (exit 0 shown, 1 not shown, 77 skip)
'use strict';
let Algebra, VERSION;
try { Algebra = require('ganja.js'); VERSION = require('ganja.js/package.json').version; } catch (e) {
  console.log('rotorcert reproducer: ganja.js EDGE-5 (APPLY-3 on a non-unit q): SKIP, cannot load ganja.js: ' + e.message.split('\n')[0]);
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

// Conventions. Cl(3,0) in binary64 (the default Algebra(3) stores Float32Array coefficients):
// basis order 1, e1, e2, e3, e12, e13, e23, e123 (no e31; e31 = -e13). The quaternion (w, x, y, z)
// is the rotor w - x e23 - y e31 - z e12 (spec Q2R-1) = coefficients [w, 0,0,0, -z, +y, -x, 0].
// A trivector a is a e123. The pseudoscalar is central, so R (a e123) ~R = (R ~R) a e123 exactly.
const C3 = Algebra({p: 3, baseType: Float64Array});
const rotor = (w, x, y, z) => C3.Element(w, 0, 0, 0, -z, y, -x, 0);

// Input: q = (w, x, y, z) = (1, 1, 1, 1), |q| = 2: the rotation by 120 degrees about (1, 1, 1).
const w = 1, x = 1, y = 1, z = 1, a = -3;
const R = rotor(w, x, y, z);
const got = C3.sw(R, C3.Trivector(a)).e123;          // R >>> a e123 (ganja's sandwich, README: x>>>y)
// Correct value (closed form): a volume is invariant under every rotation: a' = a = -3 exactly.
const want = a;
const rel = Math.abs(got - want) / Math.abs(want), EPS = 2 ** -52, LOOSE = 256;  // EDGE-5: eps16

console.log(`rotorcert reproducer: ganja.js ${VERSION} EDGE-5 (APPLY-3 on a non-unit q): the sandwich R >>> (a e123) of a non-unit rotor returns |q|^2 a instead of a`);
console.log('call:    C3 = Algebra({p:3, baseType:Float64Array}); R = C3.Element(w,0,0,0,-z,y,-x,0); C3.sw(R, C3.Trivector(a)).e123');
console.log(`input:   q (w,x,y,z) = ${show([w, x, y, z])}  a = ${hex(a)}   (R = ${R})`);
console.log(`ganja:   ${got}  (${hex(got)})`);
console.log(`correct: ${want}  (${hex(want)})   [R (a I) ~R = a I for the rotation q/|q|]`);
console.log(`error:   relative ${rel.toExponential(3)} = ${(rel / EPS).toExponential(3)} eps (loose bar ${LOOSE} eps)`);
if (!(rel <= LOOSE * EPS)) { console.log('DEFECT SHOWN'); process.exit(0); }
console.log('DEFECT NOT SHOWN'); process.exit(1);
