#!/usr/bin/env node
// rotorcert reproducer: ganja.js, clause EXP-1 (spec/SPEC.md 8.2, tolerance eps16, loose bar 256 eps).
// EXP-1: exp(B) = cos|B| + B sin|B|/|B| (a series near 0), a unit rotor, judged by METRIC-1 and METRIC-6
// (unit output). ganja's Cl(3,0) Exp returns 1 + B for every simple bivector with |B| <= 1e-5, i.e. for
// rotations below 2e-5 rad: |1 + B| = sqrt(1 + |B|^2), a norm defect of |B|^2/2 (up to 5e-11 = 2.25e5 eps).
// Source (ganja.js 1.0.204): ganja.js:510 'if (len <= 1E-5) return total.Mul(Element.Scalar(1).Add(simple))'
// (see also EDGE-2.js item 1). Upstream tracker (github.com/enkimute/ganja.js/issues): no report found.
// Run: NODE_PATH=build/adapters/ganja/node_modules node EXP-1.js   (exit 0 shown, 1 not shown, 77 skip)
'use strict';
let Algebra, VERSION;
try { Algebra = require('ganja.js'); VERSION = require('ganja.js/package.json').version; } catch (e) {
  console.log('rotorcert reproducer: ganja.js EXP-1: SKIP, cannot load ganja.js: ' + e.message.split('\n')[0]);
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

// Input: the suite's worst case, v = [0x1.61f66fcfc824bp-19, -0x1.3986914fbb83ap-17, -0x1.3299c5536a286p-19]
// (|v| = 9.98e-6: a rotation by 2.0e-5 rad).
const v = [2.6372272045191147e-06, -9.343792640472652e-06, -2.2843529820691615e-06];
const got = quat(C3.Bivector(-v[2], v[1], -v[0]).Exp());
// Correct (closed form, Taylor; the dropped terms are below 1e-33): cos n = 1 - n^2/2 + n^4/24,
// sin(n)/n = 1 - n^2/6 + n^4/120, n = |v|.
const n = norm(v), c = 1 - n * n / 2 + n ** 4 / 24, sn = 1 - n * n / 6 + n ** 4 / 120;
const want = [c, ...v.map((x) => x * sn)];
const e1 = metric1(got, want), e6 = normDefect(got), err = Math.max(e1, e6);

console.log(`rotorcert reproducer: ganja.js ${VERSION} EXP-1: Exp of a bivector with |B| <= 1e-5 returns 1 + B, not a unit rotor (norm defect |B|^2/2)`);
console.log('call:    C3 = Algebra({p:3, baseType:Float64Array}); C3.Bivector(-vz, vy, -vx).Exp()');
console.log(`input:   v = ${show(v)}`);
console.log(`ganja:   (w,x,y,z) = ${show(got)}`);
console.log(`correct: (w,x,y,z) = ${show(want)}   (cos|v|, sin|v| v/|v|), unit`);
console.log(`error:   METRIC-1 ${e1.toExponential(3)} rad, METRIC-6 | |exp(v)| - 1 | = ${e6.toExponential(3)}: ` +
            `${(err / EPS).toExponential(3)} eps (loose bar ${LOOSE} eps)`);
if (!(err <= LOOSE * EPS)) { console.log('DEFECT SHOWN'); process.exit(0); }
console.log('DEFECT NOT SHOWN'); process.exit(1);
