#!/usr/bin/env node
/* rotorcert vectors adapter for three.js (https://github.com/mrdoob/three.js), npm `three`, pinned 0.187.0.
 *
 *   node three_adapter.js --vectors DIR --out RESULTS.json     run every binary64 vector of the mapped ops
 *   node three_adapter.js --self-test                          check the package's hexfloat reader/printer
 *
 * three.js is loaded as its users load it: the ES module build (`import * as THREE from 'three'`,
 * build/three.module.js). Its CommonJS build (require('three'), build/three.cjs) is the same code
 * and prints a deprecation warning in r187; the module is located through require.resolve, so that
 * NODE_PATH (scripts/setup-adapters) finds it, and imported by URL. rotorcert-vectors is required.
 *
 * Numbers: three.js stores every component in a plain JavaScript number (binary64) and computes in
 * binary64, so the adapter is certified as `double` (binary64 vectors).
 *
 * Conventions: THREE.Quaternion(x, y, z, w) stores x, y, z, w, which is LAYOUT-1's order; its
 * product multiplyQuaternions(a, b) is the Hamilton product a b (x = ax bw + aw bx + ay bz - az by,
 * Quaternion.js:686), so compose(a, b) = a b with b applied first, no conversion. Vector3.applyQuaternion
 * is the active rotation v' = q v q* (t = 2 q x v; v + w t + q x t). Matrix4.elements is column-major
 * (Matrix4.js, class doc), as is Matrix3.fromArray (Matrix3.js:567 "The matrix elements in column-major
 * order"), the order of LAYOUT-1. Angles are radians.
 *
 * The ABI ops and the three.js calls they are (every other ABI op is declared unsupported):
 *   normalize        new Quaternion(x, y, z, w).normalize()
 *   compose          new Quaternion().multiplyQuaternions(a, b)
 *   inverse          q.invert()                       (three's invert is conjugate(): unit q assumed, documented)
 *   apply_vector     new Vector3(v).applyQuaternion(q)
 *   to_matrix        new Matrix4().makeRotationFromQuaternion(q).elements, upper 3x3 (columns 0..2, rows 0..2)
 *   from_matrix      new Quaternion().setFromRotationMatrix(new Matrix4().setFromMatrix3(new Matrix3().fromArray(m)))
 *   from_axis_angle  new Quaternion().setFromAxisAngle(new Vector3(axis), angle)
 *   slerp            new Quaternion().slerpQuaternions(a, b, t) (= a.clone().slerp(b, t), three's instance slerp)
 * Rule: each op is the library call on the input as given: no normalisation, no domain check, no
 * hemisphere flip of our own (three's slerp has its own flip). What three does with a non-unit,
 * zero or non-finite input is graded.
 *
 * Status (RESULT-2, the rule of the rotorcert-vectors package, conformance/packages/node/lib/outcome.js):
 * three has no status channel; an exception -> DOMAIN_ERROR with every output NaN; every output
 * component NaN -> DOMAIN_ERROR; anything else -> OK with the outputs as computed. A ReferenceError
 * or TypeError is a defect of this adapter and stops the run.
 */
'use strict';

const path = require('path');
const {pathToFileURL} = require('url');
const rcv = require('rotorcert-vectors');

/** three.js's ES module build, found where require() would find the package (NODE_PATH). */
async function loadThree() {
  const cjs = require.resolve('three');                       // .../three/build/three.cjs
  const THREE = await import(pathToFileURL(path.join(path.dirname(cjs), 'three.module.js')).href);
  const pkg = JSON.parse(require('fs').readFileSync(path.join(path.dirname(cjs), '..', 'package.json'), 'utf8'));
  return {THREE, version: pkg.version};
}

function makeOps(THREE) {
  const Q = (q) => new THREE.Quaternion(q[0], q[1], q[2], q[3]);
  const V = (v) => new THREE.Vector3(v[0], v[1], v[2]);
  const RT = (q, t) => new THREE.Matrix4().compose(V(t), Q(q), new THREE.Vector3(1, 1, 1));
  const split = (m) => {
    const p = new THREE.Vector3(), r = new THREE.Quaternion(), s = new THREE.Vector3();
    m.decompose(p, r, s);
    return [r.toArray(), p.toArray()];
  };
  return {
    normalize: (q) => Q(q).normalize().toArray(),
    compose: (a, b) => new THREE.Quaternion().multiplyQuaternions(Q(a), Q(b)).toArray(),
    inverse: (q) => Q(q).invert().toArray(),
    apply_vector: (q, v) => V(v).applyQuaternion(Q(q)).toArray(),
    to_matrix: (q) => {
      const e = new THREE.Matrix4().makeRotationFromQuaternion(Q(q)).elements;   // column-major 4x4
      return [e[0], e[1], e[2], e[4], e[5], e[6], e[8], e[9], e[10]];
    },
    from_matrix: (m) => new THREE.Quaternion()
      .setFromRotationMatrix(new THREE.Matrix4().setFromMatrix3(new THREE.Matrix3().fromArray(m))).toArray(),
    from_axis_angle: (angle, axis) => new THREE.Quaternion().setFromAxisAngle(V(axis), angle).toArray(),
    slerp: (a, b, t) => new THREE.Quaternion().slerpQuaternions(Q(a), Q(b), t).toArray(),
    // ABI version 4: rigid transforms as a three.js user holds them (an Object3D's matrix):
    // Matrix4.compose(position, quaternion, scale 1) (x -> R x + t), multiplyMatrices(a, b) (a b: b
    // applied first), Vector3.applyMatrix4, Matrix4.invert, read back with decompose.
    rigid_compose: (qa, ta, qb, tb) => split(new THREE.Matrix4().multiplyMatrices(RT(qa, ta), RT(qb, tb))),
    rigid_apply: (q, t, p) => V(p).applyMatrix4(RT(q, t)).toArray(),
    rigid_inverse: (q, t) => split(RT(q, t).invert()),
  };
}

function implementation(version) {
  return {
    name: 'three',
    version,
    scalar: 'double',
    description:
      'three.js ' + version + ' (npm three, ES module build) THREE.Quaternion, Vector3.applyQuaternion, ' +
      'Matrix4.makeRotationFromQuaternion and Quaternion.setFromRotationMatrix, Matrix4.compose / multiplyMatrices / ' +
      'invert / decompose and Vector3.applyMatrix4 for rigid transforms, in JavaScript numbers (binary64), ' +
      'through the JSON-vectors adapter conformance/adapters/three; status rule: an exception -> DOMAIN_ERROR, ' +
      'every output NaN -> DOMAIN_ERROR (RESULT-2, three has no status channel), otherwise OK',
  };
}

function selfTest() {
  const report = rcv.checkHexfloat();
  for (const f of report.failures.slice(0, 20)) console.log('FAIL ' + f);
  console.log(`self-test: ${report.parseCases} parse cases, ${report.roundTrips} round trips, ${report.failures.length} failures`);
  return report.failures.length ? 1 : 0;
}

async function main(argv) {
  if (argv.length === 1 && argv[0] === '--self-test') return selfTest();
  const {THREE, version} = await loadThree();
  return rcv.runAdapter(argv, 'rotorcert adapter for three.js ' + version +
                        ' (node three_adapter.js --vectors DIR --out RESULTS.json | --self-test)',
                        implementation(version), makeOps(THREE));
}

if (require.main === module) {
  main(process.argv.slice(2)).then((rc) => { process.exitCode = rc; }, (e) => {
    console.error(e && e.stack ? e.stack : String(e));
    process.exitCode = 1;
  });
}

module.exports = {loadThree, makeOps};
