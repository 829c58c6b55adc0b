#!/usr/bin/env node
/* rotorcert vectors adapter for ganja.js (https://github.com/enkimute/ganja.js), pinned 1.0.204.
 *
 *   node ganja_adapter.js --vectors DIR --out RESULTS.json     run every binary64 vector of the mapped ops
 *   node ganja_adapter.js --self-test                          check the package's hexfloat reader/printer
 *
 * ganja.js and rotorcert-vectors are found by plain require() (NODE_PATH or a node_modules next to
 * this file).
 * It runs through ganja's object API, never the inline translator:
 *   C3  = Algebra({p: 3, baseType: Float64Array})        Cl(3,0): rotors (rotation ops)
 *   PGA = Algebra({p: 3, r: 1, baseType: Float64Array})  Cl(3,0,1): motors (dual-quaternion ops)
 * Float64Array is ganja's documented option for binary64 (README: "R3_64"); the default Algebra(3)
 * stores coefficients in a Float32Array, which would round every result to binary32.
 *
 * Conventions (spec Q2R-1, ALG-7, MOTOR-1), written with ganja's basis names: C3's bivectors are
 * e12, e13, e23 (no e31; e31 = -e13), PGA's are e01, e02, e03, e12, e13, e23 and e0123.
 *   quaternion [x, y, z, w]  <-> rotor  w - x e23 - y e31 - z e12  = s:w, e23:-x, e13:+y, e12:-z
 *   bivector [b23, b31, b12] <-> b23 e23 + b31 e31 + b12 e12       = e23:b23, e13:-b31, e12:b12
 *   log / exp vector v       <-> the bivector Phi(0, v) = -I v      = e23:-vx, e13:+vy, e12:-vz
 *   trivector a              <-> a e123
 *   dual quaternion [r, d]   <-> motor  w_r - x_r e23 - y_r e31 - z_r e12 - x_d e01 - y_d e02 - z_d e03 - w_d e0123
 *   point (x, y, z)          <-> x e032 + y e013 + z e021 + e123, built as ganja's own point,
 *                                !(e0 + x e1 + y e2 + z e3) (.Dual of a PGA vector), and read back as
 *                                (e032, e013, e021) / e123 (MOTOR-2: division by the e123 weight).
 *
 * The ABI ops and the ganja calls they are (every other ABI op is declared unsupported):
 *   normalize        r2q( Phi(q).Normalized )
 *   compose          r2q( Phi(a).Mul(Phi(b)) )                                 (b applied first)
 *   inverse          r2q( Phi(q).Inverse )
 *   apply_vector     C3.sw(Phi(q), v)          ganja's sandwich R x ~R (the >>> operator)
 *   apply_bivector   C3.sw(Phi(q), B)
 *   apply_trivector  C3.sw(Phi(q), a e123)
 *   to_matrix        C3.sw(Phi(q).Normalized, [e1, e2, e3]): column c = image of e_c (sw maps over arrays)
 *   from_axis_angle  r2q( axis.Normalized.Dual.Scale(-angle/2).Exp() ) = exp(-I u angle/2)  (Dual = times e123 in C3)
 *   log              Phi(q).Log()  read as the vector v of Phi(0, v)
 *   exp              Phi(0, v).Exp()
 *   (log_exp_round_trip: exp of what log returned, DOMAIN_ERROR when log's output is all NaN)
 *   dq_from_rotation_translation  PGA: T.Mul(Phi(q).Normalized), T = Bivector(-t/2 on e01, e02, e03).Exp() = 1 - t e0/2
 *   dq_compose       PGA: M(a).Mul(M(b))
 *   dq_apply_point   PGA.sw(M(d), P(p))
 *   dq_normalize     PGA: M(d).Normalized  (ganja's closed form M (M ~M)^(-1/2))
 *   dq_log           PGA: M(d).Log(), its bivector read back by MOTOR-1 as the dual vector (DQ-8)
 *   dq_exp           PGA: B(xi).Exp(), B the motor bivector of the dual vector (DQ-9)
 * Rule: where ganja has a call for the op, it is called on the mapped input as it is (ganja's
 * sandwich, Log, Inverse, Mul assume nothing and check nothing; what they do with a non-unit, zero or
 * non-finite input is graded). Where ganja has no single call (to_matrix, from_axis_angle,
 * dq_from_rotation_translation) the spec's definition is written as one expression of ganja calls,
 * normalising with ganja's Normalized exactly where the definition normalises. No hemisphere flips,
 * no domain checks, no rescaling of our own: slerp, nlerp, blends and ScLERP need an adapter-written
 * hemisphere rule and are declared unsupported (adapter.json says why for every op).
 *
 * Status (RESULT-2, the rule of the rotorcert-vectors package, conformance/packages/node/lib/outcome.js,
 * the same as the Python adapters'): ganja has no status channel; an exception thrown by ganja ->
 * DOMAIN_ERROR with every output NaN; every output component NaN -> DOMAIN_ERROR; anything else ->
 * OK with the outputs as computed. A ReferenceError or TypeError is a defect of this adapter and
 * stops the run.
 *
 * Reading the vectors (exact hexfloat parser), calling the ops and writing the results file are the
 * package's (require('rotorcert-vectors'), installed beside ganja.js by scripts/setup-adapters).
 */
'use strict';

const rcv = require('rotorcert-vectors');

// ---- ganja ----------------------------------------------------------------------------------

const Algebra = require('ganja.js');
const GANJA_VERSION = require('ganja.js/package.json').version;
const C3 = Algebra({p: 3, baseType: Float64Array});
const PGA = Algebra({p: 3, r: 1, baseType: Float64Array});

/** Q2R-1 into C3: w - x e23 - y e31 - z e12 (e31 = -e13). */
function rotor(q) {
  const R = new C3();
  R.s = q[3]; R.e23 = -q[0]; R.e13 = q[1]; R.e12 = -q[2];
  return R;
}
/** The inverse of Q2R-1 on the even part: [x, y, z, w] = [-R_e23, -R_e31, -R_e12, R_s]. */
function quat(R) { return [-R.e23, R.e13, -R.e12, R.s]; }

/** [e23, e31, e12] coefficients <-> a C3 bivector. */
function bivector(b) {
  const B = new C3();
  B.e23 = b[0]; B.e13 = -b[1]; B.e12 = b[2];
  return B;
}
function bivectorCoeffs(B) { return [B.e23, -B.e13, B.e12]; }

/** The quaternion-view vector v <-> the bivector Phi(0, v) = -(vx e23 + vy e31 + vz e12). */
function logBivector(v) { return bivector([-v[0], -v[1], -v[2]]); }
function logVector(B) { const b = bivectorCoeffs(B); return [-b[0], -b[1], -b[2]]; }

/** MOTOR-1 into PGA. */
function motor(d) {
  const M = new PGA();
  M.s = d[3]; M.e23 = -d[0]; M.e13 = d[1]; M.e12 = -d[2];
  M.e01 = -d[4]; M.e02 = -d[5]; M.e03 = -d[6]; M.e0123 = -d[7];
  return M;
}
function dualQuat(M) { return [-M.e23, M.e13, -M.e12, M.s, -M.e01, -M.e02, -M.e03, -M.e0123]; }
/** The dual vector xi = [xi_r, xi_d] <-> the motor bivector -(xi_r on e23, e31, e12) - (xi_d on e01, e02, e03)
 *  (MOTOR-1 is linear; e31 = -e13). */
function motorBivector(xi) {
  const B = new PGA();
  B.e23 = -xi[0]; B.e13 = xi[1]; B.e12 = -xi[2];
  B.e01 = -xi[3]; B.e02 = -xi[4]; B.e03 = -xi[5];
  return B;
}
function dualVector(B) { return [-B.e23, B.e13, -B.e12, -B.e01, -B.e02, -B.e03]; }
/** The rotor of q embedded in PGA (Q2R-1). */
function pgaRotor(q) { return motor([q[0], q[1], q[2], q[3], 0, 0, 0, 0]); }

/** ALG-7 point x e032 + y e013 + z e021 + e123, built as ganja's point !(e0 + x e1 + y e2 + z e3). */
function point(p) { return PGA.Vector(1, p[0], p[1], p[2]).Dual; }
/** (e032, e013, e021) / e123, with e032 = -e023 and e021 = -e012. */
function pointCoords(P) { const w = P.e123; return [-P.e023 / w, P.e013 / w, -P.e012 / w]; }

const OPS = {
  normalize: (q) => quat(rotor(q).Normalized),
  compose: (a, b) => quat(rotor(a).Mul(rotor(b))),
  inverse: (q) => quat(rotor(q).Inverse),
  apply_vector: (q, v) => { const r = C3.sw(rotor(q), C3.Vector(v[0], v[1], v[2])); return [r.e1, r.e2, r.e3]; },
  apply_bivector: (q, b) => bivectorCoeffs(C3.sw(rotor(q), bivector(b))),
  apply_trivector: (q, a) => { const X = new C3(); X.e123 = a; return C3.sw(rotor(q), X).e123; },
  to_matrix: (q) => {
    const columns = C3.sw(rotor(q).Normalized, [C3.Vector(1, 0, 0), C3.Vector(0, 1, 0), C3.Vector(0, 0, 1)]);
    return columns.flatMap((c) => [c.e1, c.e2, c.e3]);  // column-major: m[c*3 + r]
  },
  from_axis_angle: (angle, axis) =>
    quat(C3.Vector(axis[0], axis[1], axis[2]).Normalized.Dual.Scale(-angle / 2).Exp()),
  log: (q) => logVector(rotor(q).Log()),
  exp: (v) => quat(logBivector(v).Exp()),
  dq_from_rotation_translation: (q, t) => {
    const T = PGA.Bivector(-t[0] / 2, -t[1] / 2, -t[2] / 2, 0, 0, 0).Exp();  // e01, e02, e03 first
    return dualQuat(T.Mul(pgaRotor(q).Normalized));
  },
  dq_compose: (a, b) => dualQuat(motor(a).Mul(motor(b))),
  dq_apply_point: (d, p) => pointCoords(PGA.sw(motor(d), point(p))),
  dq_normalize: (d) => dualQuat(motor(d).Normalized),
  dq_log: (d) => dualVector(motor(d).Log()),
  dq_exp: (xi) => dualQuat(motorBivector(xi).Exp()),
};

const IMPLEMENTATION = {
  name: 'ganja',
  version: GANJA_VERSION,
  scalar: 'double',
  description:
    'ganja.js ' + GANJA_VERSION + ' object API, Algebra({p:3,baseType:Float64Array}) rotors and ' +
    'Algebra({p:3,r:1,baseType:Float64Array}) motors (MOTOR-1), through the JSON-vectors adapter ' +
    'conformance/adapters/ganja; status rule: an exception thrown by ganja -> DOMAIN_ERROR with NaN ' +
    'outputs, every output NaN -> DOMAIN_ERROR (RESULT-2, ganja has no status channel), otherwise OK',
};

// ---- command line -----------------------------------------------------------------------------

function selfTest() {
  const report = rcv.checkHexfloat();
  for (const f of report.failures.slice(0, 20)) console.log('FAIL ' + f);
  console.log(`self-test: ${report.parseCases} parse cases, ${report.roundTrips} round trips, ${report.failures.length} failures`);
  return report.failures.length ? 1 : 0;
}

function main(argv) {
  if (argv.length === 1 && argv[0] === '--self-test') return selfTest();
  const ops = Object.assign({}, OPS, {log_exp_round_trip: rcv.roundTrip(OPS.log, OPS.exp)});
  return rcv.runAdapter(argv, 'rotorcert adapter for ganja.js ' + GANJA_VERSION +
                        ' (node ganja_adapter.js --vectors DIR --out RESULTS.json | --self-test)', IMPLEMENTATION, ops);
}

if (require.main === module) process.exitCode = main(process.argv.slice(2));

module.exports = {hexfloat: rcv.hexfloat, parseHexfloat: rcv.parseHexfloat, OPS};
