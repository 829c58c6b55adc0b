#!/usr/bin/env node
/* rotorcert vectors adapter for gl-matrix (https://github.com/toji/gl-matrix), npm `gl-matrix`, pinned 3.4.4.
 *
 *   node gl_matrix_adapter.js --vectors DIR --out RESULTS.json   run every binary32 vector of the mapped ops
 *   node gl_matrix_adapter.js --self-test                        check the package's hexfloat reader/printer
 *
 * gl-matrix is certified as its users get it by default: glMatrix.ARRAY_TYPE is Float32Array
 * (common.js: `ARRAY_TYPE = typeof Float32Array !== "undefined" ? Float32Array : Array`), so every
 * quat, quat2, vec3, mat3 and mat4 made by create() / fromValues() stores binary32, while the
 * functions compute in JavaScript numbers (binary64) between the loads and the stores. The
 * adapter therefore answers the binary32 vectors (`scalar: float`): each input, a binary32 value,
 * is stored exactly in a Float32Array made by gl-matrix's fromValues(); each output is the
 * Float32Array gl-matrix wrote (create()), i.e. the binary64 result rounded once to binary32 by
 * the store. The one output gl-matrix returns as a plain number, quat.getAxisAngle's angle, is
 * stored into the binary32 ABI output by Math.fround, as a user storing it in a Float32Array (or
 * a C plugin writing a float*) would. The adapter never calls glMatrix.setMatrixArrayType.
 *
 * Conventions: gl-matrix's quat is [x, y, z, w] ("Quaternion in the format XYZW", quat.js), which is
 * LAYOUT-1; quat.multiply(out, a, b) is the Hamilton product a b (out[0] = ax bw + aw bx + ay bz -
 * az by), so compose(a, b) = a b, b applied first; vec3.transformQuat is the active rotation
 * v' = q v q*; mat3 and mat4 are column-major (m[c*3 + r]), as LAYOUT-1; quat2 is [real xyzw,
 * dual xyzw] ("Format: [real, dual]", quat2.js) with dual = 1/2 t real (fromRotationTranslation),
 * which is the ABI's dual quaternion layout, no conversion. Angles are radians.
 *
 * The ABI ops and the gl-matrix calls they are (every other ABI op is declared unsupported):
 *   normalize        quat.normalize(quat.create(), q)
 *   compose          quat.multiply(quat.create(), a, b)
 *   inverse          quat.invert(quat.create(), q)
 *   apply_vector     vec3.transformQuat(vec3.create(), v, q)
 *   to_matrix        mat3.fromQuat(mat3.create(), q)
 *   from_matrix      quat.fromMat3(quat.create(), mat3.fromValues(...m))   (not normalised: documented)
 *   to_axis_angle    angle = quat.getAxisAngle(axis = vec3.create(), q)
 *   from_axis_angle  quat.setAxisAngle(quat.create(), vec3.fromValues(...axis), angle)
 *   log              quat.ln(quat.create(), q): its vector part [x, y, z] (its w is ln|q|, the log of
 *                    the norm, which the ABI's log of q/|q| does not have)
 *   exp              quat.exp(quat.create(), quat.fromValues(vx, vy, vz, 0)): the exponential of the
 *                    pure quaternion (0, v), e^0 (cos|v|, sin|v| v/|v|), EXP-1 exactly
 *   slerp            quat.slerp(quat.create(), a, b, t)
 *   dq_from_rotation_translation  quat2.fromRotationTranslation(quat2.create(), q, t)
 *   dq_compose       quat2.multiply(quat2.create(), a, b)
 *   dq_normalize     quat2.normalize(quat2.create(), d)
 *   dq_apply_point   vec3.transformMat4(vec3.create(), p, mat4.fromQuat2(mat4.create(), d))
 *                    (gl-matrix has no dual-quaternion point transform: its users go through the
 *                    4x4 matrix of the dual quaternion, as here)
 *   to_angle         quat.getAxisAngle(vec3.create(), q)      gl-matrix has no angle-only or axis-only
 *   to_axis          axis written by quat.getAxisAngle(axis, q)   call: each is read from the one call
 *   dq_to_rotation_translation   quat2.getReal(quat.create(), d), quat2.getTranslation(vec3.create(), d)
 *   rigid_compose    M = mat4.multiply(mat4.create(), RT(qa, ta), RT(qb, tb)); mat4.getRotation(quat.create(), M),
 *                    mat4.getTranslation(vec3.create(), M), RT(q, t) = mat4.fromRotationTranslation(mat4.create(), q, t)
 *   rigid_apply      vec3.transformMat4(vec3.create(), p, RT(q, t))
 *   rigid_inverse    M = mat4.invert(mat4.create(), RT(q, t)) (null for a singular matrix: DOMAIN_ERROR);
 *                    mat4.getRotation, mat4.getTranslation of M
 * Rule: each op is the library call on the input as given: no normalisation, no domain check, no
 * hemisphere flip of our own. What gl-matrix does with a non-unit, zero or non-finite input is graded.
 *
 * Status (RESULT-2, the rule of the rotorcert-vectors package, conformance/packages/node/lib/outcome.js):
 * gl-matrix has no status channel and throws nothing here; every output component NaN ->
 * DOMAIN_ERROR; anything else -> OK with the outputs as computed.
 */
'use strict';

const rcv = require('rotorcert-vectors');
const glm = require('gl-matrix');
const GL_MATRIX_VERSION = require('gl-matrix/package.json').version;
const {glMatrix, quat, quat2, vec3, mat3, mat4} = glm;

const Q = (q) => quat.fromValues(q[0], q[1], q[2], q[3]);
const V = (v) => vec3.fromValues(v[0], v[1], v[2]);
const RT = (q, t) => mat4.fromRotationTranslation(mat4.create(), Q(q), V(t));

const OPS = {
  normalize: (q) => quat.normalize(quat.create(), Q(q)),
  compose: (a, b) => quat.multiply(quat.create(), Q(a), Q(b)),
  inverse: (q) => quat.invert(quat.create(), Q(q)),
  apply_vector: (q, v) => vec3.transformQuat(vec3.create(), V(v), Q(q)),
  to_matrix: (q) => mat3.fromQuat(mat3.create(), Q(q)),
  from_matrix: (m) => quat.fromMat3(quat.create(), mat3.fromValues(m[0], m[1], m[2], m[3], m[4], m[5], m[6], m[7], m[8])),
  to_axis_angle: (q) => {
    const axis = vec3.create();
    const angle = quat.getAxisAngle(axis, Q(q));
    return [Math.fround(angle), axis];
  },
  from_axis_angle: (angle, axis) => quat.setAxisAngle(quat.create(), V(axis), angle),
  log: (q) => quat.ln(quat.create(), Q(q)).slice(0, 3),
  exp: (v) => quat.exp(quat.create(), quat.fromValues(v[0], v[1], v[2], 0)),
  slerp: (a, b, t) => quat.slerp(quat.create(), Q(a), Q(b), t),
  dq_from_rotation_translation: (q, t) => quat2.fromRotationTranslation(quat2.create(), Q(q), V(t)),
  dq_compose: (a, b) => quat2.multiply(quat2.create(), quat2.fromValues(...a), quat2.fromValues(...b)),
  dq_normalize: (d) => quat2.normalize(quat2.create(), quat2.fromValues(...d)),
  dq_apply_point: (d, p) => vec3.transformMat4(vec3.create(), V(p), mat4.fromQuat2(mat4.create(), quat2.fromValues(...d))),
  to_angle: (q) => Math.fround(quat.getAxisAngle(vec3.create(), Q(q))),
  to_axis: (q) => {
    const axis = vec3.create();
    quat.getAxisAngle(axis, Q(q));
    return axis;
  },
  dq_to_rotation_translation: (d) => {
    const D = quat2.fromValues(...d);
    return [quat2.getReal(quat.create(), D), quat2.getTranslation(vec3.create(), D)];
  },
  // ABI version 4: rigid transforms as a gl-matrix user holds them, a mat4 from
  // mat4.fromRotationTranslation(out, q, t) (x -> R x + t), composed with mat4.multiply(out, a, b)
  // (a b: b applied first), applied with vec3.transformMat4, inverted with mat4.invert, read back
  // with mat4.getRotation / mat4.getTranslation.
  rigid_compose: (qa, ta, qb, tb) => {
    const M = mat4.multiply(mat4.create(), RT(qa, ta), RT(qb, tb));
    return [mat4.getRotation(quat.create(), M), mat4.getTranslation(vec3.create(), M)];
  },
  rigid_apply: (q, t, p) => vec3.transformMat4(vec3.create(), V(p), RT(q, t)),
  rigid_inverse: (q, t) => {
    const M = mat4.invert(mat4.create(), RT(q, t));
    return M === null ? null : [mat4.getRotation(quat.create(), M), mat4.getTranslation(vec3.create(), M)];
  },
};

const IMPLEMENTATION = {
  name: 'gl_matrix',
  version: GL_MATRIX_VERSION,
  scalar: 'float',
  description:
    'gl-matrix ' + GL_MATRIX_VERSION + ' (npm gl-matrix) quat, quat2, vec3, mat3, mat4 with the default ' +
    'glMatrix.ARRAY_TYPE Float32Array: binary32 storage, binary64 JavaScript arithmetic between loads and stores, ' +
    'through the JSON-vectors adapter conformance/adapters/gl_matrix; status rule: every output NaN -> DOMAIN_ERROR ' +
    '(RESULT-2, gl-matrix has no status channel), otherwise OK',
};

function selfTest() {
  const report = rcv.checkHexfloat();
  for (const f of report.failures.slice(0, 20)) console.log('FAIL ' + f);
  console.log(`self-test: ${report.parseCases} parse cases, ${report.roundTrips} round trips, ${report.failures.length} failures`);
  return report.failures.length ? 1 : 0;
}

function main(argv) {
  if (argv.length === 1 && argv[0] === '--self-test') return selfTest();
  if (glMatrix.ARRAY_TYPE !== Float32Array) {
    console.error('gl-matrix ARRAY_TYPE is not Float32Array: this adapter certifies the default binary32 storage');
    return 1;
  }
  return rcv.runAdapter(argv, 'rotorcert adapter for gl-matrix ' + GL_MATRIX_VERSION +
                        ' (node gl_matrix_adapter.js --vectors DIR --out RESULTS.json | --self-test)', IMPLEMENTATION, OPS);
}

if (require.main === module) process.exitCode = main(process.argv.slice(2));

module.exports = {OPS};
