#!/usr/bin/env node
// rotorcert reproducer: ganja.js, clause EDGE-5 (spec/SPEC.md 9, tolerance eps16, loose bar 256 eps).
// EDGE-5: a finite nonzero q means the rotation q/|q| at every scale the format holds, and unit-valued
// outputs stay unit (INV-1 is defined on the unnormalised q: q^-1 = q*/|q|^2). ganja neither scales nor
// normalises: Inverse divides by <R ~R R ~R>_0 = |q|^4 (overflows), Normalized computes
// sqrt(<R conj R>_0) (overflows / underflows; these NORM-1 failures are judged here now), Log takes acos
// of the unnormalised scalar, and the sandwich R x ~R of a non-unit rotor scales x by |q|^2.
// Source (ganja.js 1.0.204): Inverse ganja.js:1862, Length/Normalized ganja.js:225/234, Log ganja.js:534
// 'si.Scale(Math.acos(ci)/len)', sandwich ganja.js:675. Upstream tracker: no report found.
// Run: NODE_PATH=build/adapters/ganja/node_modules node EDGE-5.js   (exit 0 shown, 1 not shown, 77 skip)
'use strict';
let Algebra, VERSION;
try { Algebra = require('ganja.js'); VERSION = require('ganja.js/package.json').version; } catch (e) {
  console.log('rotorcert reproducer: ganja.js EDGE-5: SKIP, cannot load ganja.js: ' + e.message.split('\n')[0]);
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
// Quaternion (w, x, y, z) <-> rotor w - x e23 - y e31 - z e12 (spec Q2R-1) = [w, 0,0,0, -z, +y, -x, 0];
// the quaternion-view log v is the bivector -(vx e23 + vy e31 + vz e12).
const C3 = Algebra({p: 3, baseType: Float64Array});
const rotor = (w, x, y, z) => C3.Element(w, 0, 0, 0, -z, y, -x, 0);
const quat = (R) => [R.s, -R.e23, R.e13, -R.e12];        // (w, x, y, z)
const logv = (B) => [-B.e23, B.e13, -B.e12];

console.log(`rotorcert reproducer: ganja.js ${VERSION} EDGE-5: no scaling of non-unit inputs: Inverse and Normalized overflow/underflow, Log takes acos(w) of non-unit q, the sandwich scales by |q|^2`);
let shown = false;
// err(got, want) in the clause's metric; a NaN error counts as infinite.
const compRel = (g, w) => Math.max(...g.map((c, i) => Math.abs(c - w[i]))) / Math.hypot(...w);  // INV-1
const normDefect = (g) => Math.abs(Math.hypot(...g) - 1);                                      // METRIC-6
const absDiff = (g, w) => Math.hypot(...g.map((c, i) => c - w[i]));                            // METRIC-5
function check(tag, call, input, got, want, why, err, metric) {
  const e = Number.isNaN(err) ? Infinity : err / EPS; shown = shown || !(e <= LOOSE);
  console.log(`\n[${tag}] call:    ${call}\n    input:   ${input}\n    ganja:   ${show(got)}` +
              (got.every(Number.isNaN) ? '   (all NaN: a spurious DOMAIN_ERROR)' : ''));
  console.log(`    correct: ${show(want)}   ${why}`);
  console.log(`    error:   ${Number.isNaN(err) ? 'NaN' : err.toExponential(3)} ${metric} = ${e.toExponential(3)} eps (loose bar ${LOOSE} eps)`);
}

// 1. INV-1: q = 2^400 (1, 1, 1, 1) (w,x,y,z): q^-1 = q*/|q|^2 = 2^400 (1,-1,-1,-1) / 2^802, exact.
{ const a = 2.5822498780869086e+120, h = 2 ** -402, want = [h, -h, -h, -h];   // a = 2^400
  const got = quat(rotor(a, a, a, a).Inverse);
  check(1, 'C3.Element(w,0,0,0,-z,y,-x,0).Inverse', 'q (w,x,y,z) = ' + show([a, a, a, a]), got, want,
        'q*/|q|^2 = 2^-402 (1,-1,-1,-1)', compRel(got, want), 'componentwise relative (INV-1)'); }
// 2. NORM-1 at the top of the range: q = 2^1023 (1, 1, 1, 1), q/|q| = (0.5, 0.5, 0.5, 0.5) exactly.
{ const a = 8.98846567431158e+307, got = quat(rotor(a, a, a, a).Normalized);   // a = 2^1023
  check(2, 'C3.Element(w,0,0,0,-z,y,-x,0).Normalized', 'q (w,x,y,z) = ' + show([a, a, a, a]), got,
        [0.5, 0.5, 0.5, 0.5], 'q/|q|, |q| = 2^1024, unit', normDefect(got), '= | |out| - 1 | (METRIC-6)'); }
// 3. NORM-1 low in the range (normal numbers whose squares underflow): q = 2^-999 (2, 1.5, 0, 0),
//    |q| = 2.5 * 2^-999, q/|q| = (0.8, 0.6, 0, 0) (the doubles nearest 4/5 and 3/5).
{ const w = 3.7330544740128755e-301, x = 2.7997908555096566e-301;   // 2^-998, 1.5 * 2^-999
  const got = quat(rotor(w, x, 0, 0).Normalized);
  check(3, 'C3.Element(w,0,0,0,-z,y,-x,0).Normalized', 'q (w,x,y,z) = ' + show([w, x, 0, 0]), got,
        [0.8, 0.6, 0, 0], 'q/|q| = (4/5, 3/5, 0, 0), unit', normDefect(got), '= | |out| - 1 | (METRIC-6)'); }
// 4. LOG-1 (scale-free): q = (2, 0, 0, 2): log q = atan2(|v|, w) v/|v| = (0, 0, pi/4), a quarter turn about z.
{ const got = logv(rotor(2, 0, 0, 2).Log()), want = [0, 0, Math.PI / 4];
  check(4, 'C3.Element(w,0,0,0,-z,y,-x,0).Log()', 'q (w,x,y,z) = ' + show([2, 0, 0, 2]), got, want,
        '(0, 0, pi/4) rounded', absDiff(got, want), 'rad (METRIC-5)'); }
// 5. APPLY-1: q = (2, 2, 2, 2) is the 120-degree turn about (1,1,1), which maps (x, y, z) to (z, x, y).
{ const r = C3.sw(rotor(2, 2, 2, 2), C3.Vector(1, 2, 3)), got = [r.e1, r.e2, r.e3], want = [3, 1, 2];
  check(5, 'C3.sw(C3.Element(w,0,0,0,-z,y,-x,0), C3.Vector(1,2,3))   (R >>> v)',
        'q (w,x,y,z) = ' + show([2, 2, 2, 2]) + '  v = ' + show([1, 2, 3]), got, want,
        'R v ~R of R = q/|q|', absDiff(got, want) / Math.hypot(1, 2, 3), 'relative to |v| (METRIC-3)'); }
if (shown) { console.log('\nDEFECT SHOWN'); process.exit(0); }
console.log('\nDEFECT NOT SHOWN'); process.exit(1);
