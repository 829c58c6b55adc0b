#!/usr/bin/env node
// rotorcert reproducer: ganja.js, clause DQ-9 (spec/SPEC.md 8.4, tolerance eps16, loose bar 256 eps).
// DQ-9: exp(xi_r + eps xi_d) = (cos b, sin b n) + eps (-a sin b, a cos b n + (sin b / b) xi_perp) with
// b = |xi_r|, n = xi_r / b, a = xi_d . n: a screw by the angle 2b with the translation 2a along its axis.
// ganja's 3D PGA Exp returns 1 + B whenever the rotation part is below 1e-5 (ganja.js:499, 'if
// (Math.abs(u)<1E-5) return this.Add(Element.Scalar(1))'): it drops cos b - 1 and the pitch term -a sin b,
// so a screw with a small turn and a long translation along its axis loses the e0123 part of the motor
// (dual w) and the second-order part of the rotation.
// Upstream tracker (github.com/enkimute/ganja.js/issues): no report found.
// Run: NODE_PATH=build/adapters/ganja/node_modules node DQ-9.js   (exit 0 shown, 1 not shown, 77 skip)
'use strict';
let Algebra, VERSION;
try { Algebra = require('ganja.js'); VERSION = require('ganja.js/package.json').version; } catch (e) {
  console.log('rotorcert reproducer: ganja.js DQ-9: SKIP, cannot load ganja.js: ' + e.message.split('\n')[0]);
  process.exit(77);
}
const EPS = 2 ** -52, LOOSE = 256;
const PGA = Algebra({p: 3, r: 1, baseType: Float64Array});
// MOTOR-1: the dual vector xi = [xi_r, xi_d] is the bivector -(xi_r on e23, e31, e12) - (xi_d on e01, e02, e03)
// (e31 = -e13); a motor M reads back as the dual quaternion [-e23, e13, -e12, s, -e01, -e02, -e03, -e0123].
function bivector(xi) {
  const B = new PGA();
  B.e23 = -xi[0]; B.e13 = xi[1]; B.e12 = -xi[2]; B.e01 = -xi[3]; B.e02 = -xi[4]; B.e03 = -xi[5];
  return B;
}
const dualQuat = (M) => [-M.e23, M.e13, -M.e12, M.s, -M.e01, -M.e02, -M.e03, -M.e0123];
// The suite's worst input (hexfloat): xi = [0x1.f922ea10799bep-19, 0x1.d4d7612847159p-18, 0x1.097a1246b03d1p-18,
// 0x1.fb34860de852dp-4, 0x1.4b6878456a91fp+1, 0x1.3931139c2220dp+1]: a turn of 1.8e-5 rad.
const xi = ['0x1.f922ea10799bep-19', '0x1.d4d7612847159p-18', '0x1.097a1246b03d1p-18', '0x1.fb34860de852dp-4',
  '0x1.4b6878456a91fp+1', '0x1.3931139c2220dp+1'].map((h) => {
  const [m, e] = h.slice(2).split('p'); const [i, f] = m.split('.');
  return (parseInt(i, 16) + parseInt(f, 16) / 16 ** f.length) * 2 ** Number(e);
});
const got = dualQuat(bivector(xi).Exp());
// DQ-9 in binary64 (well conditioned here: every term is computed without cancellation).
const b = Math.hypot(xi[0], xi[1], xi[2]), n = xi.slice(0, 3).map((c) => c / b);
const a = xi[3] * n[0] + xi[4] * n[1] + xi[5] * n[2], perp = [0, 1, 2].map((i) => xi[3 + i] - a * n[i]);
const want = [...n.map((c) => Math.sin(b) * c), Math.cos(b),
  ...[0, 1, 2].map((i) => a * Math.cos(b) * n[i] + Math.sin(b) / b * perp[i]), -a * Math.sin(b)];
const scale = Math.max(1, Math.hypot(xi[3], xi[4], xi[5]));
const err = Math.max(Math.max(...[0, 1, 2, 3].map((i) => Math.abs(got[i] - want[i]))),
  Math.hypot(...[4, 5, 6, 7].map((i) => got[i] - want[i])) / scale);
const shown = !(err <= LOOSE * 16 * EPS);
console.log(`rotorcert reproducer: ganja.js ${VERSION} DQ-9: Exp of a screw with a turn below 1e-5 rad returns 1 + B`);
console.log('call:    PGA = Algebra({p:3, r:1, baseType:Float64Array}); B(xi).Exp()');
console.log(`input:   xi = [${xi.join(', ')}]`);
console.log(`library: [${got.join(', ')}]`);
console.log(`correct: [${want.join(', ')}]  (DQ-9)`);
console.log(`error:   ${(err / EPS).toExponential(3)} eps (real part absolute, dual part relative to max(1, |xi_d|))`);
console.log(shown ? 'DEFECT SHOWN' : 'DEFECT NOT SHOWN');
process.exit(shown ? 0 : 1);
