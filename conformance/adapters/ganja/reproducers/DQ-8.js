#!/usr/bin/env node
// rotorcert reproducer: ganja.js, clause DQ-8 (spec/SPEC.md 8.4, tolerance eps32, loose bar 512 eps).
// DQ-8: the log of a unit dual quaternion (motor) is the dual vector xi with exp(xi) = sigma (DQ-9); the
// principal branch, or the log of -sigma where r_w <= 0 (ACC-1 shorter_arc): any xi whose exp is +-sigma.
// ganja's 3D PGA Log (ganja.js:524) returns the ideal part alone, 'if (Math.abs(this.s)>=.99999) return
// Element.Bivector(this[5],this[6],this[7],0,0,0).Scale(Math.sign(this.s))', whenever the rotation angle is
// below 2 acos(0.99999) = 0.0089 rad (or that close to a full turn): it drops the rotation, so exp(Log M) is a
// pure translation, neither M nor -M. (Above the threshold it uses acos(s), the log of a normalised motor.)
// Upstream tracker (github.com/enkimute/ganja.js/issues): no report found.
// Run: NODE_PATH=build/adapters/ganja/node_modules node DQ-8.js   (exit 0 shown, 1 not shown, 77 skip)
'use strict';
let Algebra, VERSION;
try { Algebra = require('ganja.js'); VERSION = require('ganja.js/package.json').version; } catch (e) {
  console.log('rotorcert reproducer: ganja.js DQ-8: SKIP, cannot load ganja.js: ' + e.message.split('\n')[0]);
  process.exit(77);
}
const EPS = 2 ** -52, LOOSE = 512;
const PGA = Algebra({p: 3, r: 1, baseType: Float64Array});
// MOTOR-1: the dual quaternion [x_r, y_r, z_r, w_r, x_d, y_d, z_d, w_d] is the motor
// w_r - x_r e23 - y_r e31 - z_r e12 - x_d e01 - y_d e02 - z_d e03 - w_d e0123 (e31 = -e13); a bivector B
// reads back as the dual vector xi = [-e23, e13, -e12, -e01, -e02, -e03].
function motor(d) {
  const M = new PGA();
  M.s = d[3]; M.e23 = -d[0]; M.e13 = d[1]; M.e12 = -d[2]; M.e01 = -d[4]; M.e02 = -d[5]; M.e03 = -d[6]; M.e0123 = -d[7];
  return M;
}
const dualVector = (B) => [-B.e23, B.e13, -B.e12, -B.e01, -B.e02, -B.e03];
/** DQ-9 in binary64: exp of a dual vector as a dual quaternion [x, y, z, w, dx, dy, dz, dw]. */
function exp(xi) {
  const b = Math.hypot(xi[0], xi[1], xi[2]);
  if (b === 0) return [0, 0, 0, 1, xi[3], xi[4], xi[5], 0];
  const n = xi.slice(0, 3).map((c) => c / b), a = xi[3] * n[0] + xi[4] * n[1] + xi[5] * n[2];
  const perp = [0, 1, 2].map((i) => xi[3 + i] - a * n[i]);
  return [...n.map((c) => Math.sin(b) * c), Math.cos(b),
    ...[0, 1, 2].map((i) => a * Math.cos(b) * n[i] + Math.sin(b) / b * perp[i]), -a * Math.sin(b)];
}
// A unit motor: a turn of 0.004 rad about (1, 2, 2)/3 and the translation (1, 2, 3), built as DQ-1
// (r = (cos h, sin h u), d = 1/2 t r) in binary64.
const h = 0.002, u = [1 / 3, 2 / 3, 2 / 3], t = [1, 2, 3];
const r = [...u.map((c) => Math.sin(h) * c), Math.cos(h)];                          // [x, y, z, w]
const d = [0.5 * (t[0] * r[3] + t[1] * r[2] - t[2] * r[1]), 0.5 * (-t[0] * r[2] + t[1] * r[3] + t[2] * r[0]),
  0.5 * (t[0] * r[1] - t[1] * r[0] + t[2] * r[3]), -0.5 * (t[0] * r[0] + t[1] * r[1] + t[2] * r[2])];
const sigma = [...r, ...d];
const xi = dualVector(motor(sigma).Log());
const back = exp(xi);
// The same rigid motion as sigma or -sigma: real parts absolute, dual parts relative to max(1, |d|).
const off = (s) => Math.max(Math.max(...[0, 1, 2, 3].map((i) => Math.abs(back[i] - s * sigma[i]))),
  Math.hypot(...[4, 5, 6, 7].map((i) => back[i] - s * sigma[i])) / Math.max(1, Math.hypot(...d)));
const err = Math.min(off(1), off(-1));
const shown = !(err <= LOOSE * EPS * 4);
console.log(`rotorcert reproducer: ganja.js ${VERSION} DQ-8: Log of a motor turning by less than 0.0089 rad drops the rotation`);
console.log('call:    PGA = Algebra({p:3, r:1, baseType:Float64Array}); M(sigma).Log()');
console.log(`input:   sigma = [${sigma.join(', ')}]  (a 0.004 rad turn, translation (1, 2, 3))`);
console.log(`library: xi = [${xi.join(', ')}]  (the rotation part xi_r is 0)`);
console.log(`exp(xi): [${back.join(', ')}]  (DQ-9), a pure translation, neither sigma nor -sigma`);
console.log(`error:   ${(err / EPS).toExponential(3)} eps`);
console.log(shown ? 'DEFECT SHOWN' : 'DEFECT NOT SHOWN');
process.exit(shown ? 0 : 1);
