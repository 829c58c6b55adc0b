#!/usr/bin/env node
// rotorcert reproducer: ganja.js, clause DQ-4 (spec/SPEC.md 8.4, tolerance eps16, loose bar 256 eps).
// DQ-4: normalising sigma = (r, d) gives r' = r/|r|, d' = d/|r| - ((r.d)/|r|^3) r, which keeps the rotation
// of r and the translation t = vector part of 2 d r*/|r|^2; judged by METRIC-7 (rotation and
// |t' - t|/max(1, |t|)), METRIC-6 of r' and |r'.d'|. ganja's PGA motor M.Normalized computes
// S = M ~M, keeps S's scalar s and e0123 part p and replaces them by 1/sqrt(s) and -p/(2 s^1.5), but leaves the
// rest of S in place: the bivector parts of M ~M (exactly 0 in exact arithmetic, but ~|r||d| eps after its
// rounded products) are multiplied back into M, a translation error of ~|r|^2 eps relative that the
// 1/|r| scaling does not remove (400 eps for |r| = 8, |t| = 21, an ordinary motor). Zeroing S's other
// components first (M.Mul(new PGA with only s and p)) gives 0.13 eps on the same input.
// Source (ganja.js 1.0.204): ganja.js:229-232 'var sq = this.Mul(this.Reverse) ... sq[0] = 1/Math.sqrt(s);
// sq[15] = -t/(2*Math.pow(Math.sqrt(s),3)); return this.Mul(sq);'. Upstream tracker: no report found.
// Run: NODE_PATH=build/adapters/ganja/node_modules node DQ-4.js   (exit 0 shown, 1 not shown, 77 skip)
'use strict';
let Algebra, VERSION;
try { Algebra = require('ganja.js'); VERSION = require('ganja.js/package.json').version; } catch (e) {
  console.log('rotorcert reproducer: ganja.js DQ-4: SKIP, cannot load ganja.js: ' + e.message.split('\n')[0]);
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

// Exact rationals [num, den] (BigInt) of doubles, for the reference translation (no square roots needed).
function rat(x) {
  const dv = new DataView(new ArrayBuffer(8)); dv.setFloat64(0, x);
  const bits = dv.getBigUint64(0), field = Number((bits >> 52n) & 0x7ffn), neg = bits >> 63n;
  let m = bits & ((1n << 52n) - 1n), e = field - 1075;
  if (field) m |= 1n << 52n; else e = -1074;
  if (neg) m = -m;
  return e >= 0 ? [m << BigInt(e), 1n] : [m, 1n << BigInt(-e)];
}
const add = (a, b) => [a[0] * b[1] + b[0] * a[1], a[1] * b[1]], mul = (a, b) => [a[0] * b[0], a[1] * b[1]];
const neg = (a) => [-a[0], a[1]], sub = (a, b) => add(a, neg(b)), div = (a, b) => b[0] < 0n ? [-a[0] * b[1], -a[1] * b[0]] : [a[0] * b[1], a[1] * b[0]];
function num(a) {  // nearest double of a rational, to ~2^-60 relative
  if (a[0] === 0n) return 0;
  const k = a[1].toString(2).length - (a[0] < 0n ? -a[0] : a[0]).toString(2).length + 64;
  return Number(k >= 0 ? (a[0] << BigInt(k)) / a[1] : a[0] / (a[1] << BigInt(-k))) * 2 ** -k;
}
/** Vector part of 2 d r* / |r|^2 (quaternions [x, y, z, w]), exactly: the translation of sigma. */
function translation(r, d) {
  const [rx, ry, rz, rw] = r.map(rat), [dx, dy, dz, dw] = d.map(rat), two = [2n, 1n];
  const n2 = [rx, ry, rz, rw].reduce((s, c) => add(s, mul(c, c)), [0n, 1n]);
  const v = [  // vec(d conj(r)) = -dw r + rw d - d x r
    sub(sub(mul(rw, dx), mul(dw, rx)), sub(mul(dy, rz), mul(dz, ry))),
    sub(sub(mul(rw, dy), mul(dw, ry)), sub(mul(dz, rx), mul(dx, rz))),
    sub(sub(mul(rw, dz), mul(dw, rz)), sub(mul(dx, ry), mul(dy, rx)))];
  return v.map((c) => div(mul(two, c), n2));
}

// Conventions: PGA Cl(3,0,1) in binary64; the dual quaternion ([x,y,z,w]_r, [x,y,z,w]_d) is the motor
// w_r - x_r e23 - y_r e31 - z_r e12 - x_d e01 - y_d e02 - z_d e03 - w_d e0123 (spec MOTOR-1; e31 = -e13).
const PGA = Algebra({p: 3, r: 1, baseType: Float64Array});
function motor(d) {
  const M = new PGA();
  M.s = d[3]; M.e23 = -d[0]; M.e13 = d[1]; M.e12 = -d[2]; M.e01 = -d[4]; M.e02 = -d[5]; M.e03 = -d[6]; M.e0123 = -d[7];
  return M;
}
const dualQuat = (M) => [-M.e23, M.e13, -M.e12, M.s, -M.e01, -M.e02, -M.e03, -M.e0123];

// Input: the suite's worst case (random rigid motion): d = [0x1.8c78d65693db2p-2, 0x1.031128d021192p+1,
// 0x1.e2e82febb3d29p+2, 0x1.adeb3e6de4fb8p+0, 0x1.f4b4672214801p+4, 0x1.a89f66f11fb55p+4,
// -0x1.b7b16a4b8c05dp+4, 0x1.15aabf7582c3ap+6]  (|r| = 8, r.d = -24.9, |t| = 21.3).
const sig = [0.3871797075598479, 2.02396116411746, 7.545421581438213, 1.679370786504462,
             31.294043667912778, 26.53891653241165, -27.48081426153691, 69.41674598322507];
const M = motor(sig), out = dualQuat(M.Normalized), S = M.Mul(M.Reverse);
const r = sig.slice(0, 4), ro = out.slice(0, 4), dO = out.slice(4);
// Correct, exactly: t = vec(2 d r*)/|r|^2 of the input; the output's translation after DQ-4 is vec(2 d' r'*)/|r'|^2.
const tRef = translation(r, sig.slice(4)), tOut = translation(ro, dO);
const tn = Math.sqrt(num(tRef.reduce((s, c) => add(s, mul(c, c)), [0n, 1n])));
const eTrans = Math.sqrt(num(tOut.map((c, i) => sub(c, tRef[i])).reduce((s, c) => add(s, mul(c, c)), [0n, 1n]))) / Math.max(1, tn);
const n2o = ro.map(rat).reduce((s, c) => add(s, mul(c, c)), [0n, 1n]);
const eNorm = Math.abs(num(sub(n2o, [1n, 1n]))) / 2;                      // | |r'| - 1 | (to first order)
const eOrth = Math.abs(num(ro.map(rat).reduce((s, c, i) => add(s, mul(c, rat(dO[i]))), [0n, 1n]))) / Math.max(1, tn);
// For display: the closed form of DQ-4 in binary64 (a few ulps).
const nr = Math.hypot(...r), rd = r.reduce((s, c, i) => s + c * sig[4 + i], 0);
const want = [...r.map((c) => c / nr), ...sig.slice(4).map((c, i) => c / nr - rd / nr ** 3 * r[i])];
// METRIC-1 of the real parts (binary64 after normalising both: accurate to ~2 eps; not decisive here).
const unit = (q) => { const n = Math.hypot(...q); return q.map((c) => c / n); }, a = unit(ro), b = unit(r);
const dm = Math.hypot(...a.map((c, i) => c - b[i])), dp = Math.hypot(...a.map((c, i) => c + b[i]));
const eRot = 4 * Math.atan2(Math.min(dm, dp), Math.max(dm, dp));
const err = Math.max(eRot, eTrans, eNorm, eOrth);

console.log(`rotorcert reproducer: ganja.js ${VERSION} DQ-4: the PGA motor's Normalized multiplies the rounding residue of M ~M's bivector part back into M: translation error ${(eTrans / EPS).toFixed(1)} eps`);
console.log('call:    PGA = Algebra({p:3, r:1, baseType:Float64Array}); M.Normalized');
console.log(`input:   sigma (r; d) = ${show(sig)}`);
console.log(`         M ~M: s = ${hex(S.s)}, e0123 = ${hex(S.e0123)}, and [e01, e02, e03, e12, e13, e23] = ` +
            `${show([S.e01, S.e02, S.e03, S.e12, S.e13, S.e23])} (exactly 0 in exact arithmetic; kept by Normalized)`);
console.log(`ganja:   sigma' = ${show(out)}`);
console.log(`correct: sigma' = ${show(want)}   (r/|r|, d/|r| - (r.d/|r|^3) r; binary64, a few ulps)`);
console.log(`         t = [${tRef.map(num).join(', ')}] (exact: vec(2 d r*)/|r|^2), ganja's t' = [${tOut.map(num).join(', ')}]`);
console.log(`error:   METRIC-7: |t' - t|/max(1,|t|) = ${eTrans.toExponential(3)} = ${(eTrans / EPS).toFixed(1)} eps, ` +
            `rotation ${eRot.toExponential(3)} rad = ${(eRot / EPS).toFixed(1)} eps;`);
console.log(`         METRIC-6 ${(eNorm / EPS).toFixed(2)} eps; |r'.d'|/max(1,|t|) ${(eOrth / EPS).toFixed(2)} eps (loose bar ${LOOSE} eps)`);
if (!(err <= LOOSE * EPS)) { console.log('DEFECT SHOWN'); process.exit(0); }
console.log('DEFECT NOT SHOWN'); process.exit(1);
