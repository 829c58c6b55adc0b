'use strict';
/* The example library's tests, run by `node --test`: its own unit tests, and its certificate. The
 * rotorcert test certifies when ROTORCERT_VECTORS names an export (`rotorcert vectors export`) and
 * is skipped otherwise; ROTORCERT_RESULTS (the results file) and ROTORCERT_CHECK (the rotorcert
 * executable: grade the results) are optional. */

const assert = require('node:assert');
const {test} = require('node:test');
const {certify, Implementation} = require('rotorcert-vectors');
const quaternion = require('./quaternion');

test('compose applies the right factor first', () => {
  const quarterZ = [0, 0, Math.SQRT1_2, Math.SQRT1_2];  // 90 degrees about z
  const quarterX = [Math.SQRT1_2, 0, 0, Math.SQRT1_2];  // 90 degrees about x
  const v = quaternion.applyVector(quaternion.compose(quarterZ, quarterX), [0, 1, 0]);
  [0, 0, 1].forEach((c, i) => assert.ok(Math.abs(v[i] - c) <= 1e-15, `${v} is not [0, 0, 1]`));  // y -> z by x first
});

test('zero is not a rotation', () => {
  assert.throws(() => quaternion.normalize([0, 0, 0, 0]), RangeError);
});

test('rotorcert', (t) => certify(t, new Implementation({
  name: 'example_quaternion_js', version: quaternion.VERSION, scalar: 'double',
  description: 'conformance/packages/node/example: quaternion.js in JavaScript numbers',
  ops: {normalize: quaternion.normalize, compose: quaternion.compose, inverse: quaternion.inverse,
        apply_vector: quaternion.applyVector, slerp: quaternion.slerp},
  claimedClauses: ['QUAT-2', 'NORM-1', 'COMPOSE-1', 'INV-1', 'APPLY-1',
                   'SLERP-1', 'SLERP-2', 'SLERP-3', 'SLERP-4', 'SLERP-5', 'EDGE-6', 'EDGE-7'],
})));
